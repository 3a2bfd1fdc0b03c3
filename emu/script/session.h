// Executes commands of the command language on one Machine: the engine behind `alp85 script` and
// the debugger's prompt. It keeps what a command needs beyond the machine: the symbols of loaded
// sources, the script's folder, and the time of the last reset.
#pragma once

#include <array>
#include <bitset>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "emu/program/firmware.h"
#include "emu/program/image_loader.h"
#include "emu/board/machine.h"
#include "emu/debug/debugger.h"
#include "emu/debug/signal_record.h"
#include "emu/debug/signal_trace.h"
#include "emu/debug/tool_record.h"
#include "emu/script/command.h"
#include "emu/script/parser.h"
#include "asm/files/output_paths.h"

namespace alp85::script {

struct SessionOptions {
    std::filesystem::path base_dir = ".";  // relative paths in commands start here
    Variant cpu = Variant::I8085;
    // The monitor EPROM image and its symbols for the `monitor` command (the front end supplies
    // the built ROM, firmware::monitor).
    std::function<firmware::Firmware()> monitor_rom;
    std::ostream* out = nullptr;  // events as text (print, stops, -v echo); nullptr: none
    bool verbose = false;
    // --max-time: no run takes the machine's clock past this many T-states; a command whose run
    // reaches it fails. ~0: no limit (the window, DAP); `alp85 script` and `alp85 debug` default
    // to kDefaultMaxTime, 1 h of machine time (a couple of minutes of host time).
    std::uint64_t max_time = ~std::uint64_t{0};
    static constexpr std::uint64_t kDefaultMaxTime = 3600ull * board::kCpuHz;
    const board::Board* board = &board::kAlp85;  // the board the Machine is built as (--board)
};

class Session {
public:
    enum class Status : std::uint8_t { Ok, Failed };
    struct Outcome {
        Status status = Status::Ok;
        std::string message;  // for Failed: what was expected, what was found, when
    };

    explicit Session(SessionOptions options);

    Machine& machine() { return *machine_; }
    const Machine& machine() const { return *machine_; }
    // The debugging API over this session's machine: front ends listen to its events.
    debug::Debugger& debugger() { return debugger_; }

