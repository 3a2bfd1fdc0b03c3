// The debugging API every front end uses (the script session, `alp85 debug`'s prompt, the GUI,
// DAP): runs that end in a Stop value, events to listeners instead of text, the program's symbols
// and source lines in one table, and the machine's input log for exact replay. On top of that the
// source-level debugger: numbered breakpoints (address, symbol, FILE:LINE; conditions, ignore
// counts, temporary) and watchpoints (memory, I/O ports, the machine tool, chip registers),
// stepping with CALL/RET tracking (step, next, finish, until, advance), and reverse execution
// (reverse step, next, finish, continue) by periodic snapshots and deterministic re-execution.
//
// It wraps one Machine and adds no cost to a plain run: while no breakpoint or watchpoint is armed
// and no step is under way, the CPU runs its plain path (the debugger's RunObserver is installed only
// while needed). Reading anything through the debugger never changes a device.
//
//   Machine m;  debug::Debugger d(m);
//   d.program().add_table(fw.symbols);
//   d.set_history(true);                          // snapshots for reverse execution
//   int n = d.add_breakpoint("OUT").number;       // or "thesis.asm:629", "0B2CH"
//   debug::Stop s = d.cont();                     // StopReason::Breakpoint, s.number == n
//   s = d.step();  s = d.finish();  s = d.reverse_step();
//   auto v = d.evaluate("word[YAC] + 1");         // value or error with its column
#pragma once

#include <atomic>
#include <bitset>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "emu/board/machine.h"
#include "emu/core/cpu_registers.h"
#include "emu/debug/expr.h"
#include "emu/program/symbols.h"

