#include "emu/dap/protocol.h"

#include <fmt/format.h>

namespace alp85::dap {
namespace {

const Json* find(const Json& args, std::string_view key) {
    if (!args.is_object()) return nullptr;
    const auto it = args.find(key);
    return it == args.end() || it->is_null() ? nullptr : &*it;
}

[[noreturn]] void wrong(std::string_view key, std::string_view type) {
    throw RequestError(fmt::format("argument '{}' must be {}", key, type));
}

}  // namespace

std::optional<std::string> opt_string(const Json& args, std::string_view key) {
    const Json* v = find(args, key);
    if (!v) return std::nullopt;
    if (!v->is_string()) wrong(key, "a string");
    return v->get<std::string>();
}

std::optional<std::int64_t> opt_int(const Json& args, std::string_view key) {
    const Json* v = find(args, key);
    if (!v) return std::nullopt;
    if (!v->is_number_integer()) wrong(key, "an integer");
    return v->get<std::int64_t>();
}

std::optional<bool> opt_bool(const Json& args, std::string_view key) {
    const Json* v = find(args, key);
    if (!v) return std::nullopt;
    if (!v->is_boolean()) wrong(key, "true or false");
    return v->get<bool>();
}

std::string need_string(const Json& args, std::string_view key) {
    auto v = opt_string(args, key);
    if (!v) throw RequestError(fmt::format("argument '{}' is missing", key));
    return *v;
}

std::int64_t need_int(const Json& args, std::string_view key) {
    auto v = opt_int(args, key);
    if (!v) throw RequestError(fmt::format("argument '{}' is missing", key));
    return *v;
}

const Json& opt_array(const Json& args, std::string_view key) {
    static const Json empty = Json::array();
    const Json* v = find(args, key);
    if (!v) return empty;
    if (!v->is_array()) wrong(key, "an array");
    return *v;
}

const Json& opt_object(const Json& args, std::string_view key) {
    static const Json empty = Json::object();
    const Json* v = find(args, key);
    if (!v) return empty;
    if (!v->is_object()) wrong(key, "an object");
    return *v;
}

std::string hex4(std::uint16_t v) { return fmt::format("0x{:04X}", v); }

}  // namespace alp85::dap