    // ---- the typed API -------------------------------------------------------------------------
    // What every front end calls to drive the board (alp85 run, debug, gui, dap); the command
    // language's commands run through the same code. Paths are used as given (relative ones from
    // the session's folder); nothing is parsed from text.
    struct Boot {
        bool monitor = true;                     // the monitor EPROM (options.monitor_rom)
        std::filesystem::path rom;               // or the board's ROM from the user's file (load_rom)
        std::vector<std::string> firmware;       // built-in names (firmware::find)
        struct Image {
            std::filesystem::path path;          // .asm, .hex or .bin
            std::optional<std::uint16_t> address;  // where (a .bin needs one)
        };
        std::vector<Image> images;
        std::vector<std::pair<std::string, std::string>> defines;  // NAME=VALUE for every .asm image
        std::vector<std::filesystem::path> maps;  // asm85 maps read after the images (a .hex's symbols, lines)
        std::optional<periph::MachineTool::MotorModel> motor;
        bool reset = true;                       // RESET IN once everything is in place
        // A board without the monitor: after the reset the PC is at the last image's start (its
        // END address, else its first byte), else at the last firmware's first byte.
        bool pc_at_program = false;
        // Keys typed after the reset: the first closes `boot_time` after it, each held kKeyHold
        // with kKeyGap before the next (as the script's `type`); the machine does not run here.
        std::vector<KeyRef> keys;
        std::uint64_t boot_time = 0;
    };
    // What a boot placed: where the CPU may fetch instructions (every RAM byte and every byte
    // loaded: a fetch anywhere else is a runaway), and the loads' warnings (asm85's, file:line:col).
    struct BootReport {
        std::bitset<0x10000> code;
        std::vector<std::string> warnings;
    };
    Outcome boot(const Boot& b, BootReport* report = nullptr);
    Outcome load_monitor();
    // The board's ROM at 0000H from the user's file (alp85 run --rom: a 2 KB .bin dump, Intel HEX or
    // asm85 source; emu/program/rom_image.h); check_rom says why a file will not do ("" if it will).
    Outcome load_rom(const std::filesystem::path& path);
    std::string check_rom(const std::filesystem::path& path) const;
    Outcome load_firmware(const std::string& name);
    Outcome load_image(const std::filesystem::path& path, std::optional<std::uint16_t> address = {});
    Outcome reset();
    Outcome save(const std::filesystem::path& path);
    Outcome restore(const std::filesystem::path& path);
    Outcome record(const std::filesystem::path& csv, std::uint64_t period);
    // record signals FILE.vcd [PIN...] [every T] (docs/signals.md): the pins as a VCD until record_stop.
    Outcome record_signals(const std::filesystem::path& vcd, const std::vector<std::string>& pins,
                           std::uint64_t period = kDefaultSignalPeriod);
    Outcome record_stop();
    // The window's Signals pane (docs/signals.md): the chosen pins (the words of record signals)
    // kept in memory over the last `span` T-states while the machine runs, beside any recording;
    // a trace already open is replaced. trace_stop closes it (the board then pays nothing).
    Outcome trace_signals(const std::vector<std::string>& pins, std::uint64_t span);
    void trace_stop() { pane_trace_.stop(); }
    const debug::SignalTrace& signal_trace() const { return pane_trace_; }
    void set_trace_span(std::uint64_t span) { pane_trace_.set_span(span); }
    // Every pin a recording or a trace can name, in a recording's order (the pane's picker).
    std::vector<debug::PinTap::PinName> pin_names() const { return debug::PinTap::pin_names(*machine_); }
    // The recorded X-Y path and the ideal line between two points (mm; default the path's ends).
    Outcome plot_toolpath(const std::filesystem::path& out, const std::optional<std::array<double, 4>>& ideal_line = {});
    Outcome set_motor(periph::MachineTool::MotorModel model);
    Outcome new_workpiece();  // the operator's set-up of a new workpiece (the script's `new workpiece`)
    // A key pressed or released now, or at machine time `at` (a user at the keypad, a press held
    // long enough for the debounce): the one entrance of every front end's keys.
    void key(Button button, periph::Key key, bool down, std::optional<std::uint64_t> at = {});
    // The machine tool sampled every `period` T-states of machine time (a window drawing the
    // toolpath); an empty function stops it. One sampler: a recording (record) takes its place.
    void sample_tool(std::uint64_t period, std::function<void(const debug::ToolSample&)> sample);
    // The address space as a debugger sees it (DAP's readMemory, writeMemory): peek has no side
    // effects; poke writes RAM or EPROM alike, false where nothing is mapped.
    std::uint8_t peek(std::uint16_t address) const { return machine_->peek(address); }
    bool poke(std::uint16_t address, std::uint8_t value) { return machine_->poke(address, value); }
    // The PC moved by hand (DAP's goto, the console's jump): reverse execution's history ends here.
    void set_pc(std::uint16_t pc);
    // The machine's time in T-states (board::kCpuHz a second).
    std::uint64_t now() const { return machine_->now(); }
    // A serial terminal on SID and SOD (docs/signals.md, "A serial line on SID/SOD"), connected
    // once for the rest of the session; `gap`: idle T-states it leaves between the characters it
    // sends. Failed if one is already connected.
    Outcome connect_serial(const periph::UartFormat& format, std::uint64_t gap);
    periph::SerialTerminal* serial() { return serial_.get(); }
    // Characters typed at that terminal now, scheduled as the keys are; sent one after another.
    void serial_type(std::string_view text);