namespace alp85::debug {

enum class StopReason : std::uint8_t {
    Deadline,     // the requested time was reached
    Condition,    // the caller's condition became true
    Breakpoint,   // the PC reached a breakpoint (the instruction there has not run)
    Watchpoint,   // a watched thing changed or was accessed (after the instruction)
    Target,       // run_to / advance / until reached its address
    Step,         // a step ended (step, stepi, next, reverse-step, ...)
    Finished,     // finish / reverse-finish: the routine returned (or was entered)
    Interrupted,  // interrupt() (Ctrl-C) ended the run
    HistoryStart, // a reverse run reached the oldest snapshot: no more history
    Error,        // a breakpoint's condition could not be evaluated, or a command could not run
    Halted,       // the CPU executed HLT (or is halted with nothing to wake it): like an exited program
    Runaway,      // the CPU fetched an instruction where no program is (set_runaway_guard)
    Paused,       // pause() ended a resumable run between its slices
};
std::string_view name(StopReason reason);  // "deadline", "breakpoint", ...

// A watched value that changed: old and new.
struct Change {
    int number = 0;       // the watchpoint
    std::string what;     // "word YAC (1B32H)", "port F9H out", "axis Y count"
    std::int64_t old_value = 0, new_value = 0;
    int digits = 2;       // hex digits for memory and ports; 0: a signed decimal quantity
    bool value_only = false;  // an access (read/port) without old/new: new_value is the value
};

struct Stop {
    StopReason reason = StopReason::Deadline;
    std::uint64_t at = 0;                // T-state
    std::uint16_t pc = 0;                // the next instruction
    std::optional<std::uint16_t> data;   // Watchpoint: the address or port accessed
    std::optional<SourceLine> line;      // the source line of pc, when a loaded program has one
    int number = 0;                      // the breakpoint or watchpoint that stopped it
    std::vector<int> numbers;            // Breakpoint: every breakpoint that stopped it (number first)
    std::vector<Change> changes;         // watchpoints: what changed
    std::optional<std::uint16_t> after;  // watchpoints, runaway: the instruction that made the change
    std::string message;                 // Error, HistoryStart, Halted, Runaway: what happened
};

// A hit condition (DAP's hitCondition): "N" or "==N" (the Nth hit), ">=N", ">N", "<N", "<=N", "%N"
// (every Nth). Hits are counted after the condition holds and the ignore count has passed.
struct HitCondition {
    enum class Op : std::uint8_t { Eq, Ge, Gt, Lt, Le, Every };
    Op op = Op::Eq;
    std::uint64_t n = 0;
    std::string text;
    bool met(std::uint64_t hits) const;
    static std::optional<HitCondition> parse(std::string_view text);  // nullopt: not one of the forms
};

// Where a command came from (a script's file and line), for front ends that print it.
struct Origin {
    std::string file;
    int line = 0;
};

struct Event {
    enum class Kind : std::uint8_t {
        Stopped,       // a run ended at a breakpoint or watchpoint (stop)
        ExpectFailed,  // an expectation did not hold (text: what was expected and found)
        Output,        // text for the user (print, a display dump)
    };
    Kind kind = Kind::Output;
    Stop stop;
    std::string text;
    Origin origin;
};

struct Breakpoint {
    int number = 0;
    std::uint16_t address = 0;
    std::string location;                // as given: "OUT", "thesis.asm:629", "0B2CH"
    std::optional<SourceLine> line;      // the source line it is on
    bool temporary = false;              // tbreak: deleted at its first stop
    bool enabled = true;
    std::optional<Expr> condition;
    unsigned ignore = 0;                 // hits still to pass
    unsigned hits = 0;                   // stops (and ignored passes) so far
    std::optional<HitCondition> hit_condition;  // stops only on the hits it allows
    std::string log_message;             // a log point: prints this ({expr} replaced) and goes on
    std::vector<std::string> commands;   // run by the front end at a stop (commands ... end)
};

enum class WatchKind : std::uint8_t {
    Write,   // memory written with a new value (gdb's watch)
    Read,    // memory read (rwatch)
    Access,  // memory read or written (awatch)
    Port,    // an I/O port: IN, OUT or either, with an optional value
    Tool,    // a machine-tool quantity changes
    Part,    // a value a part describes changes (watch 8155 porta, watch 8279 fifo)
};
enum class PortDir : std::uint8_t { In, Out, Any };
enum class ToolQuantity : std::uint8_t { Steps, Count, Lost, EndStop };

struct Watchpoint {
    int number = 0;
    WatchKind kind = WatchKind::Write;
    std::string what;                    // for messages: "word YAC (1B32H)", "port F9H out"
    std::uint16_t first = 0, last = 0;   // memory range (inclusive), or the port in `first`
    PortDir dir = PortDir::Any;
    std::optional<std::uint8_t> value;   // Port: only this value
    ToolQuantity quantity = ToolQuantity::Steps;
    periph::MachineTool::Axis axis = periph::MachineTool::Axis::X;
    std::string part, field;             // Part: the part's name and the field's watch name
    bool enabled = true;
    std::optional<Expr> condition;
    unsigned ignore = 0;
    unsigned hits = 0;
    std::optional<HitCondition> hit_condition;
    std::vector<std::string> commands;
    std::int64_t last_value = 0;          // Write, Tool, Part: the value at the last check
    int digits = 2;                       // Part: hex digits of its messages (0: signed decimal)
    std::uint64_t part_now = 0;           // Part: the part's time and the inputs applied at the last check
    std::size_t part_inputs = 0;
    std::vector<std::uint8_t> shadow;     // Write over more than a word: the bytes at the last check;
                                          // Part: the part's state at the last check
};

// A parsed watchpoint request, for add_watchpoint (the console parses text into one).
struct WatchSpec {
    WatchKind kind = WatchKind::Write;
    std::string what;
    std::uint16_t first = 0, last = 0;
    PortDir dir = PortDir::Any;
    std::optional<std::uint8_t> value;
    ToolQuantity quantity = ToolQuantity::Steps;
    periph::MachineTool::Axis axis = periph::MachineTool::Axis::X;
    std::string part, field;  // Part: the part's name and the field's watch name (Description::find_watch)
};

// A frame of the call stack (bt): found by reading the stack for return addresses.
struct Frame {
    std::uint16_t pc = 0;                // where this frame is (frame 0: the PC)
    std::uint16_t slot = 0;              // the stack address of its return address (frames > 0)
    std::optional<std::string> routine;  // SymbolTable::routine_at(pc): "OUT", "O42+12", or none
    std::optional<SourceLine> line;
};

// One executed instruction of `history`: where, and the registers it changed.
struct Executed {
    std::uint64_t at = 0;
    std::uint16_t pc = 0;
    Registers before, after;
};

// The CPU's state beside its registers, as a debugger shows it.
struct CpuStatus {
    bool halted = false;              // waiting after a HLT
    bool interrupts_enabled = false;  // IE
    std::uint8_t masks = 0;           // bit 2 M7.5, bit 1 M6.5, bit 0 M5.5 (SIM's)
    bool rst75_latched = false, trap_latched = false;
    bool sod = false;                 // the serial output line
    std::uint8_t rim = 0;             // what RIM would read now
    Variant variant = Variant::I8085;
};

// How long one slice of a resumable run may go on (Debugger::resume).
struct Budget {
    std::uint64_t tstates = ~std::uint64_t{0};  // machine time in this slice, at most
    double seconds = 0;                         // host time in this slice, at most (0: no limit)
};

struct Boundary;    // emu/debug/observer.h, the debugger's inside
struct Hit;
struct Checkpoint;

class Debugger {
public:
    using Listener = std::function<void(const Event&)>;

