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

// The argument `key`: null when absent; an error saying it must be `type` when `is` says it is not.
const Json* typed(const Json& args, std::string_view key, bool (Json::*is)() const noexcept, std::string_view type) {
    const Json* v = find(args, key);
    if (v && !(v->*is)()) wrong(key, type);
    return v;
}

template <class T>
T needed(std::optional<T> v, std::string_view key) {
    if (!v) throw RequestError(fmt::format("argument '{}' is missing", key));
    return *std::move(v);
}

}  // namespace

std::optional<std::string> opt_string(const Json& args, std::string_view key) {
    const Json* v = typed(args, key, &Json::is_string, "a string");
    if (!v) return std::nullopt;
    return v->get<std::string>();
}

std::optional<std::int64_t> opt_int(const Json& args, std::string_view key) {
    const Json* v = typed(args, key, &Json::is_number_integer, "an integer");
    if (!v) return std::nullopt;
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
    const Json* v = typed(args, key, &Json::is_boolean, "true or false");
    if (!v) return std::nullopt;
    return v->get<bool>();
}

std::string need_string(const Json& args, std::string_view key) {
    return needed(opt_string(args, key), key);
}

std::int64_t need_int(const Json& args, std::string_view key) {
    return needed(opt_int(args, key), key);
}

const Json& opt_array(const Json& args, std::string_view key) {
    static const Json empty = Json::array();
    const Json* v = typed(args, key, &Json::is_array, "an array");
    return v ? *v : empty;
}

const Json& opt_object(const Json& args, std::string_view key) {
    static const Json empty = Json::object();
    const Json* v = typed(args, key, &Json::is_object, "an object");
    return v ? *v : empty;
}

void check_common(const Json& args) {
    if (!args.is_object()) return;
    enum class Type { Integer, Boolean, String, Object, Array };
    static const std::pair<std::string_view, Type> kTypes[] = {
        {"threadId", Type::Integer}, {"frameId", Type::Integer}, {"line", Type::Integer}, {"column", Type::Integer},
        {"endLine", Type::Integer}, {"endColumn", Type::Integer}, {"startFrame", Type::Integer},
        {"levels", Type::Integer}, {"variablesReference", Type::Integer}, {"targetId", Type::Integer},
        {"sourceReference", Type::Integer}, {"offset", Type::Integer}, {"count", Type::Integer},
        {"instructionOffset", Type::Integer}, {"instructionCount", Type::Integer}, {"start", Type::Integer},
        {"singleThread", Type::Boolean}, {"restart", Type::Boolean}, {"terminateDebuggee", Type::Boolean},
        {"suspendDebuggee", Type::Boolean}, {"sourceModified", Type::Boolean}, {"resolveSymbols", Type::Boolean},
        {"allowPartial", Type::Boolean}, {"linesStartAt1", Type::Boolean}, {"columnsStartAt1", Type::Boolean},
        {"noDebug", Type::Boolean}, {"adapterID", Type::String}, {"clientID", Type::String},
        {"clientName", Type::String}, {"locale", Type::String}, {"pathFormat", Type::String},
        {"granularity", Type::String}, {"context", Type::String}, {"expression", Type::String},
        {"name", Type::String}, {"value", Type::String}, {"path", Type::String}, {"memoryReference", Type::String},
        {"data", Type::String}, {"condition", Type::String}, {"hitCondition", Type::String},
        {"logMessage", Type::String}, {"instructionReference", Type::String}, {"dataId", Type::String},
        {"accessType", Type::String}, {"source", Type::Object}, {"format", Type::Object},
        {"breakpoints", Type::Array}, {"lines", Type::Array}, {"filters", Type::Array},
        {"filterOptions", Type::Array}, {"exceptionOptions", Type::Array},
    };
    for (const auto& [key, type] : kTypes) {
        switch (type) {
            case Type::Integer: opt_int(args, key); break;
            case Type::Boolean: opt_bool(args, key); break;
            case Type::String: opt_string(args, key); break;
            case Type::Object: opt_object(args, key); break;
            case Type::Array: opt_array(args, key); break;
        }
    }
    // initialize's capabilities of the client: supportsVariableType, supportsMemoryReferences, ...
    for (const auto& [key, value] : args.items())
        if (key.starts_with("supports") && !value.is_null() && !value.is_boolean()) wrong(key, "true or false");
}

const Json& opt_objects(const Json& args, std::string_view key) {
    const Json& list = opt_array(args, key);
    for (const Json& item : list) {
        if (!item.is_object()) throw RequestError(fmt::format("argument '{}' must hold objects", key));
        check_common(item);
    }
    return list;
}

std::string hex4(std::uint16_t v) { return fmt::format("0x{:04X}", v); }

}  // namespace alp85::dap
