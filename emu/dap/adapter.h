// The Debug Adapter Protocol over the debugging API: requests (JSON) in, responses and events
// out through a sink. It owns one DebugShell (a script Session - its Machine and Debugger - and
// the debugger's console), so the debug console runs `alp85 debug`'s commands and the command
// language on the very machine the editor shows.
//
// Single-threaded: a run is cut into slices of simulated time (`advance`), and the server reads
// messages between slices, so `pause` is answered within a slice. Nothing a client sends can
// end the session: malformed JSON, unknown commands, wrong argument types and requests out of
// order all get an error response.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "emu/dap/breakpoints.h"
#include "emu/dap/launch.h"
#include "emu/dap/machine_view.h"
#include "emu/debug/debugger.h"
#include "emu/front/pacer.h"
#include "emu/script/debug_shell.h"
#include "emu/script/session.h"

namespace alp85::dap {

using Json = nlohmann::json;

class Adapter {
public:
    using Sink = std::function<void(const Json&)>;

    explicit Adapter(Sink sink);
    ~Adapter();
    Adapter(const Adapter&) = delete;
    Adapter& operator=(const Adapter&) = delete;

    // The requests it answers ("initialize", "launch", ...), for clients that test it.
    static std::vector<std::string_view> commands();
    // One message body from the client, answered whatever it holds.
    void receive(std::string_view body);
    // A frame whose header could not be read: an error response (request_seq 0).
    void refuse_frame(const std::string& why);
    // While a run is in progress: runs one slice. Returns how long (ms) the caller may wait for
    // messages before the next slice: 0 to go on at once, more when pacing to real time.
    int advance();
    bool running() const { return session_ && (session_->debugger().running() || run_.steps_left > 0); }
    // Called between slices of a long reverse run (Debugger::set_poll): the server reads the
    // messages that came meanwhile there, keeps them for after the run, and on a `pause`
    // calls interrupt(), which ends the run.
    void set_poll(std::function<void()> poll) {
        poll_ = std::move(poll);
        if (session_) session_->debugger().set_poll(poll_);
    }
    void interrupt() {
        if (session_) session_->debugger().interrupt();
    }
    // The client said disconnect (answered): the server may close.
    bool finished() const { return finished_; }

private:
    using Handler = void (Adapter::*)(const Json& args, Json& body);
    static const std::map<std::string, Handler, std::less<>>& handlers();

    // ---- messages (adapter.cpp) --------------------------------------------------------------
    void dispatch(const Json& request);
    void respond(std::int64_t request_seq, std::string_view command, Json body);
    void error_response(std::int64_t request_seq, std::string_view command, const std::string& message);
    void event(std::string_view name, Json body = Json::object());
    void output(std::string_view category, const std::string& text);
    void on_debug_event(const debug::Event& e);

    // ---- session (session.cpp) ---------------------------------------------------------------
    void initialize(const Json& args, Json& body);
    void launch(const Json& args, Json& body);
    void configuration_done(const Json& args, Json& body);
    void restart(const Json& args, Json& body);
    void disconnect(const Json& args, Json& body);
    void terminate(const Json& args, Json& body);
    void start_session();  // builds the machine from config_ (launch and restart)
    void begin();          // after configurationDone: stop on entry or run
    script::Session& session();  // throws RequestError before launch

    // ---- breakpoints (breakpoint_requests.cpp) -----------------------------------------------------
    void set_breakpoints(const Json& args, Json& body);
    void set_function_breakpoints(const Json& args, Json& body);
    void set_instruction_breakpoints(const Json& args, Json& body);
    void set_exception_breakpoints(const Json& args, Json& body);
    void data_breakpoint_info(const Json& args, Json& body);
    void set_data_breakpoints(const Json& args, Json& body);
    void breakpoint_locations(const Json& args, Json& body);
    void arm();  // the machine's breakpoints and watchpoints from the tables below
    void resolve_breakpoints();  // binds every breakpoint to the program now loaded
    void resolve(Breakpoint& b, const std::string& path);
    bool check_options(Breakpoint& b);  // condition and hit condition; false: unverified, says why
    Json breakpoint_json(const Breakpoint& b, const std::string& path) const;
    // A finished step or reverse run as a stopped event; `tell`: with the output that says why
    // (a halt, a runaway), which the console's own report of a stop already holds.
    void report(const debug::Stop& s, std::string_view step_reason, bool tell = true);

