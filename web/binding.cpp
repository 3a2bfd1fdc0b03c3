// The web page's handle on the board (embind): one script Session, driven through its typed calls
// and the Debugger's resumable run, exactly as the window (emu/gui) drives it. The page draws;
// nothing here builds command text or decodes instructions. The key map, the presses, the pacing,
// the toolpath with its ideal line and the views of the board are the front ends' shared library
// (emu/front), the window's too.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <array>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "asm/asm85.h"
#include "emu/debug/tool_record.h"
#include "emu/gcode/gcode.h"
#include "emu/gcode/path_table.h"
#include "emu/front/keys.h"
#include "emu/front/pacer.h"
#include "emu/front/toolpath.h"
#include "emu/front/views.h"
#include "emu/program/firmware.h"
#include "emu/script/session.h"

namespace alp85::web {
namespace {

using emscripten::val;
using front::HostClock;

// Files the page hands the board live in the module's memory file system (MEMFS), under /work;
// the firmware sources the editor's INCLUDEs reach are packed under /src (web/CMakeLists.txt).
const std::filesystem::path kWork = "/work";
constexpr std::uint64_t kSamplePeriod = board::tstates_from_ms(1);  // the window's toolpath clock
// The project's own SDK-85 test program (firmware/sdk85/sdk85test.asm, as the native build
// assembled it): the ROM a board whose ROM is the user's runs until the user loads one.
const std::filesystem::path kTestRom = "/src/sdk85/sdk85test.bin";

// The board by its name (the page's ?board=), the default one for a name there is none of.
script::SessionOptions options(const std::string& board) {
    script::SessionOptions o;
    o.monitor_rom = [] { return firmware::monitor(); };
    if (const auto* b = script::Session::find_board(board)) o.board = b;
    return o;
}

val outcome(const script::Session::Outcome& o) {
    return val(o.status == script::Session::Status::Ok ? std::string() : o.message);
}

// The snapshot's layout (web/main.js reads it by the same numbers).
constexpr std::size_t kSnapT = 0, kSnapPc = 1, kSnapRunning = 2, kSnapStops = 3, kSnapDisplayChanges = 4,
                      kSnapDigits = 5, kSnapAxes = 13, kSnapPathSize = 25, kSnapIdeal = 26, kSnapLog = 31,
                      kSnapHalted = 32, kSnapSize = 33;

// The boards there are, for the page's selector: [name, title], the default first.
val boards() {
    val out = val::array();
    for (const front::BoardChoice& b : front::board_choices()) {
        val o = val::array();
        o.call<void>("push", std::string(b.name));
        o.call<void>("push", std::string(b.title));
        out.call<void>("push", o);
    }
    return out;
}

}  // namespace

class Board {
public:
    explicit Board(const std::string& board) : session_(options(board)) {
        std::filesystem::create_directories(kWork);
        session_.debugger().listen([this](const debug::Event& e) {
            if (!e.text.empty()) log_.push_back(e.text);
        });
    }

    // The monitor and the named firmware ("thesis-fixed", "thesis", "master": the master program
    // goes in beside thesis-fixed, whose line routine it calls), then RESET, and the board runs.
    std::string boot(const std::string& name) {
        pause();
        script::Session::Boot b;
        if (name == "master") b.firmware = {"thesis-fixed", "master"};
        else b.firmware = {name};
        const auto o = session_.boot(b);
        after_load();
        if (o.status != script::Session::Status::Ok) return o.message;
        start();
        return {};
    }

    // The board's name and title, and whether its ROM is the user's (no monitor built in: the page
    // offers Load ROM... and runs the test program until then).
    std::string name() const { return std::string(session_.board().name); }
    std::string title() const { return std::string(session_.board().title); }
    bool user_rom() const { return !session_.board().builtin_firmware && front::monitor_rom(session_); }
    bool has_tool() const { return front::has_tool(session_); }
    int digits() const { return static_cast<int>(front::display_digits(session_)); }

    // Load ROM...: the user's file (a .bin, .hex or source, by its name's extension) checked by the
    // ROM loader as --rom is, then put in the board's ROM through the
    // session, RESET, and the board runs. The loader's refusal is returned for the page to show;
    // the board is then as it was.
    std::string load_rom(const std::string& file_name, const std::string& bytes) {
        const std::filesystem::path file = kWork / "rom" / std::filesystem::path(file_name).filename();
        std::filesystem::create_directories(file.parent_path());
        {
            std::ofstream out(file, std::ios::binary | std::ios::trunc);
            out << bytes;
        }
        return boot_rom(file);
    }
    // The test program built into the page, as the board boots by default.
    std::string boot_test_rom() { return boot_rom(kTestRom); }