    explicit Debugger(Machine& machine);
    ~Debugger();
    Debugger(const Debugger&) = delete;
    Debugger& operator=(const Debugger&) = delete;

    Machine& machine() { return m_; }
    const Machine& machine() const { return m_; }
    // The symbols and source lines of everything loaded.
    SymbolTable& program() { return program_; }
    const SymbolTable& program() const { return program_; }

    // Listeners receive every event in order; front ends format them.
    void listen(Listener listener) { listeners_.push_back(std::move(listener)); }
    void emit(const Event& e) const {
        for (const Listener& l : listeners_) l(e);
    }

    // ---- running ---------------------------------------------------------------------------------
    // Runs as Machine does, with the breakpoints and watchpoints armed; a stop at one is also sent
    // as a Stopped event (with `origin`, the command that ran).
    Stop run_until(std::uint64_t until, const std::function<bool()>& condition = {}, const Origin& origin = {});
    Stop run_for(std::uint64_t tstates, const std::function<bool()>& condition = {}, const Origin& origin = {}) {
        return run_until(m_.now() + tstates, condition, origin);
    }
    // Runs until the PC reaches `pc` (Target) or `until` (Deadline); breakpoints do not stop it.
    Stop run_to(std::uint16_t pc, std::uint64_t until);
    // Until a breakpoint, a watchpoint, interrupt(), or `limit` T-states (Deadline).
    Stop cont() { return cont(continue_limit_); }
    Stop cont(std::uint64_t limit) { return complete(begin_continue(limit)); }
    Stop stepi();    // one instruction (into CALL and RST)
    Stop step() { return complete(begin_step()); }      // one source line: into a CALL or RST, over routines without lines
    Stop next() { return complete(begin_next()); }      // one instruction, a CALL, RST or RSTV run whole
    Stop finish() { return complete(begin_finish()); }  // until the current routine returns to its caller
    // advance: until the PC reaches `pc` (or a breakpoint). until: the same, and also stops when the
    // current routine returns; without `pc`, until the PC passes the current one in this routine
    // (out of a loop).
    Stop advance(std::uint16_t pc) { return complete(begin_advance(pc)); }
    Stop until(std::optional<std::uint16_t> pc = {}) { return complete(begin_until(pc)); }
    Stop here(StopReason reason) const;  // a Stop describing the machine now
    // A guard on machine time (--max-time): no run goes past the T-state `at`; one that would
    // stops there with an Error Stop whose message is `why`. ~0: none.
    void set_time_limit(std::uint64_t at, std::string why) {
        time_limit_ = at;
        time_limit_why_ = std::move(why);
    }
    // True once after a run stopped at the limit (a front end's command then fails).
    bool take_time_limit_hit() { return std::exchange(time_limit_hit_, false); }
    const std::string& time_limit_message() const { return time_limit_why_; }
    // Called between slices of a re-execution (under the reverse commands and `history`), at most
    // every kPollPeriod of host time: a front end that reads its requests on this thread (DAP, the
    // window) looks there for a pause and calls interrupt(). It must not run the debugger.
    void set_poll(std::function<void()> poll) { poll_ = std::move(poll); }
    static constexpr std::chrono::milliseconds kPollPeriod{10};
    // Ends a run from another thread or a signal handler (Ctrl-C); the run returns Interrupted.
    void interrupt() { interrupt_.store(true); }
    void interrupt_clear() { interrupt_.store(false); }
    // How much machine time continue, finish, until and advance run before they give up (a routine
    // that never returns, a breakpoint never reached): kContinueLimit unless the user sets another
    // (the console's `set limit TIME`).
    static constexpr std::uint64_t kContinueLimit = 600ull * board::kCpuHz;  // 10 minutes simulated
    void set_continue_limit(std::uint64_t tstates) { continue_limit_ = tstates; }
    std::uint64_t continue_limit() const { return continue_limit_; }