    // ---- running (run.cpp) ---------------------------------------------------------------------
    void continue_(const Json& args, Json& body);
    void next(const Json& args, Json& body);
    void step_in(const Json& args, Json& body);
    void step_out(const Json& args, Json& body);
    void pause(const Json& args, Json& body);
    void step_back(const Json& args, Json& body);
    void reverse_continue(const Json& args, Json& body);
    void goto_targets(const Json& args, Json& body);
    void goto_(const Json& args, Json& body);
    void require_stopped();
    void stopped(std::string_view reason, const std::string& description = {}, std::vector<int> hit_ids = {},
                 const std::string& text = {});
    void started(std::optional<debug::Stop> s, std::string_view step_reason);
    // A run (or one step of a console's `step N`) stopped at `s`: the run's end, reported (the
    // text the console shows for it, for a run begun in the console), or nullopt when `step N`
    // goes on with its next step.
    std::optional<std::string> ended(const debug::Stop& s);
    // A debug console line that runs the machine forward (continue, step, next, stepi, nexti,
    // finish, until, advance, jump, run TIME) begun as a resumable run, as the continue request's
    // are: the text to answer with; nullopt when the line is none of these (or one the console
    // refuses, which it says why at once).
    std::optional<std::string> begin_console_run(std::string_view line);
    std::optional<debug::Stop> begin_console_step();  // the next step of `step N`, `next N`, `stepi N`

    // ---- state (state.cpp) ---------------------------------------------------------------------
    void threads(const Json& args, Json& body);
    void stack_trace(const Json& args, Json& body);
    void scopes(const Json& args, Json& body);
    void variables(const Json& args, Json& body);
    void set_variable(const Json& args, Json& body);
    void evaluate(const Json& args, Json& body);
    void source(const Json& args, Json& body);
    Json source_of(const std::string& file) const;  // a DAP Source for a file of the map
    // A name the client may watch (a firmware variable, a symbol, an address): address and size.
    std::optional<std::pair<std::uint16_t, std::uint16_t>> data_target(const std::string& name, std::int64_t ref);

    // ---- memory (memory.cpp) -------------------------------------------------------------------
    void read_memory(const Json& args, Json& body);
    void write_memory(const Json& args, Json& body);
    void disassemble(const Json& args, Json& body);
    std::uint16_t address_of(const std::string& reference) const;  // "0x1B32", "1B32H", a symbol

    Sink sink_;
    std::int64_t seq_ = 1;
    bool initialized_ = false;
    bool finished_ = false;
    bool configured_ = false;
    bool lines_start_at_1_ = true;
    LaunchConfig config_;
    std::unique_ptr<script::DebugShell> shell_;
    script::Session* session_ = nullptr;  // shell_'s
    std::function<void()> poll_;
    ProgramMap map_;           // what is loaded where, for runaways and sources
    BreakpointTable bps_;      // every kind the client set
    std::vector<int> engine_points_;    // the Debugger's breakpoints and watchpoints made for bps_
    std::map<int, int> engine_to_dap_;  // their numbers -> DAP breakpoint ids
    std::string captured_;     // the debugger's output while a console command runs
    bool capturing_ = false;   // evaluate: the debugger's output goes to captured_
    bool in_request_ = false;  // events wait in deferred_ until the response is sent
    std::vector<Json> deferred_;

    // The run in progress (the Debugger's): how its end is reported, and real-time pacing.
    struct Run {
        std::string step_reason = "step";
        front::Pacer pacer;            // real time from the run's start (the window's pacer)
        // Begun in the debug console: as fast as the host can (as `alp85 debug` runs it), its end
        // told as the console tells it, and the stop's console commands run.
        bool console = false;
        bool timed = false;            // run TIME: reaching the time is its end, not a pause
        enum class Step : std::uint8_t { Line, Over, Instruction } step = Step::Line;
        int steps_left = 0;            // step N: steps still to begin after the one under way
    } run_;
    // Stops' console commands that run the machine again, nested (ended -> begin_console_run).
    static constexpr int kMaxCommandsDepth = 16;
    int commands_depth_ = 0;
};

}  // namespace alp85::dap
