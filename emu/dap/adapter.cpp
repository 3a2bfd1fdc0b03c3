#include "emu/dap/adapter.h"

#include <fmt/format.h>

namespace alp85::dap {

Adapter::Adapter(Sink sink) : sink_(std::move(sink)) {}
Adapter::~Adapter() = default;

const std::map<std::string, Adapter::Handler, std::less<>>& Adapter::handlers() {
    static const std::map<std::string, Handler, std::less<>> table = {
        {"initialize", &Adapter::initialize},
        {"launch", &Adapter::launch},
        {"configurationDone", &Adapter::configuration_done},
        {"restart", &Adapter::restart},
        {"disconnect", &Adapter::disconnect},
        {"terminate", &Adapter::terminate},
        {"setBreakpoints", &Adapter::set_breakpoints},
        {"setFunctionBreakpoints", &Adapter::set_function_breakpoints},
        {"setInstructionBreakpoints", &Adapter::set_instruction_breakpoints},
        {"setExceptionBreakpoints", &Adapter::set_exception_breakpoints},
        {"dataBreakpointInfo", &Adapter::data_breakpoint_info},
        {"setDataBreakpoints", &Adapter::set_data_breakpoints},
        {"breakpointLocations", &Adapter::breakpoint_locations},
        {"continue", &Adapter::continue_},
        {"next", &Adapter::next},
        {"stepIn", &Adapter::step_in},
        {"stepOut", &Adapter::step_out},
        {"pause", &Adapter::pause},
        {"stepBack", &Adapter::step_back},
        {"reverseContinue", &Adapter::reverse_continue},
        {"gotoTargets", &Adapter::goto_targets},
        {"goto", &Adapter::goto_},
        {"threads", &Adapter::threads},
        {"stackTrace", &Adapter::stack_trace},
        {"scopes", &Adapter::scopes},
        {"variables", &Adapter::variables},
        {"setVariable", &Adapter::set_variable},
        {"evaluate", &Adapter::evaluate},
        {"source", &Adapter::source},
        {"readMemory", &Adapter::read_memory},
        {"writeMemory", &Adapter::write_memory},
        {"disassemble", &Adapter::disassemble},
    };
    return table;
}

std::vector<std::string_view> Adapter::commands() {
    std::vector<std::string_view> out;
    for (const auto& [name, handler] : handlers()) out.push_back(name);
    return out;
}

void Adapter::receive(std::string_view body) {
    const Json msg = Json::parse(body, nullptr, /*allow_exceptions=*/false);
    if (msg.is_discarded()) {
        error_response(0, "", "the message is not JSON");
        return;
    }
    if (!msg.is_object() || !msg.contains("type") || msg["type"] != "request") {
        // Responses to reverse requests and stray events carry nothing to act on; anything else
        // is answered so that the client sees its mistake.
        if (msg.is_object() && msg.contains("type") && (msg["type"] == "response" || msg["type"] == "event")) return;
        error_response(msg.is_object() && msg.contains("seq") && msg["seq"].is_number_integer() ? msg["seq"].get<std::int64_t>() : 0,
                       "", "the message is not a request (\"type\": \"request\")");
        return;
    }
    dispatch(msg);
}

void Adapter::refuse_frame(const std::string& why) { error_response(0, "", "unreadable message: " + why); }

void Adapter::dispatch(const Json& request) {
    // The fields every request has, checked before anything reads them: a wrong type is this
    // request's error response, never an exception out of the adapter.
    const bool seq_ok = request.contains("seq") && request["seq"].is_number_integer() &&
                        (!request["seq"].is_number_unsigned() || request["seq"].get<std::uint64_t>() <= INT64_MAX);
    const std::int64_t seq = seq_ok ? request["seq"].get<std::int64_t>() : 0;
    if (!request.contains("command") || !request["command"].is_string()) {
        error_response(seq, "", request.contains("command") ? "\"command\" must be a string" : "a request without \"command\"");
        return;
    }
    const std::string command = request["command"].get<std::string>();
    if (!seq_ok) {  // its response could not name the request it answers
        error_response(0, command, "\"seq\" must be an integer (the request's number)");
        return;
    }
    if (request.contains("arguments") && !request["arguments"].is_object() && !request["arguments"].is_null()) {
        error_response(seq, command, "\"arguments\" must be an object");
        return;
    }
    const auto it = handlers().find(command);
    if (it == handlers().end()) {
        error_response(seq, command, fmt::format("unknown request '{}'", command));
        return;
    }
    if (!initialized_ && command != "initialize" && command != "disconnect") {
        error_response(seq, command, fmt::format("'{}' before 'initialize'", command));
        return;
    }
    static const Json kNoArgs = Json::object();
    const Json& args = request.contains("arguments") && request["arguments"].is_object() ? request["arguments"] : kNoArgs;
    Json body = Json::object();
    in_request_ = true;
    struct Flush {  // events raised while handling go out after the response
        Adapter& a;
        ~Flush() {
            a.in_request_ = false;
            std::vector<Json> events;
            events.swap(a.deferred_);
            for (Json& e : events) {
                e["seq"] = a.seq_++;
                a.sink_(e);
            }
        }
    } flush{*this};
    try {
        check_common(args);
        if (const auto src = args.find("source"); src != args.end() && src->is_object()) check_common(*src);
        (this->*(it->second))(args, body);
    } catch (const RequestError& e) {
        error_response(seq, command, e.what());
        return;
    } catch (const Json::exception& e) {
        error_response(seq, command, fmt::format("bad arguments: {}", e.what()));
        return;
    } catch (const std::exception& e) {
        error_response(seq, command, e.what());
        return;
    }
    respond(seq, command, std::move(body));
}

void Adapter::respond(std::int64_t request_seq, std::string_view command, Json body) {
    Json r = {{"seq", seq_++},
              {"type", "response"},
              {"request_seq", request_seq},
              {"success", true},
              {"command", command}};
    if (!body.empty()) r["body"] = std::move(body);
    sink_(r);
}

void Adapter::error_response(std::int64_t request_seq, std::string_view command, const std::string& message) {
    sink_({{"seq", seq_++},
           {"type", "response"},
           {"request_seq", request_seq},
           {"success", false},
           {"command", command},
           {"message", message},
           {"body", {{"error", {{"id", 1}, {"format", message}, {"showUser", false}}}}}});
}

void Adapter::event(std::string_view name, Json body) {
    Json e = {{"seq", 0}, {"type", "event"}, {"event", name}};
    if (!body.empty()) e["body"] = std::move(body);
    if (in_request_) {
        deferred_.push_back(std::move(e));
    } else {
        e["seq"] = seq_++;
        sink_(e);
    }
}

void Adapter::output(std::string_view category, const std::string& text) {
    event("output", {{"category", category}, {"output", text.ends_with('\n') ? text : text + "\n"}});
}

void Adapter::on_debug_event(const debug::Event& e) {
    switch (e.kind) {
        case debug::Event::Kind::Stopped: return;  // the adapter reports stops from the Stop values
        case debug::Event::Kind::ExpectFailed:
        case debug::Event::Kind::Output:
            if (capturing_) {
                captured_ += e.text;
                captured_ += '\n';
            } else {
                output(e.kind == debug::Event::Kind::ExpectFailed ? "stderr" : "console", e.text);
            }
            return;
    }
}

}  // namespace alp85::dap