    // ---- resumable runs ----------------------------------------------------------------------------
    // The same runs cut into slices, for front ends that draw or read messages between them (the
    // GUI, DAP). begin_X starts X and returns its Stop when X ended at once (a single step, an
    // error); otherwise nullopt, and resume() carries it on for at most a budget, returning the
    // Stop once it has ended. pause() ends it between slices. Breakpoint conditions, hit conditions,
    // log points and the runaway guard are decided here, the same for every front end.
    // stop_at_halt false: a HLT does not end it (a board left running, woken by a key or RESET).
    std::optional<Stop> begin_continue() { return begin_continue(continue_limit_); }
    std::optional<Stop> begin_continue(std::uint64_t limit, bool stop_at_halt = true);
    std::optional<Stop> begin_step();
    std::optional<Stop> begin_next();
    std::optional<Stop> begin_finish();
    std::optional<Stop> begin_advance(std::uint16_t pc);
    std::optional<Stop> begin_until(std::optional<std::uint16_t> pc = {});
    std::optional<Stop> resume(const Budget& budget = {});
    bool running() const { return active_.has_value(); }
    Stop pause();  // ends the run under way (Paused); with none, a Stop describing now
    // Runs a begun run to its end (the blocking forms above).
    Stop complete(std::optional<Stop> begun);

    // Stop when the CPU fetches an instruction outside `code` (an address where a program was
    // loaded) after having run inside it: the Stop names the instruction that ran away (`after`).
    // nullptr: off.
    void set_runaway_guard(const std::bitset<0x10000>* code);
    // SP as the program last set it (LXI SP, SPHL; the CPU notes it, I8085::stack_load), while on:
    // return addresses above it are older code's (the monitor's), and backtraces end there.
    void track_stack_base(bool on) { track_stack_ = on; }
    std::optional<std::uint16_t> stack_base() const { return track_stack_ ? m_.cpu().stack_load() : std::nullopt; }

    // ---- reverse execution -------------------------------------------------------------------------
    // Snapshots every `interval` T-states while on; the machine can then be taken back to any
    // earlier instruction since history began: memory, chips, machine tool and time included.
    void set_history(bool on, std::uint64_t interval = kHistoryInterval);
    bool history() const { return history_on_; }
    // The machine was changed outside its run (set, load, reset): history after now is no longer
    // this timeline's, and a snapshot is taken now. `new_timeline` (a snapshot restored: the
    // machine's past is another run's): all history goes.
    void state_changed(bool new_timeline = false);
    Stop reverse_stepi();
    Stop reverse_step();      // as reverse_stepi (asm: a line is an instruction)
    Stop reverse_next();      // back one instruction of this routine (a routine called is undone whole)
    Stop reverse_finish();    // back to the CALL that entered this routine
    Stop reverse_continue();  // back to the previous breakpoint or watchpoint hit
    // The last `n` instructions before now, oldest first (re-executed from the snapshots: nothing
    // is traced while running). Fewer when history does not reach back so far.
    std::vector<Executed> last_instructions(std::size_t n);
    std::uint64_t history_start() const;  // the oldest T-state reverse execution can reach
    std::size_t history_snapshots() const;
    // True while the machine re-executes the past (front ends keep quiet about what it does again).
    bool replaying() const { return replaying_; }
    static constexpr std::uint64_t kHistoryInterval = 768'000;  // 250 ms simulated: a few per cent of a run's time

    // ---- breakpoints and watchpoints -------------------------------------------------------------
    // A location: a symbol or expression ("OUT", "OUT+3", "0B2CH", "*0B2CH") or FILE:LINE. A line
    // without code binds to the next line that has some; `bound` says which.
    struct Location {
        std::vector<std::uint16_t> addresses;
        std::optional<SourceLine> bound;
        std::string error;  // empty when found
        int col = 0;        // of the error, 1-based in the text given
    };
    Location locate_line(std::string_view file, int line) const;
    Location locate(std::string_view text) const;