    std::string reset() {
        const auto o = session_.reset();
        path_.clear();
        return o.status == script::Session::Status::Ok ? std::string() : o.message;
    }

    // The run: a Continue that a HLT does not end (a board left running still answers RESET and
    // the keys), cut into slices by frame().
    void start() {
        if (session_.debugger().running()) return;
        if (const auto s = session_.debugger().begin_continue(~std::uint64_t{0}, false)) stopped(*s);
        pacer_.rebase(session_.now(), HostClock::now());
    }
    void pause() {
        if (session_.debugger().running()) stopped(session_.debugger().pause());
    }
    bool running() { return session_.debugger().running(); }

    // speed: 1 real time, 10, ... ; 0 as fast as possible.
    void set_speed(double speed) { pacer_.set_speed(speed, session_.now(), HostClock::now()); }

    // One frame's slice: runs the machine to where the pacer says it should be by now, for at
    // most `seconds` of host time. Returns the T-states run.
    double frame(double seconds) {
        const std::uint64_t before = session_.now();
        debug::Debugger& d = session_.debugger();
        if (!d.running()) return 0;
        const std::uint64_t goal = pacer_.target(before, HostClock::now());
        if (goal > before) {
            debug::Budget b;
            b.tstates = goal - before;
            b.seconds = seconds;
            if (const auto s = d.resume(b)) stopped(*s);
        }
        return static_cast<double>(session_.now() - before);
    }

    // A board key by its name (find_pad_key: "0"-"F", "EXEC", "NEXT", "RESET", "VECT", ...), down
    // or up, or a PC key by the key map's name (KeyboardEvent.key: "Enter", "a", "Escape").
    bool key(const std::string& name, bool down) {
        const auto k = front::find_pad_key(name, session_);
        if (!k) return false;
        press(*k, down);
        return true;
    }
    std::string pc_key(const std::string& pc_name, bool down) {
        const auto k = front::pad_key_for_pc(pc_name, session_);
        if (!k) return {};
        press(*k, down);
        for (const front::KeypadKey& d : front::keypad_view(session_))
            if (d.key.pad == k->pad && d.key.row == k->row && d.key.col == k->col) return std::string(d.name);
        return {};
    }

    // The keypad as the window lays it out, from the board's description (front::keypad_view):
    // name, caption, PC key, row, column, function key.
    val keypad() const {
        val out = val::array();
        for (const front::KeypadKey& k : front::keypad_view(session_)) {
            val o = val::object();
            o.set("name", std::string(k.name));
            o.set("cap", std::string(k.cap));
            o.set("pc", std::string(k.pc));
            o.set("row", k.key.row);
            o.set("col", k.key.col);
            o.set("fn", k.fn);
            out.call<void>("push", o);
        }
        return out;
    }
    val key_map() const {
        val out = val::array();
        for (const front::KeyMapRow& r : front::key_map_rows(false, session_)) {
            if (r.keys.find("drag") != std::string_view::npos || r.keys.find("wheel") != std::string_view::npos ||
                r.keys.find("Home") != std::string_view::npos || r.keys.find("End") != std::string_view::npos)
                continue;  // the window's table view; the page has its own
            val o = val::array();
            o.call<void>("push", std::string(r.keys));
            o.call<void>("push", std::string(r.action));
            out.call<void>("push", o);
        }
        return out;
    }

    // The eight digits as text (the nearest character each, '.' for a dot).
    std::string display_text() const { return front::display_view(session_).text; }

