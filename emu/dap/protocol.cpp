#include "emu/dap/protocol.h"

#include <cstdlib>

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
    // JSON's safe integers: sums of two arguments cannot overflow.
    constexpr std::int64_t kSafe = (std::int64_t{1} << 53) - 1;
    if (v->is_number_unsigned() ? v->get<std::uint64_t>() > static_cast<std::uint64_t>(kSafe)
                                : std::abs(v->get<std::int64_t>()) > kSafe)
        wrong(key, "an integer within +-(2^53 - 1)");
    return v->get<std::int64_t>();
}

int need_line(const Json& args, std::string_view key, bool from_1) {
    const std::int64_t v = need_int(args, key) + (from_1 ? 0 : 1);
    if (v < 1 || v > 10'000'000) throw RequestError(fmt::format("argument '{}': no line {}", key, v));
    return static_cast<int>(v);
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