    struct Added {
        int number = 0;        // 0: refused (error says why)
        std::string error;
        int col = 0;                      // of the error, in the location or the condition text
        bool in_condition = false;        // the error is the condition's
        std::optional<SourceLine> bound;  // FILE:LINE bound to a later line
    };
    Added add_breakpoint(std::string_view location, bool temporary = false, std::string_view condition = {});
    Added add_breakpoint_at(std::uint16_t address, bool temporary = false);
    Added add_watchpoint(const WatchSpec& spec, std::string_view condition = {});
    // By number (breakpoints and watchpoints share the numbers). False: no such number.
    bool remove(int number);
    void remove_all();
    bool remove_breakpoints_at(std::uint16_t address);
    bool enable(int number, bool on);
    // An empty condition removes it; otherwise the error (with column) or "".
    std::string set_condition(int number, std::string_view condition, int& col);
    bool set_ignore(int number, unsigned count);
    bool set_hits(int number, unsigned hits);  // a front end re-making its points keeps their counts
    bool set_commands(int number, std::vector<std::string> commands);
    // A hit condition (HitCondition's forms; empty removes it): "" or why the text is not one.
    std::string set_hit_condition(int number, std::string_view text);
    // A breakpoint becomes a log point (an empty message makes it a breakpoint again).
    bool set_log_message(int number, std::string message);
    // `message` with each {expression} replaced by its value (log points); "<error>" where one fails.
    std::string interpolate(std::string_view message) const;
    const std::vector<Breakpoint>& breakpoints() const { return breakpoints_; }
    const std::vector<Watchpoint>& watchpoints() const { return watchpoints_; }
    const Breakpoint* breakpoint(int number) const;
    const Watchpoint* watchpoint(int number) const;
    // The commands to run for the stop `s` (its breakpoint's or watchpoint's), or none.
    std::vector<std::string> commands_for(const Stop& s) const;

    // ---- looking --------------------------------------------------------------------------------
    struct Value {
        std::int64_t value = 0;
        int width = 16;
        std::string error;  // with col
        int col = 0;
    };
    Value evaluate(std::string_view expression) const;
    // Convenience variables ($NAME, `set $N = 3`): one set for the console, conditions, log points
    // and DAP; an expression reads them when it is evaluated.
    Expr::Variables& variables() { return vars_; }
    const Expr::Variables& variables() const { return vars_; }
    // The current value of a machine-tool quantity (no side effects).
    std::int64_t tool_value(ToolQuantity q, periph::MachineTool::Axis axis) const;
    // A part's description as of the machine's time (no side effects).
    periph::Description describe(const periph::Part& part) const;
    std::vector<Frame> backtrace() const;  // a caller's line: its CALL's (or RST's), as gdb shows it
    // Where the program is, to show: the PC, or the HLT's address while the CPU is halted (its PC
    // is past the HLT; gdb shows an exited program where it ended).
    std::uint16_t where() const;

    // ---- the machine's state, as a debugger reads and writes it --------------------------------
    // Front ends read the board here and through the Session, never the Machine: nothing below
    // changes a device, and the writes are a debugger's (memory by poke, a register in the file).
    std::uint64_t now() const { return m_.now(); }
    // A register through the CPU's description (any kind but Memory, which is memory at HL).
    std::uint16_t reg(const cpu::Register& r) const { return r.read(m_.cpu().regs()); }
    void set_reg(const cpu::Register& r, std::uint16_t value) { r.write(m_.cpu().regs(), value & r.mask()); }
    CpuStatus cpu_status() const;
    // The bus without side effects (FFH where nothing answers), and a write into RAM or EPROM
    // storage (false where nothing is mapped).
    std::uint8_t peek(std::uint16_t address) const { return m_.peek(address); }
    bool poke(std::uint16_t address, std::uint8_t value) { return m_.poke(address, value); }
    bool in_ram(std::uint16_t address) const;  // the board's memory map says RAM there
    // The instruction at `address`, its operands named from the program's symbols unless `plain`.
    asm85::Disassembly disassemble(std::uint16_t address, bool plain = false) const {
        return alp85::disassemble(m_.bus(), address, m_.cpu().variant(), plain ? nullptr : &program_);
    }
    // Every part beside the CPU, in the machine's order (describe() tells what each shows).
    const std::vector<periph::Part*>& parts() const { return m_.parts(); }
    std::array<std::uint8_t, 8> display() const { return m_.display(); }  // segment bytes, leftmost first
    std::string display_text() const { return m_.display_text(); }