    // What the page draws, in one array it reads without a call per figure (kSnap* below): time,
    // PC, the run, the eight digits' segments (with a count of their changes), the axes, the
    // toolpath's length and the ideal line. A view of the module's memory, filled in place.
    val snapshot() {
        const front::CpuView cpu = front::cpu_view(session_);
        auto& v = snap_;
        v[kSnapT] = static_cast<double>(session_.now());
        v[kSnapPc] = cpu.pc;
        v[kSnapRunning] = running() ? 1 : 0;
        v[kSnapHalted] = cpu.halted ? 1 : 0;  // after a HLT: the run goes on (RESET, interrupts), the CPU waits
        v[kSnapStops] = static_cast<double>(stops_);
        const auto digits = front::display_view(session_).segments;
        if (digits != digits_) {
            digits_ = digits;
            ++display_changes_;
        }
        v[kSnapDisplayChanges] = static_cast<double>(display_changes_);
        for (std::size_t i = 0; i < 8; ++i) v[kSnapDigits + i] = digits[i];
        const front::ToolView tool = front::tool_view(session_);
        for (std::size_t i = 0; i < 3; ++i) {
            const front::AxisView& a = tool.axes[i];
            v[kSnapAxes + 4 * i] = static_cast<double>(a.commanded);
            v[kSnapAxes + 4 * i + 1] = a.mm;
            v[kSnapAxes + 4 * i + 2] = static_cast<double>(a.count);
            v[kSnapAxes + 4 * i + 3] = static_cast<double>(a.lost);
        }
        v[kSnapPathSize] = static_cast<double>(path_.points().size());
        const auto l = path_.ideal(session_);
        v[kSnapIdeal] = l ? 1 : 0;
        if (l) v[kSnapIdeal + 1] = l->from.x, v[kSnapIdeal + 2] = l->from.y, v[kSnapIdeal + 3] = l->to.x, v[kSnapIdeal + 4] = l->to.y;
        v[kSnapLog] = static_cast<double>(log_.size());
        return val(emscripten::typed_memory_view(v.size(), v.data()));
    }

    // The toolpath's points from index `from` on (x, y in table mm, flat): a view the page copies.
    val path_since(int from) {
        const auto& p = path_.points();
        points_.clear();
        for (std::size_t i = static_cast<std::size_t>(std::max(0, from)); i < p.size(); ++i) {
            points_.push_back(p[i].x);
            points_.push_back(p[i].y);
        }
        return val(emscripten::typed_memory_view(points_.size(), points_.data()));
    }
    void clear_path() { path_.clear(); }
    std::string stop_text() const { return stop_; }

    // asm85 on the editor's text: its diagnostics (severity, line, col, message); with no error,
    // the image is loaded through the session as any .asm is (the symbols come with it).
    val assemble(const std::string& source) {
        const std::filesystem::path file = "/src/user/program.asm";  // INCLUDE ../monitor/monitor.inc works
        std::filesystem::create_directories(file.parent_path());
        {
            std::ofstream out(file, std::ios::binary | std::ios::trunc);
            out << source;
        }
        asm85::Options opt;
        const asm85::Result r = asm85::assemble_file(file, opt);
        val o = val::object();
        val diags = val::array();
        for (const asm85::Diagnostic& d : r.diagnostics) {
            val x = val::object();
            x.set("severity", std::string(d.severity == asm85::Severity::Error     ? "error"
                                          : d.severity == asm85::Severity::Warning ? "warning"
                                                                                   : "note"));
            x.set("file", d.file);
            x.set("line", d.line);
            x.set("col", d.col);
            x.set("message", d.message);
            x.set("text", asm85::format_diagnostic(d));
            diags.call<void>("push", x);
        }
        o.set("diagnostics", diags);
        o.set("ok", r.ok());
        if (r.ok()) {
            o.set("bytes", static_cast<int>(r.image.size()));
            if (!r.image.empty()) o.set("lowest", static_cast<int>(r.image.lowest()));
            if (!r.image.empty()) o.set("highest", static_cast<int>(r.image.highest()));
            const bool was = running();
            pause();
            const auto l = session_.load_image(file);
            after_load();
            if (was) start();
            o.set("load", outcome(l));
        }
        return o;
    }

    // G-code (docs/contours.md's subset) to the master program's path table, loaded at 3DD0H.
    std::string gcode(const std::string& text) {
        try {
            return load_gcode(text);
        } catch (const std::exception& e) {  // the page shows it; the board is as it was
            return e.what();
        }
    }
    std::string load_gcode(const std::string& text) {
        const gcode::Parsed p = gcode::parse(text);
        if (p.error) return "line " + std::to_string(p.error->line) + ", column " + std::to_string(p.error->column) + ": " + p.error->message;
        const bool sampling = p.method && *p.method == gcode::Method::Sampling;
        const bool ramp = p.ramp.value_or(true);
        const std::vector<std::vector<gcode::Entry>> paths{sampling ? gcode::sampling_path(p.entries, ramp) : p.entries};
        const std::vector<std::uint8_t> bytes = gcode::table_bytes(paths);
        if (bytes.size() > gcode::kTableSize)
            return "the path needs " + std::to_string(bytes.size()) + " bytes; the EPROM holds " + std::to_string(gcode::kTableSize);
        const std::filesystem::path file = kWork / "path.hex";
        {
            std::ofstream out(file, std::ios::binary | std::ios::trunc);
            out << gcode::intel_hex(gcode::kTableBase, bytes);
        }
        const bool was = running();
        pause();
        const auto o = session_.load_image(file);
        if (was) start();
        return o.status == script::Session::Status::Ok ? std::string() : o.message;
    }