    // ---- state, read and written as a debugger does -------------------------------------------
    // A register through the CPU's description (cpu::description()): read, or set to the low
    // `width` bits (no history ends: set_reg does that for a script's `set reg`).
    std::uint16_t reg(const cpu::Register& r) const { return debugger_.reg(r); }
    bool halted() const { return machine_->cpu().halted(); }
    // The eight digits' segment bytes (leftmost first) and their nearest characters.
    std::array<std::uint8_t, 8> display() const { return machine_->display(); }
    std::string display_text() const { return machine_->display_text(); }
    // The machine tool as it stands (not caught up with the machine's time: what it last did).
    const periph::MachineTool& tool() const { return machine_->tool(); }
    // An accessory added to the board (Machine::attach): advanced, reset and saved with the
    // board's own parts from now on; it must outlive the session.
    void attach(periph::Part& part, IoDevice* io = nullptr, std::uint8_t first = 0, std::uint8_t last = 0);

    // ---- checks before a run ----------------------------------------------------------------------
    // What check() checks of a script's lines, for a front end that makes the typed calls itself
    // (alp85 run) and reports the problems at its own arguments. Each gives "" or why; `known`
    // collects the symbols the loads so far define (an address may name only those). Paths are
    // taken as load_image takes them.
    std::string check_monitor(std::set<std::string>& known) const;
    std::string check_firmware(const std::string& name, std::set<std::string>& known) const;
    // The file can be read as a program; a binary (.bin, .rom) needs an address.
    std::string check_program(const std::filesystem::path& path, bool has_address) const;
    // It assembles (or reads) and fits the board at `address` (an expression: its regions are
    // checked when it loads). The image is kept for load_image; its warnings join warnings().
    std::string check_image(const std::filesystem::path& path, const std::optional<Value>& address,
                            std::set<std::string>& known);
    // A value's problems, each with its column in the line: a number outside lo..hi (`what`
    // names it), a name that no load before it defines.
    std::vector<std::pair<int, std::string>> check_value(const Value& v, std::int64_t lo, std::int64_t hi,
                                                         const char* what, const std::set<std::string>& known) const;
    std::string check_pin(const std::string& pin) const;  // a word of record signals (docs/signals.md)
    std::string check_key(const KeyRef& key) const;       // a key this board has (the SDK-85 has no R, no PREV)
    // A value against the symbols and the machine of now (nullopt: `error` says why).
    std::optional<std::int64_t> value(const Value& v, std::string& error) const { return resolve(v, error); }