    // Every outside input applied so far, with its T-state (Machine::input_log).
    const std::vector<InputEvent>& input_log() const { return m_.input_log(); }

private:
    class Observer;
    class History;
    friend class Observer;
    friend class History;

    // A run begun and not yet ended (resumable).
    struct Active {
        std::uint64_t until = 0;
        std::function<bool()> condition;
        bool first = true;                    // the first slice: a breakpoint at the start does not stop
        bool stop_at_halt = false;            // continue and steps: HLT ends them
        std::optional<StopReason> target_as;  // what reaching the target is called
        std::uint64_t limit = 0;              // continue: its limit, for the message at the deadline
        bool emit_stops = false;              // run_until: stops are also Stopped events
        Origin origin;
    };
    // The one run loop: a slice of chunks up to the next snapshot time, observer armed as needed;
    // nullopt when the slice's budget ran out before the run ended.
    std::optional<Stop> drive(const Budget& budget);
    std::optional<Stop> begin(Active a, std::function<bool(const I8085&)> target = {});
    Stop end_run(Stop s);
    std::optional<Stop> begin_with_target(std::function<bool(const I8085&)> target, StopReason reason);
    // A Part watchpoint's value: the part's description read again only when the part's state
    // bytes changed since the last read (a check runs before every instruction; describing costs
    // far more than comparing), at the part's own time, as the machine last caught it up. A part
    // changes only when it is caught up (its time moves), through I/O (`io`: the instruction was
    // an IN or OUT) or by an outside input (a key, RESET); otherwise not even its bytes are read.
    std::int64_t part_watch_value(Watchpoint& w, bool io = true);
    // Re-execution: the machine back at checkpoint `c`, then run to `t` (a position of this
    // timeline), recording boundaries and/or hits on the way, a slice of kReplaySlice T-states at
    // a time; after each slice `drain` takes what was recorded (and empties the vectors). Only
    // interrupt() stops it: false, the machine left where it had got to.
    bool replay(const Checkpoint& c, std::uint64_t t, std::vector<Boundary>* record, std::vector<Hit>* hits,
                const std::function<void()>& drain = {});
    Stop interrupted_reverse();  // a reverse command's Stop when interrupt() ended its re-execution
    static constexpr std::uint64_t kReplaySlice = 65'536;  // about 21 ms simulated, well under 1 ms of host time
    Stop reverse_frame(bool finish);
    // Inputs scheduled since the last run (a key pressed after going back): snapshots later than
    // now belong to the old future and go.
    void check_inputs();
    Stop no_history(std::string why);
    void arm();     // installs the observer iff something needs it
    void rebaseline();  // watched values as they are now
    Stop finish_stop(Stop s);  // temporary breakpoints, the line
    std::optional<std::uint16_t> return_slot() const;  // the current routine's return address slot
    int next_number() { return ++last_number_; }
    Breakpoint* find_bp(int number);
    Watchpoint* find_wp(int number);

    Machine& m_;
    std::vector<std::uint8_t> part_state_;  // part_watch_value's scratch
    SymbolTable program_;
    std::vector<Listener> listeners_;
    std::vector<Breakpoint> breakpoints_;
    std::vector<Watchpoint> watchpoints_;
    int last_number_ = 0;
    std::unique_ptr<Observer> observer_;
    std::unique_ptr<History> history_;
    bool history_on_ = false;
    bool replaying_ = false;
    std::uint64_t seen_seq_ = 0;  // the input queue's numbering at the last run
    std::atomic<bool> interrupt_{false};
    std::function<void()> poll_;
    std::chrono::steady_clock::time_point poll_due_{};  // when replay() calls poll_ next
    std::optional<Active> active_;
    Expr::Variables vars_;
    bool halted_ = false;  // set by the CPU's HLT while a run that stops there is under way
    bool track_stack_ = false;
    std::uint64_t time_limit_ = ~std::uint64_t{0};
    std::uint64_t continue_limit_ = kContinueLimit;
    std::string time_limit_why_;
    bool time_limit_hit_ = false;
    Stop time_limit_stop();
    std::optional<std::bitset<0x10000>> code_;  // the runaway guard's map (nullopt: off)
};

}  // namespace alp85::debug