    // A snapshot as the bytes of the file alp85 writes (the page downloads them), and back.
    val save() {
        const bool was = running();
        pause();
        const std::filesystem::path file = kWork / "board.alp85snap";
        const auto o = session_.save(file);
        if (was) start();
        if (o.status != script::Session::Status::Ok) return val(o.message);
        std::ifstream in(file, std::ios::binary);
        const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        return val::global("Uint8Array").new_(emscripten::typed_memory_view(bytes.size(), bytes.data()));
    }
    std::string restore(const std::string& bytes) {
        const std::filesystem::path file = kWork / "picked.alp85snap";
        {
            std::ofstream out(file, std::ios::binary | std::ios::trunc);
            out << bytes;
        }
        pause();
        const auto o = session_.restore(file);
        if (o.status == script::Session::Status::Ok) path_.restored();  // a refused snapshot leaves the drawing
        after_load();
        start();
        return o.status == script::Session::Status::Ok ? std::string() : o.message;
    }

    // What the session said (prints, failures), oldest first; taken once.
    val take_log() {
        val out = val::array();
        for (const std::string& l : log_) out.call<void>("push", l);
        log_.clear();
        return out;
    }

private:
    // The board's ROM from a file, through the Session's ROM loader (as --rom; a refusal leaves the
    // board as it was), then RESET and the board runs.
    std::string boot_rom(const std::filesystem::path& file) {
        if (const auto o = session_.load_rom(file); o.status != script::Session::Status::Ok) return o.message;
        pause();
        const auto o = session_.reset();
        path_.clear();
        after_load();
        start();
        return o.status == script::Session::Status::Ok ? std::string() : o.message;
    }
    void press(const front::PadKey& k, bool down) {
        if (down) presser_.down(k, session_);
        else presser_.up(k, session_);
    }
    void stopped(const debug::Stop& s) {
        ++stops_;
        stop_ = std::string(debug::name(s.reason));
        if (!s.message.empty()) stop_ += ": " + s.message;
    }
    // As the window: the thesis's variables give the ideal line; the sampler draws the toolpath.
    void after_load() {
        const auto& sym = session_.symbols();
        path_.set_variables(sym.value_of("X2") && sym.value_of("Y2") ? sym.value_of("X1") : std::nullopt);
        session_.sample_tool(kSamplePeriod, [this](const debug::ToolSample& t) { path_.observe(t, session_); });
    }

    script::Session session_;
    front::Presser presser_;
    front::Pacer pacer_;
    front::Toolpath path_;
    std::vector<std::string> log_;
    std::string stop_;
    std::uint64_t stops_ = 0;
    std::array<std::uint8_t, 8> digits_{};
    std::uint64_t display_changes_ = 0;
    std::array<double, kSnapSize> snap_{};
    std::vector<double> points_;
};

}  // namespace alp85::web

EMSCRIPTEN_BINDINGS(alp85) {
    using alp85::web::Board;
    emscripten::class_<Board>("Board")
        .constructor<std::string>()
        .function("name", &Board::name)
        .function("title", &Board::title)
        .function("userRom", &Board::user_rom)
        .function("hasTool", &Board::has_tool)
        .function("digits", &Board::digits)
        .function("loadRom", &Board::load_rom)
        .function("bootTestRom", &Board::boot_test_rom)
        .function("boot", &Board::boot)
        .function("reset", &Board::reset)
        .function("start", &Board::start)
        .function("pause", &Board::pause)
        .function("running", &Board::running)
        .function("setSpeed", &Board::set_speed)
        .function("frame", &Board::frame)
        .function("key", &Board::key)
        .function("pcKey", &Board::pc_key)
        .function("keypad", &Board::keypad)
        .function("keyMap", &Board::key_map)
        .function("displayText", &Board::display_text)
        .function("snapshot", &Board::snapshot)
        .function("stopText", &Board::stop_text)
        .function("pathSince", &Board::path_since)
        .function("clearPath", &Board::clear_path)
        .function("assemble", &Board::assemble)
        .function("gcode", &Board::gcode)
        .function("save", &Board::save)
        .function("restore", &Board::restore)
        .function("takeLog", &Board::take_log);
    emscripten::function("boards", &alp85::web::boards);
}