    // Every other command of the language, one call each (docs/scripting.md names them by their
    // command): the script's lines are parsed, their values resolved, then these do the work.
    // Keys, runs and breakpoints:
    Outcome key_now(Button button, periph::Key key, bool down);  // keydown/keyup: changed and delivered now
    Outcome press(Button button, periph::Key key, std::uint64_t hold = kDefaultHold, std::uint64_t gap = kDefaultGap);
    Outcome type(const std::vector<KeyRef>& keys, std::uint64_t hold = kDefaultHold, std::uint64_t gap = kDefaultGap);
    Outcome run(std::uint64_t tstates);
    Outcome run_until(std::uint16_t address, std::uint64_t timeout = kDefaultUntil);  // passes breakpoints
    Outcome wait_display(const std::string& text, std::uint64_t timeout = kDefaultWait);
    Outcome step(unsigned count = 1);
    Outcome add_breakpoint(std::uint16_t address);
    Outcome delete_breakpoints(std::uint16_t address);
    Outcome delete_all_breakpoints();
    // Changing the machine:
    Outcome set_mem(std::uint16_t address, const std::vector<std::uint8_t>& bytes);
    Outcome set_reg(const cpu::Register& reg, std::uint16_t value);  // the value is masked to its width
    Outcome set_option(bool expansion_eprom) { return set_option("expansion", expansion_eprom); }  // option expansion on|off
    Outcome set_option(std::string_view name, bool fitted);  // an option of the board (Board::options)
    // The board as its description says (memory map, devices, wiring, keys, display): `info board`.
    const board::Board& board() const { return machine_->board(); }
    static const board::Board& default_board() { return *board::kBoards.front(); }  // the ALP 85
    // The board with that name (alp85, sdk85: --board), or nullptr; "alp85, sdk85" for messages.
    static const board::Board* find_board(std::string_view name) { return board::find_board(name); }
    static std::string board_names() { return board::board_names(); }
    std::string describe_board() const;
    Outcome set_feedback(periph::MachineTool::Feedback feedback);
    Outcome mark();
    // Showing (as Output events):
    Outcome print(const std::string& text);
    Outcome print_display(bool as_text);
    Outcome print_axes();
    Outcome print_time();
    Outcome plot_time(const std::filesystem::path& out);
    // Expectations: Failed (and an ExpectFailed event) with what was expected and what was found.
    Outcome expect_display(const std::string& text);
    Outcome expect_mem(std::uint16_t address, const std::vector<std::uint8_t>& bytes);
    Outcome expect_word(std::uint16_t address, std::uint16_t value);
    Outcome expect_reg(const cpu::Register& reg, std::uint16_t value);
    Outcome expect_flag(const cpu::Flag& flag, bool set, const std::string& name);  // name: as written (C for CY)
    Outcome expect_port(char port, std::uint8_t value);  // 'A', 'B' or 'C'
    Outcome expect_symbol(const std::string& name, std::uint16_t value);
    Outcome expect_time(Compare compare, std::uint64_t tstates);
    Outcome expect_halted(bool halted);
    // The machine tool's axes (0 X, 1 Y, 2 Z); steps are whole steps, the nearest one.
    Outcome expect_axis_steps(std::uint8_t axis, Compare compare, std::int64_t steps);
    Outcome expect_axis_mm(std::uint8_t axis, Compare compare, double mm, double within);
    Outcome expect_count(std::uint8_t axis, Compare compare, std::int64_t count);
    Outcome expect_lost(std::uint8_t axis, Compare compare, std::int64_t lost);
    Outcome run_until_axis(std::uint8_t axis, Compare compare, std::int64_t steps, std::uint64_t timeout = kDefaultUntil);

    // Runs one command of the language: its values resolved against the symbols of now, then the
    // typed call above. Failed expectations and commands that cannot be carried out (a load that
    // falls off the board, a snapshot that is refused, a run-until that times out) give Failed,
    // the message naming the script line.
    Outcome execute(const Command& command);
    // When set, the files a script writes or keeps between runs (save, restore, record, plot)
    // are relative to this folder instead of the script's (alp85 script --out-dir: tests keep the
    // source tree clean).
    void set_out_dir(std::filesystem::path dir) { out_dir_ = std::move(dir); }
    // The files this session reads and the command line's own outputs: no file the session
    // writes (save, record, plot) may be one of the inputs or one of those outputs. The session
    // adds what it reads itself (loaded programs, restored snapshots); a front end adds the
    // script, its included files, a launched program, a map (add_input) and --trace, --junit
    // (add_output). `role` is how a refusal names the file ("the script").
    void add_input(const std::filesystem::path& path, std::string role);
    void add_output(const std::filesystem::path& path, std::string role);
    // "" when writing `path` destroys no input and no command-line output; else why.
    std::string output_problem(const std::filesystem::path& path, const std::string& role) const;
    const std::vector<NamedPath>& inputs() const { return inputs_; }
    // Ends the script: writes a recording still open (record FILE.csv without record stop).
    Outcome finish();
    const debug::ToolRecorder& recorder() const { return recorder_; }

    // Checks, before anything runs, what can be checked: files exist, sources assemble, binaries
    // have an address, symbols are defined by a load before their use, numbers fit, no save,
    // record or plot names a file the script reads (at any line) or a command-line output.
    // Appends every problem to `errors` and keeps the assembled images for the run.
    void check(const std::vector<Command>& commands, std::vector<ParseError>& errors);

