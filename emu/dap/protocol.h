// Pieces every request handler uses: the JSON type, the error a handler throws to answer with
// an error response, and typed access to arguments that names what is wrong.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace alp85::dap {

using Json = nlohmann::json;

// Thrown by a handler: the request is answered success=false with this message.
class RequestError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// args[key] if present and of the right type; absent: nullopt; present with another type: a
// RequestError naming the argument.
std::optional<std::string> opt_string(const Json& args, std::string_view key);
std::optional<std::int64_t> opt_int(const Json& args, std::string_view key);
std::optional<bool> opt_bool(const Json& args, std::string_view key);
std::string need_string(const Json& args, std::string_view key);
std::int64_t need_int(const Json& args, std::string_view key);
// A line number, 1-based inside (the client's counts from 1 when `from_1`).
int need_line(const Json& args, std::string_view key, bool from_1);
// args[key] as an array or object (empty when absent); another type is a RequestError.
const Json& opt_array(const Json& args, std::string_view key);
const Json& opt_object(const Json& args, std::string_view key);

// The arguments DAP gives one type in every request and object that has them (threadId, frameId,
// source, breakpoints, granularity, singleThread, supports..., ...): one of another type is a
// RequestError naming it, also where the adapter has no use for it (threadId: there is one thread).
// For `args` and the objects inside it the handlers read (a source, each breakpoint).
void check_common(const Json& args);
// args[key] as an array of objects, each checked as above (empty when absent).
const Json& opt_objects(const Json& args, std::string_view key);

std::string hex4(std::uint16_t v);  // "0x1B32": DAP's addresses and memory references

}  // namespace alp85::dap