    // Warnings of the loads check() read (asm85's, with file:line:col; an image crossing memory
    // regions), once each, for the front end to show.
    const std::vector<std::string>& warnings() const { return warnings_; }
    const SymbolTable& symbols() const { return debugger_.program(); }
    std::uint64_t elapsed() const { return machine_->now() - time_origin_; }
    // "at 12.345 ms (37920 T-states), PC=0123H, display "H1=----"" - for failure reports.
    std::string where_now() const;
    // A trace line per executed instruction (CSV), to `out`; nullptr stops it.
    void set_trace(std::ostream* out);
    // Commands that run the machine (run, wait, type, press, run until axis) run in slices of
    // `slice` T-states and call `pace` between them: a window draws and keeps to real time there.
    // Unset (the default), they run in one piece.
    void set_pace(std::function<void(std::uint64_t now)> pace, std::uint64_t slice) {
        pace_ = std::move(pace);
        pace_slice_ = slice;
    }

    static std::string format_limit(std::uint64_t t);  // a --max-time: "1 h", "90 s", "250 ms"
    static std::string format_time(std::uint64_t tstates);

private:
    // Every file a command names (load, save, restore) is relative to the script's folder.
    std::filesystem::path resolve(const std::string& path) const;
    std::filesystem::path resolve_output(const std::string& path) const;
    std::optional<std::int64_t> resolve(const Value& v, std::string& error) const;
    // Failures name the script line running (execute), if any: its place, its text and the
    // machine's state; a front end's typed call gets `what` alone.
    Outcome fail(std::string what) const { return fail_at(line_, std::move(what)); }
    Outcome fail_at(const Command* line, std::string what) const;
    debug::Origin origin() const;
    void output(std::string text) const {
        debugger_.emit({debug::Event::Kind::Output, {}, std::move(text), origin()});
    }
    Outcome fail_expect(const std::string& expected, const std::string& actual) const;
    // A run that reached --max-time failed, whatever it was for.
    Outcome ran(Outcome o);
    Outcome run_command(const Command& c);
    Outcome load_image(const std::filesystem::path& file, std::optional<std::uint16_t> address,
                       const std::vector<std::pair<std::string, std::string>>& defines);  // a boot's images
    void placed(const std::vector<ImageSegment>& segments);  // marks them in a boot's report
    Outcome boot_steps(const Boot& b);
    Outcome write_recording();
    Outcome write_signals();
    Outcome stop_recordings();
    debug::Stop run_paced(std::uint64_t until, const std::function<bool()>& condition);
    std::string axes_text() const;
    periph::MachineTool& tool_now();  // the tool caught up with the machine's time
    // The state a typed call changed outside a run: reverse execution's history ends there.
    struct Changed {
        debug::Debugger& d;
        bool new_timeline = false;
        ~Changed() { d.state_changed(new_timeline); }
    };

    SessionOptions options_;
    std::unique_ptr<periph::SerialTerminal> serial_;  // before the machine: it outlives it
    std::unique_ptr<Machine> machine_;
    debug::Debugger debugger_;
    std::filesystem::path out_dir_;
    std::optional<std::uint64_t> mark_;  // `mark`: the time `print time` also counts from
    debug::ToolRecorder recorder_;
    debug::SignalRecorder signals_;
    debug::SignalTrace pane_trace_;  // after machine_: closed (its probe off the board) before the machine goes
    const Command* line_ = nullptr;           // the script line execute() runs; none during a typed call
    std::optional<Command> signals_line_;     // the line that started the recordings, for their failures
    std::function<void(std::uint64_t)> pace_;
    std::uint64_t pace_slice_ = 0;
    std::filesystem::path record_path_;
    std::optional<Command> record_line_;
    std::map<std::string, LoadedImage> assembled_;  // from check(), by resolved path
    std::vector<std::string> warnings_;
    std::uint64_t time_origin_ = 0;
    BootReport* report_ = nullptr;  // while boot() runs with one
    std::optional<std::uint16_t> last_start_;  // the last loaded image's start (END, else its first byte)
    std::ostream* trace_ = nullptr;
    std::vector<NamedPath> inputs_, outputs_;  // add_input, add_output
    std::vector<std::string> written_;         // what this session wrote: restoring it protects nothing
};

}  // namespace alp85::script
