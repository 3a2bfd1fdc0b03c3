#include "emu/gui/app.h"

#include <sys/resource.h>

#include <array>
#include <atomic>
#include <cctype>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <utility>
#include <iostream>
#include <thread>

#include <SDL.h>
#include <SDL_opengl.h>
#include <fmt/format.h>
#include <imgui.h>
#include <backends/imgui_impl_opengl3.h>
#include <backends/imgui_impl_sdl.h>

#include "emu/debug/tool_record.h"
#include "emu/gui/backdrop.h"
#include "emu/gui/board_view.h"
#include "emu/gui/canvas.h"
#include "emu/gui/controls.h"
#include "emu/gui/debug_panes.h"
#include "emu/gui/frame_hook.h"
#include "emu/gui/input.h"
#include "emu/gui/screenshot.h"
#include "emu/gui/signals_pane.h"
#include "emu/gui/terminal_pane.h"
#include "emu/gui/tool_view.h"
#include "emu/front/pacer.h"
#include "emu/front/toolpath.h"
#include "emu/front/views.h"
#include "emu/plot/plot.h"
#include "emu/program/firmware.h"
#include "emu/script/parser.h"
#include "emu/script/runner.h"
#include "emu/script/debug_shell.h"
#include "emu/script/session.h"

namespace alp85::gui {
namespace {

constexpr auto kMachineBudget = std::chrono::milliseconds(10);  // of a 16.7 ms frame

// SIGTERM (and SIGINT, Ctrl-C in the terminal that started the window) end the window within a
// second whatever it is doing: the handler interrupts the debugger's run or re-execution under
// way, and the frame loop and the script see the flag.
volatile std::sig_atomic_t g_terminate = 0;  // the signal that asked, or 0
std::atomic<debug::Debugger*> g_debugger{nullptr};
extern "C" void on_terminate(int signal) {
    g_terminate = signal;
    if (debug::Debugger* d = g_debugger.load()) d->interrupt();
}
constexpr std::uint64_t kSamplePeriod = board::tstates_from_ms(1);
constexpr int kSettleFrames = 30;
constexpr std::uint64_t kPaceSlice = board::tstates_from_ms(1);  // a script's run, between looks at the clock

double cpu_seconds() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
           static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1e6;
}

std::string trim_right(std::string s) {
    while (!s.empty() && s.back() == ' ') s.pop_back();
    return s;
}

script::SessionOptions session_options(const GuiOptions& o) {
    script::SessionOptions s;
    if (!o.script.empty()) {
        const std::filesystem::path p(o.script);
        s.base_dir = p.parent_path().empty() ? std::filesystem::path(".") : p.parent_path();
    }
    if (firmware::have_monitor()) s.monitor_rom = firmware::monitor;
    s.out = &std::cout;
    if (const board::Board* b = script::Session::find_board(o.board)) s.board = b;
    return s;
}

class App final : public HookWindow {
public:
    App(const GuiOptions& o, SDL_Window* w, FrameHook* hook)
        : o_(o), window_(w), hook_(hook), shell_(session_options(o)), session_(shell_.session()) {
        if (!o.out_dir.empty()) session_.set_out_dir(o.out_dir);
        session_.set_motor(o.motor);
        if (o.parts) o.parts(session_);
        // The terminal leaves a character's time between the characters it sends (as alp85 run).
        if (o.serial) done(session_.connect_serial(*o.serial, o.serial->frame_tstates(board::kCpuHz)));
        panes_.shown_part = o.show_part;
        session_.debugger().listen([this](const debug::Event& e) { ui_.add_log(e.text); });
        // The built-in firmware is the ALP 85's (the default board's); the machine tool's menu only
        // on a board that has the tool.
        if (session_.board().builtin_firmware)
            for (const auto& e : firmware::builtin()) ui_.firmware_names.emplace_back(e.name);
        ui_.tool = has_tool(session_);
        for (std::size_t i = 0; i < ui_.firmware_names.size(); ++i)
            if (ui_.firmware_names[i] == "thesis-fixed") ui_.firmware = static_cast<int>(i);
        ui_.speed = o.speed;
        pacer_.set_speed(kSpeeds[static_cast<std::size_t>(o.speed)].factor, session_.now(), HostClock::now());
        key_map_ = o.key_map;
        session_.debugger().set_poll([this] { poll_during_reverse(); });
        if (o.debug) {
            shell_.debugger().set_history(true);
            ui_.running = false;  // the debugger starts paused: Continue (or the prompt) runs it
        }
    }

    int start();
    int loop();
    debug::Debugger& debugger() { return session_.debugger(); }
    bool canvas_ok() { return canvas_.init(kWindowWidth, kWindowHeight); }

    // What a frame hook sees (emu/gui/frame_hook.h).
    script::DebugShell& shell() override { return shell_; }
    DebugPanes& panes() override { return panes_; }
    TerminalPane& terminal() override { return terminal_; }
    const SignalsPane& signals() const override { return signals_; }
    const Toolpath& toolpath() const override { return path_; }
    SDL_Window* window() override { return window_; }
    Vec2 window_point(Vec2 logical) const override { return logical_to_window(logical.x, logical.y); }
    void pause_asked() override { pause_asked_ = HostClock::now(); }
    void fail(int status) override { status_ = status; }
    void quit() override { quit_ = true; }

private:
    bool done(const script::Session::Outcome& o);
    // Runs: Continue/Run begin one that stops at breakpoints (and, debugging, at HLT); each frame
    // resumes it within the frame's budget; Pause ends it. The same Debugger run as DAP's.
    void begin_run(bool stop_at_halt);
    void pause_run();
    void report(const debug::Stop& s);
    void debug_request(DebugPanes::Request r);
    // The reverse buttons: the request waits a frame, drawn with Pause showing, then runs whole
    // (it holds the frame loop); meanwhile poll_during_reverse() reads the window's events: a
    // click on Pause (or the Controls' Run/Pause) or closing the window ends it.
    void run_reverse(DebugPanes::Request r);
    void poll_during_reverse();
    std::optional<DebugPanes::Request> reverse_pending_;
    void after_commands();
    void handle(const SDL_Event& e);
    void step_script(HostClock::time_point until);
    void run_machine(HostClock::time_point until);
    void act(const Action& a);
    void plot_drawn(const std::string& file);
    void draw();
    void draw_controls();
    bool render_frame();
    void present(bool painted);
    void pace_script();
    // Waits for the next frame: 60 a second while the user acts (an event less than kCalm ago, or a
    // hook is busy), else 30 - a moving table looks the same and costs half to draw.
    // An event ends a calm wait at the next sixtieth of a second.
    static constexpr std::chrono::milliseconds kCalm{500};
    void wait_frame();
    HostClock::time_point last_input_{};
    bool in_command_ = false;  // a frame drawn while a script's command runs (pace_script)
    FrameClock clock_{HostClock::now()};
    void finish_stats(double wall, double cpu) const;
    std::string absolute(const std::string& p) const { return std::filesystem::absolute(p).string(); }

    const GuiOptions& o_;
    SDL_Window* window_;
    FrameHook* hook_;  // a test's (emu/gui/test_hooks.h), or none
    bool hook_busy() const { return hook_ && hook_->busy(); }
    script::DebugShell shell_;
    script::Session& session_;
    DebugPanes panes_;
    SignalsPane signals_;
    TerminalPane terminal_;            // --serial
    Toolpath path_;
    Backdrop backdrop_;
    Presser presser_;
    Pacer pacer_;
    ControlsState ui_;
    bool my_sampler_ = false;
    bool was_recording_ = false;
    std::size_t rec_seen_ = 0;
    std::vector<script::Command> script_;
    std::size_t script_pos_ = 0;
    bool script_active_ = false;
    int status_ = 0;
    std::optional<PadKey> mouse_key_;
    long idle_frames_ = 0;  // frames since the script and the hook were done
    long frames_ = 0;
    std::string pending_shot_;
    std::optional<HostClock::time_point> pause_asked_;  // --debug: when Pause was asked (the log says how long it took)
    bool quit_ = false;
    double fps_ = 0;
    Canvas canvas_;
    ToolView axes_{};
    long presented_ = 0;  // frames that changed the picture
    bool expose_ = true;
    double machine_s_ = 0, render_s_ = 0;  // host time in the machine and in drawing (--stats)
    // The window's scaling: the drawable's size, the logical picture's place in it, and drawable
    // pixels per window coordinate (2 on a HiDPI screen that reports points).
    Size drawable_{kWindowWidth, kWindowHeight};
    Fit fit_;
    float dpi_ = 1;
    void update_fit();
    Vec2 window_to_logical(float x, float y) const { return to_logical(fit_, x * dpi_, y * dpi_); }
    Vec2 logical_to_window(float x, float y) const {
        const Vec2 p = to_window(fit_, x, y);
        return {p.x / dpi_, p.y / dpi_};
    }
    // The table view's zoom and pan (mouse wheel, right drag, Home, End, double click).
    TableCamera camera_;
    bool panning_ = false;
    float pan_x_ = 0, pan_y_ = 0;
    bool table_input(const SDL_Event& e, const ImGuiIO& io);
    bool key_map_ = false;
};

// A typed session call's outcome: logged when it failed; the views then follow what changed.
bool App::done(const script::Session::Outcome& o) {
    if (o.status != script::Session::Status::Ok) ui_.add_log(o.message);
    after_commands();
    return o.status == script::Session::Status::Ok;
}

// What a command may have changed: the symbols (the thesis's variables), the sampler (a `record`
// takes the machine's sampling clock; the toolpath then reads its samples).
void App::after_commands() {
    const auto& sym = session_.symbols();
    path_.set_variables(sym.value_of("X2") && sym.value_of("Y2") ? sym.value_of("X1") : std::nullopt);
    const bool rec = session_.recorder().recording();
    if (rec && !was_recording_) rec_seen_ = 0;
    was_recording_ = rec;
    ui_.recording = rec;
    if (rec) {
        my_sampler_ = false;
        const auto& s = session_.recorder().samples();
        for (; rec_seen_ < s.size(); ++rec_seen_) path_.observe(s[rec_seen_], session_);
    } else if (!my_sampler_) {
        session_.sample_tool(kSamplePeriod, [this](const debug::ToolSample& t) { path_.observe(t, session_); });
        my_sampler_ = true;
    }
}

int App::start() {
    if (!o_.rom.empty()) {  // the board's ROM, before a script or the boot below (which ends in RESET)
        if (const auto r = session_.load_rom(absolute(o_.rom)); r.status != script::Session::Status::Ok) {
            std::cerr << "alp85 gui: --rom: " << r.message << '\n';
            return 2;
        }
    }
    if (!o_.signals.empty()) {
        if (const auto r = open_signals(signals_, session_, o_.signals, o_.signals_ms); r.status != script::Session::Status::Ok) {
            std::cerr << "alp85 gui: --signals: " << r.message << '\n';
            return 2;
        }
    }
    if (!o_.script.empty()) {
        std::vector<script::ParseError> errors;
        script::RunnerOptions ro;
        ro.monitor_rom = session_options(o_).monitor_rom;
        ro.board = session_options(o_).board;
        ro.out_dir = o_.out_dir;
        ro.err = &std::cerr;
        ro.outputs = {{o_.screenshot, "--screenshot"}};  // no save, record or plot of the script may write it
        std::vector<NamedPath> read;
        if (!script::prepare(o_.script, script_, errors, ro, &read)) {
            for (const auto& e : errors) std::cerr << e.format();
            std::cerr << fmt::format("alp85 gui: {} error(s) in {}; nothing was run\n", errors.size(), o_.script);
            return 2;
        }
        // The screenshot on a file the script includes, loads or restores (the script itself and
        // the firmware were refused before the window opened).
        if (const std::string clash = output_clash(read, ro.outputs); !clash.empty()) {
            std::cerr << "alp85 gui: error: " << clash << "; nothing written\n";
            return 2;
        }
        session_.add_input(o_.script, "the script");
        for (const NamedPath& o : ro.outputs) session_.add_output(o.path, o.role);
        std::vector<script::ParseError> more;
        session_.check(script_, more);  // this session keeps the assembled sources
        script_active_ = true;
        // At the speed chosen (--speed, real time by default) the script's runs are drawn as they go.
        session_.set_pace([this](std::uint64_t) { pace_script(); }, kPaceSlice);
        pacer_.rebase(session_.now(), HostClock::now());
        ui_.add_log("script " + std::filesystem::path(o_.script).filename().string());  // no folder of the user's in the picture
        after_commands();
        return 0;
    }
    script::Session::Boot boot;
    // The built-in monitor and the thesis firmware are the ALP 85's; another board boots what it is given.
    const bool builtin = session_.board().builtin_firmware;
    boot.monitor = builtin;
    for (const auto& f : o_.firmware.empty() && builtin ? std::vector<std::string>{"thesis-fixed"} : o_.firmware) {
        if (firmware::find(f)) boot.firmware.push_back(f);
        else boot.images.push_back({absolute(f), std::nullopt});
    }
    if (!done(session_.boot(boot))) {
        std::cerr << "alp85 gui: could not load the firmware:\n";
        for (const auto& l : ui_.log) std::cerr << "  " << l << '\n';
        return 2;
    }
    if (!o_.debug) begin_run(false);
    return 0;
}

void App::update_fit() {
    int ww = 0, wh = 0;
    SDL_GetWindowSize(window_, &ww, &wh);
    SDL_GL_GetDrawableSize(window_, &drawable_.w, &drawable_.h);
    dpi_ = ww > 0 ? static_cast<float>(drawable_.w) / static_cast<float>(ww) : 1.0f;
    fit_ = fit_to(drawable_.w, drawable_.h);
    // ImGui lays out and is hit-tested in the logical picture; the canvas scales it to the window.
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = {static_cast<float>(kWindowWidth), static_cast<float>(kWindowHeight)};
    io.DisplayFramebufferScale = {1, 1};
    if (io.MousePos.x > -1e30f && io.MousePos.y > -1e30f) {
        const Vec2 p = window_to_logical(io.MousePos.x, io.MousePos.y);
        io.MousePos = {p.x, p.y};
    }
}

// The table view's mouse: the wheel zooms about the pointer, a right or middle drag pans, a
// double click frames the toolpath; Home frames it too, End returns to the automatic fit.
// Returns true when the event was the view's.
bool App::table_input(const SDL_Event& e, const ImGuiIO& io) {
    const ToolView tool = tool_view(session_);
    const TableView fitted = table_view(tool, path_, session_);
    auto frame_path = [&] {
        Bounds b = Bounds::none();
        for (const PointMm& p : path_.points()) b.add(p.x, p.y);
        if (b.empty()) b.add(tool[Axis::X].mm, tool[Axis::Y].mm);
        b.x0 -= 1, b.y0 -= 1, b.x1 += 1, b.y1 += 1;  // a millimetre around it
        camera_.frame(b);
    };
    switch (e.type) {
        case SDL_MOUSEWHEEL: {
            if (io.WantCaptureMouse) return false;
            const ImVec2 m = io.MousePos;
            if (!kTableRect.contains(m.x, m.y) || e.wheel.y == 0) return false;
            camera_.zoom_at(fitted, m.x, m.y, std::pow(1.25, e.wheel.y));
            return true;
        }
        case SDL_MOUSEBUTTONDOWN:
            if (!kTableRect.contains(static_cast<float>(e.button.x), static_cast<float>(e.button.y))) return false;
            if (e.button.button == SDL_BUTTON_RIGHT || e.button.button == SDL_BUTTON_MIDDLE) {
                panning_ = true, pan_x_ = static_cast<float>(e.button.x), pan_y_ = static_cast<float>(e.button.y);
                return true;
            }
            if (e.button.button == SDL_BUTTON_LEFT && e.button.clicks == 2) {
                frame_path();
                return true;
            }
            return false;
        case SDL_MOUSEBUTTONUP:
            if (panning_ && (e.button.button == SDL_BUTTON_RIGHT || e.button.button == SDL_BUTTON_MIDDLE)) {
                panning_ = false;
                return true;
            }
            return false;
        case SDL_MOUSEMOTION:
            if (!panning_) return false;
            camera_.pan(fitted, static_cast<float>(e.motion.x) - pan_x_, static_cast<float>(e.motion.y) - pan_y_);
            pan_x_ = static_cast<float>(e.motion.x), pan_y_ = static_cast<float>(e.motion.y);
            return true;
        case SDL_KEYDOWN:
            if (io.WantTextInput) return false;
            if (e.key.keysym.sym == SDLK_HOME) return frame_path(), true;
            if (e.key.keysym.sym == SDLK_END) return camera_.reset(), true;
            return false;
        default: return false;
    }
}

void App::handle(const SDL_Event& event) {
    ImGui_ImplSDL2_ProcessEvent(&event);
    last_input_ = HostClock::now();
    const ImGuiIO& io = ImGui::GetIO();
    // The views hit-test in the layout's (logical) coordinates.
    SDL_Event e = event;
    if (e.type == SDL_MOUSEBUTTONDOWN || e.type == SDL_MOUSEBUTTONUP) {
        const Vec2 p = window_to_logical(static_cast<float>(e.button.x), static_cast<float>(e.button.y));
        e.button.x = static_cast<int>(std::floor(p.x)), e.button.y = static_cast<int>(std::floor(p.y));
    } else if (e.type == SDL_MOUSEMOTION) {
        const Vec2 p = window_to_logical(static_cast<float>(e.motion.x), static_cast<float>(e.motion.y));
        e.motion.x = static_cast<int>(std::floor(p.x)), e.motion.y = static_cast<int>(std::floor(p.y));
    }
    // The Signals pane lies over the table view (and the source pane): clicks and the wheel there are its own.
    if (signals_.open && (e.type == SDL_MOUSEBUTTONDOWN || e.type == SDL_MOUSEBUTTONUP || e.type == SDL_MOUSEWHEEL)) {
        const float x = e.type == SDL_MOUSEWHEEL ? io.MousePos.x : static_cast<float>(e.button.x);
        const float y = e.type == SDL_MOUSEWHEEL ? io.MousePos.y : static_cast<float>(e.button.y);
        if (kSignalsRect.contains(x, y)) return;
    }
    if (!o_.debug && has_tool(session_) && table_input(e, io)) return;
    switch (e.type) {
        case SDL_QUIT: quit_ = true; break;
        case SDL_WINDOWEVENT:
            if (e.window.event == SDL_WINDOWEVENT_CLOSE) quit_ = true;
            if (e.window.event == SDL_WINDOWEVENT_EXPOSED || e.window.event == SDL_WINDOWEVENT_SIZE_CHANGED)
                expose_ = true, canvas_.expose();
            break;
        case SDL_MOUSEBUTTONDOWN:
            if (o_.debug && e.button.button == SDL_BUTTON_LEFT) {
                if (const auto row = source_row_at(static_cast<float>(e.button.x), static_cast<float>(e.button.y))) {
                    toggle_breakpoint(panes_, shell_, *row);
                    break;
                }
            }
            if (e.button.button == SDL_BUTTON_LEFT) {
                mouse_key_ = key_at(static_cast<float>(e.button.x), static_cast<float>(e.button.y), session_);
                if (mouse_key_) presser_.down(*mouse_key_, session_);
            }
            break;
        case SDL_MOUSEBUTTONUP:
            if (e.button.button == SDL_BUTTON_LEFT && mouse_key_) {
                presser_.up(*mouse_key_, session_);
                mouse_key_.reset();
            }
            break;
        case SDL_KEYDOWN:
        case SDL_KEYUP:
            if (io.WantTextInput || e.key.repeat) break;
            if (e.type == SDL_KEYDOWN && is_key_map_key(e.key.keysym)) {
                key_map_ = !key_map_;
                break;
            }
            if (const auto k = pad_key_for(e.key.keysym.sym, session_)) {
                if (e.type == SDL_KEYDOWN) presser_.down(*k, session_);
                else presser_.up(*k, session_);
            }
            break;
        default: break;
    }
}

void App::step_script(HostClock::time_point until) {
    do {
        if (g_terminate) return;
        if (script_pos_ >= script_.size()) {
            const auto r = session_.finish();
            if (r.status != script::Session::Status::Ok) {
                std::cout << "FAIL " << o_.script << '\n' << r.message << '\n';
                status_ = 1;
            } else if (status_ == 0) {
                std::cout << fmt::format("PASS {} ({} commands, {} simulated)\n", o_.script, script_.size(),
                                         script::Session::format_time(session_.now()));
            }
            script_active_ = false;
            session_.set_pace({}, 0);
            pacer_.rebase(session_.now(), HostClock::now());
            after_commands();
            if (!o_.debug) begin_run(false);
            return;
        }
        const auto r = session_.execute(script_[script_pos_++]);
        after_commands();
        if (r.status != script::Session::Status::Ok) {
            std::cout << "FAIL " << o_.script << '\n' << r.message << '\n';
            ui_.add_log(r.message);
            status_ = 1;
            script_pos_ = script_.size();
        }
    } while (HostClock::now() < until);
}

void App::begin_run(bool stop_at_halt) {
    debug::Debugger& d = session_.debugger();
    // No limit of machine time; only the debugger's Continue ends at a HLT (a board left running
    // by Run still answers RESET and the keys).
    if (const auto s = d.begin_continue(~std::uint64_t{0}, stop_at_halt)) {
        report(*s);
        return;
    }
    ui_.running = true;
    pacer_.rebase(session_.now(), HostClock::now());
    pause_asked_.reset();
}

void App::pause_run() {
    debug::Debugger& d = session_.debugger();
    if (!d.running()) return;
    report(d.pause());
}

void App::report(const debug::Stop& s) {
    ui_.running = false;
    if (std::exchange(panes_.pinned, false)) panes_.last_pc = 0xFFFF;  // a stop: the source pane shows the PC's line again
    if (pause_asked_) {
        const double ms = std::chrono::duration<double, std::milli>(HostClock::now() - *pause_asked_).count();
        pause_asked_.reset();
        if (o_.debug) std::cout << fmt::format("[gui] paused {:.1f} ms after the request\n", ms) << std::flush;
    }
    if (s.reason == debug::StopReason::Paused) {
        ui_.add_log(fmt::format("paused at {:04X}H", s.pc));
        if (o_.debug) panes_.add_log(fmt::format("paused at {:04X}H", s.pc));
        return;
    }
    ui_.add_log(fmt::format("stopped: {} at {:04X}H", debug::name(s.reason), s.pc));
    if (o_.debug) {
        const std::string text = shell_.console().describe(s);
        panes_.add_log(text);
        std::cout << "[gui] " << text << '\n' << std::flush;
    }
    panes_.last_t = ~0ull;
}

void App::run_machine(HostClock::time_point until) {
    debug::Debugger& d = session_.debugger();
    if (!d.running()) {
        ui_.running = false;
        return;
    }
    const std::uint64_t now = session_.now();
    std::uint64_t goal = pacer_.target(now, HostClock::now());
    if (const auto hold = script_active_ || !hook_ ? std::nullopt : hook_->hold()) goal = std::min(goal, std::max(*hold, now));
    const double left = std::chrono::duration<double>(until - HostClock::now()).count();
    if (goal > now && left > 0) {
        debug::Budget b;
        b.tstates = goal - now;
        b.seconds = left;
        if (const auto s = d.resume(b)) report(*s);
    }
    after_commands();
}

void App::debug_request(DebugPanes::Request r) {
    using R = DebugPanes::Request;
    debug::Debugger& d = session_.debugger();
    const auto forward = [&](std::optional<debug::Stop> s) {
        if (s) {
            report(*s);
        } else {
            ui_.running = true;
            pacer_.rebase(session_.now(), HostClock::now());
        }
    };
    switch (r) {
        case R::None: return;
        case R::Continue: begin_run(true); return;
        case R::Pause: pause_run(); return;
        case R::Step: forward(d.begin_step()); return;
        case R::Next: forward(d.begin_next()); return;
        case R::Finish: forward(d.begin_finish()); return;
        case R::ReverseContinue:
        case R::ReverseStep:
        case R::ReverseNext:
        case R::ReverseFinish:
            reverse_pending_ = r;
            ui_.running = true;  // the next frame shows Pause
            return;
    }
}

void App::run_reverse(DebugPanes::Request r) {
    using R = DebugPanes::Request;
    debug::Debugger& d = session_.debugger();
    d.interrupt_clear();
    if (o_.debug) std::cout << "[gui] reverse run under way\n" << std::flush;
    switch (r) {
        case R::ReverseStep: report(d.reverse_step()); return;
        case R::ReverseNext: report(d.reverse_next()); return;
        case R::ReverseFinish: report(d.reverse_finish()); return;
        default: report(d.reverse_continue()); return;
    }
}

void App::plot_drawn(const std::string& file) {
    if (path_.points().size() < 2) {
        ui_.add_log("nothing drawn to plot yet: the table has not moved (Record CSV records a run)");
        return;
    }
    plot::Series drawn{"table (X, Y)", {}};
    for (const PointMm& p : path_.points()) drawn.points.push_back({p.x, p.y});
    std::optional<std::pair<plot::Point, plot::Point>> line;
    if (const auto l = path_.ideal(session_)) line = std::make_pair(plot::Point{l->from.x, l->from.y}, plot::Point{l->to.x, l->to.y});
    try {
        plot::write_toolpath(file, "Toolpath", {drawn}, line);
        ui_.add_log("plotted " + file);
    } catch (const plot::PlotError& x) {
        ui_.add_log(x.what());
    }
}

void App::poll_during_reverse() {
    SDL_PumpEvents();
    SDL_Event e;
    if (SDL_PeepEvents(&e, 1, SDL_PEEKEVENT, SDL_QUIT, SDL_QUIT) > 0) session_.debugger().interrupt();
    std::array<SDL_Event, 32> events;
    const int n = SDL_PeepEvents(events.data(), static_cast<int>(events.size()), SDL_PEEKEVENT, SDL_WINDOWEVENT,
                                 SDL_MOUSEBUTTONUP);
    bool pause = false;
    for (int i = 0; i < n; ++i) {
        const SDL_Event& x = events[static_cast<std::size_t>(i)];
        if (x.type == SDL_WINDOWEVENT && x.window.event == SDL_WINDOWEVENT_CLOSE) session_.debugger().interrupt();
        if (x.type != SDL_MOUSEBUTTONDOWN || x.button.button != SDL_BUTTON_LEFT) continue;
        const Vec2 p = window_to_logical(static_cast<float>(x.button.x), static_cast<float>(x.button.y));
        for (const char* name : {"debug.continue", "controls.run"}) {
            const auto it = drawn_buttons().find(name);
            if (it != drawn_buttons().end() && p.x >= it->second.x0 && p.x < it->second.x1 && p.y >= it->second.y0 &&
                p.y < it->second.y1)
                pause = true;
        }
    }
    if (!pause) return;
    pause_asked_ = HostClock::now();
    session_.debugger().interrupt();
    // The click was Pause's: it must not press Continue once the window reads events again.
    SDL_FlushEvents(SDL_MOUSEBUTTONDOWN, SDL_MOUSEBUTTONUP);
}

void App::act(const Action& a) {
    using K = Action::Kind;
    const auto host = HostClock::now();
    switch (a.kind) {
        case K::RunPause:
            if (session_.debugger().running()) pause_run();
            else begin_run(false);
            break;
        case K::Reset: done(session_.reset()); break;
        case K::Speed:
            ui_.speed = a.speed;
            pacer_.set_speed(kSpeeds[static_cast<std::size_t>(a.speed)].factor, session_.now(), host);
            break;
        case K::Firmware:
            if (done(session_.load_firmware(a.arg)) && done(session_.reset())) {
                ui_.add_log("loaded " + a.arg);
                path_.clear();
            }
            break;
        case K::LoadFile:
            if (done(session_.load_image(absolute(a.arg)))) ui_.add_log("loaded " + absolute(a.arg));
            break;
        case K::SaveSnapshot:
            if (done(session_.save(absolute(a.arg)))) ui_.add_log("saved " + absolute(a.arg));
            break;
        case K::LoadSnapshot:
            if (done(session_.restore(absolute(a.arg)))) {  // a refused snapshot leaves the drawing as it was
                ui_.add_log("restored " + absolute(a.arg));
                path_.restored();
                pacer_.rebase(session_.now(), host);
            }
            break;
        case K::Screenshot: pending_shot_ = absolute(a.arg); break;
        case K::RecordStart: done(session_.record(absolute(a.arg), board::tstates_from_ms(1))); break;
        case K::RecordStop:
            if (done(session_.record_stop())) ui_.add_log("wrote " + absolute(a.arg));
            break;
        case K::NewWorkpiece:
            if (done(session_.new_workpiece())) {
                ui_.add_log("new workpiece: the tables and transducers are back at their start positions");
                path_.clear();  // the last job's path and its workpiece are no longer on the table
                camera_.reset();
            }
            break;
        case K::Signals:
            if (signals_.open) close_signals(signals_, session_);
            else show_signals(signals_, session_);
            break;
        case K::Plot:
            // Without a recording, what the table view draws: the toolpath since the last boot,
            // reset or restore, and the thesis's ideal line.
            if (session_.recorder().samples().size() < 2) plot_drawn(absolute(a.arg));
            else if (done(session_.plot_toolpath(absolute(a.arg)))) ui_.add_log("plotted " + absolute(a.arg));
            break;
    }
}

// A borderless, transparent window over `r` that takes no input (the keypad's clicks are
// hit-tested on the SDL events): one draw list per view. Layers are stacked in the order they are
// first made (not NoBringToFrontOnFocus: ImGui puts such a new window behind all the others).
ImDrawList* begin_layer(const char* name, const Rect& r) {
    ImGui::SetNextWindowPos({r.x, r.y});
    ImGui::SetNextWindowSize({r.w, r.h});
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, {0, 0});
    ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0);
    ImGui::Begin(name, nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoBackground | ImGuiWindowFlags_NoInputs |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
    ImGui::PopStyleVar(2);
    return ImGui::GetWindowDrawList();
}

void App::draw() {
    backdrop_.reset();
    backdrop_.fill(kControlsRect, colour::kPanel);
    if (has_tool(session_)) backdrop_.fill(kAxesRect, colour::kPanel);
    // Each view in its own window, so that the canvas sees which one changed.
    draw_keypad(begin_layer("##keypad", kBoardRect), presser_, session_);
    ImGui::End();
    const DisplayView display = display_view(session_);
    const unsigned digits = display_digits(session_);
    draw_display(begin_layer("##display", display_rect(digits)), backdrop_, display.segments, digits);
    ImGui::End();
    const ToolView tool = tool_view(session_);
    {
        ImDrawList* dl = begin_layer("##hint", kHintRect);
        if (const auto hint = feed_prompt_hint(display.text, tool.model == MotorModel::Physical))
            dl->AddText({kHintRect.x, kHintRect.y + 2}, IM_COL32(235, 235, 235, 255), hint->data(), hint->data() + hint->size());
        ImGui::End();
    }
    if (periph::SerialTerminal* t = session_.serial())
        if (const std::string typed = draw_terminal_pane(*t, terminal_); !typed.empty()) session_.serial_type(typed);
    if (o_.debug) {
        draw_debug_panes(panes_, shell_, ui_.running || in_command_);
        if (panes_.request != DebugPanes::Request::None && !in_command_) debug_request(std::exchange(panes_.request, DebugPanes::Request::None));
        draw_controls();
        return;
    }
    if (!has_tool(session_)) {  // a board without the machine tool: no table, gauge or axes
        draw_controls();
        return;
    }
    const TableView view = camera_.apply(table_view(tool, path_, session_));
    draw_table(begin_layer("##table", kTableRect), backdrop_, path_, session_, view);
    ImGui::End();
    draw_toolpath(begin_layer("##toolpath", kTableRect), tool, path_, session_, view);
    ImGui::End();
    draw_z_gauge(begin_layer("##z", {kZGaugeRect.x - 8, kTableRect.y, kWindowWidth - kZGaugeRect.x + 8, kTableRect.h}), backdrop_,
                 tool);
    ImGui::End();
    draw_travel_strip(begin_layer("##strip", kStripRect), backdrop_, tool);
    ImGui::End();
    if (frames_ % 4 == 0) axes_ = tool;
    if (const auto model = axes_panel(axes_, tool.model); model && !in_command_) done(session_.set_motor(*model));
    draw_controls();
}

// The status line, the Signals pane and the Controls panel, in either layout.
void App::draw_controls() {
    // Four times a second: a clock that changes every frame would redraw its panel every frame.
    if (frames_ % 15 == 0)
        ui_.status = fmt::format("{}  t = {}  {:.0f} fps", script_active_ ? "script" : ui_.running ? "running" : "paused",
                                 script::Session::format_time(session_.now()), fps_);
    draw_signals_pane(signals_, session_);
    ui_.signals = signals_.open;
    for (const Action& a : controls_panel(ui_))
        if (!in_command_) act(a);  // a script's command is under way: the buttons wait for its end
}

// One frame's picture: ImGui's frame, the views, the canvas; sent to the window when it changed.
bool App::render_frame() {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplSDL2_NewFrame();
    update_fit();
    ImGui::NewFrame();
    draw();
    if (key_map_) draw_key_map(o_.debug, session_);
    ImGui::Render();
    const bool painted = canvas_.render(ImGui::GetDrawData(), backdrop_, colour::kBackground);
    ++frames_;
    return painted;
}

void App::present(bool painted) {
    if (painted || expose_) {  // the window is only sent a picture that changed
        canvas_.present(drawable_.w, drawable_.h, fit_, expose_);
        SDL_GL_SwapWindow(window_);
        ++presented_;
        expose_ = false;
    }
}

// Called between the slices of a script's command that runs the machine (Session::set_pace):
// while the machine is ahead of the pacer's clock, frames are drawn (the views follow the table)
// and the host waits, so that a script runs at the speed chosen. Only closing the window is heard
// meanwhile; the buttons wait for the command's end.
void App::pace_script() {
    while (!quit_ && !pacer_.max_speed() && session_.now() > pacer_.target(session_.now(), HostClock::now())) {
        SDL_Event e;
        while (SDL_PollEvent(&e)) {
            ImGui_ImplSDL2_ProcessEvent(&e);
            if (e.type == SDL_QUIT || (e.type == SDL_WINDOWEVENT && e.window.event == SDL_WINDOWEVENT_CLOSE)) quit_ = true;
            if (e.type == SDL_WINDOWEVENT && (e.window.event == SDL_WINDOWEVENT_EXPOSED || e.window.event == SDL_WINDOWEVENT_SIZE_CHANGED))
                expose_ = true, canvas_.expose();
        }
        in_command_ = true;
        present(render_frame());
        in_command_ = false;
        wait_frame();
    }
}

void App::wait_frame() {
    const auto now = HostClock::now();
    const bool calm = now - last_input_ > kCalm && !hook_busy();
    if (!calm) {
        std::this_thread::sleep_until(clock_.next(now));
        return;
    }
    const auto deadline = clock_.next(now, 2);
    const auto wait = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - now).count();
    if (wait > 0 && SDL_WaitEventTimeout(nullptr, static_cast<int>(wait)) == 1) {
        last_input_ = HostClock::now();
        std::this_thread::sleep_until(clock_.resume(last_input_));
        return;
    }
    std::this_thread::sleep_until(deadline);
}

int App::loop() {
    const auto start = HostClock::now();
    const double cpu0 = cpu_seconds();
    clock_ = FrameClock(start);
    auto fps_t = start;
    long fps_frames = 0;
    while (!quit_ && !g_terminate) {
        const auto frame_start = HostClock::now();
        SDL_Event e;
        while (SDL_PollEvent(&e)) handle(e);
        const auto budget = frame_start + kMachineBudget;
        if (reverse_pending_) run_reverse(*std::exchange(reverse_pending_, std::nullopt));
        else if (script_active_) step_script(budget);
        else if (ui_.running) run_machine(budget);
        const auto machine_end = HostClock::now();
        machine_s_ += std::chrono::duration<double>(machine_end - frame_start).count();
        const bool done = !script_active_ && !hook_busy();
        if (!script_active_ && hook_) hook_->frame(*this);
        if (done) ++idle_frames_;

        const bool painted = render_frame();
        const bool end = (o_.frames && frames_ >= *o_.frames) ||
                         (o_.seconds && std::chrono::duration<double>(HostClock::now() - start).count() >= *o_.seconds) ||
                         (!o_.screenshot.empty() && !o_.frames && !o_.seconds && idle_frames_ > kSettleFrames);
        if (end && !o_.screenshot.empty()) pending_shot_ = o_.screenshot;
        if (!pending_shot_.empty()) {
            try {
                if (drawable_.w == kWindowWidth && drawable_.h == kWindowHeight) {
                    canvas_.bind_for_read();
                    save_screenshot(pending_shot_, kWindowWidth, kWindowHeight);
                    canvas_.unbind();
                } else {  // a scaled window: the picture as the window shows it, copied there as
                          // every frame is (only where it changed), so the pixels check that copy too
                    canvas_.present(drawable_.w, drawable_.h, fit_, expose_);
                    canvas_.bind_window_for_read();
                    save_screenshot(pending_shot_, drawable_.w, drawable_.h);
                }
                ui_.add_log("screenshot " + pending_shot_);
            } catch (const std::exception& x) {
                std::cerr << "alp85 gui: " << x.what() << '\n';
                status_ = 1;  // a file that cannot be written (README: exit statuses)
            }
            pending_shot_.clear();
        }
        present(painted);
        render_s_ += std::chrono::duration<double>(HostClock::now() - machine_end).count();
        if (end) break;
        ++fps_frames;
        const auto now = HostClock::now();
        if (now - fps_t >= std::chrono::seconds(1)) {
            fps_ = static_cast<double>(fps_frames) / std::chrono::duration<double>(now - fps_t).count();
            fps_t = now, fps_frames = 0;
        }
        wait_frame();  // pace the frames: no spinning
    }
    const double wall = std::chrono::duration<double>(HostClock::now() - start).count();
    if (o_.stats) finish_stats(wall, cpu_seconds() - cpu0);
    if (!o_.expect_display.empty()) {
        const std::string got = trim_right(display_view(session_).text);
        if (got != trim_right(o_.expect_display)) {
            std::cout << fmt::format("FAIL display: expected \"{}\", found \"{}\"\n", o_.expect_display, got);
            if (status_ == 0) status_ = 1;
        } else {
            std::cout << fmt::format("display \"{}\" as expected\n", got);
        }
    }
    return status_;
}

void App::finish_stats(double wall, double cpu) const {
    const double sim = board::ms_from_tstates(session_.now()) / 1000;
    std::cout << fmt::format("stats: renderer {}\n", canvas_.renderer());
    std::cout << fmt::format("stats: {} frames in {:.2f} s = {:.1f} fps ({} of them changed the picture); CPU {:.2f} s = {:.1f}% of one core; "
                             "simulated {:.3f} s ({:.2f}x real time); speed {}; per frame {:.2f} ms emulating, {:.2f} ms drawing; "
                             "{:.0f} pixels painted per changed frame\n",
                             frames_, wall, static_cast<double>(frames_) / wall, presented_, cpu, 100 * cpu / wall, sim, sim / wall,
                             kSpeeds[static_cast<std::size_t>(ui_.speed)].label,
                             1000 * machine_s_ / static_cast<double>(frames_), 1000 * render_s_ / static_cast<double>(frames_),
                             static_cast<double>(canvas_.painted_pixels()) / static_cast<double>(std::max<long>(presented_, 1)));
}

}  // namespace

int run(const GuiOptions& o, FrameHook* hook) {
    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    const char* headless = "alp85 gui: no display to open a window on ($DISPLAY is not set). Without a display use "
                           "the headless commands: `alp85 run` (run a program, see the display) or `alp85 script` "
                           "(run a script, e.g. scripts/demo/thesis.alp).\n";
    if ((!display || !*display) && (!wayland || !*wayland)) {
        std::cerr << headless;
        return 2;
    }
    if (SDL_Init(SDL_INIT_VIDEO | SDL_INIT_TIMER) != 0) {
        std::cerr << "alp85 gui: cannot open the display: " << SDL_GetError() << '\n' << headless;
        return 2;
    }
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 0);
    SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
    // Resizable, scaled to the screen: at most 1:1 by default, so that it fits a 1366x768 laptop.
    SDL_Rect usable{0, 0, kWindowWidth, kWindowHeight};
    if (SDL_GetDisplayUsableBounds(0, &usable) != 0) usable = {0, 0, kWindowWidth + 40, kWindowHeight + 60};
    const Size size = initial_window_size(o.scale, usable.w, usable.h);
    if (o.scale > 0 && size.w < std::lround(kWindowWidth * o.scale))
        std::cerr << fmt::format("alp85 gui: --scale {:g} ({}x{}) does not fit the screen ({}x{} usable): the window opens at {}x{} "
                                 "(it can be resized)\n",
                                 o.scale, std::lround(kWindowWidth * o.scale), std::lround(kWindowHeight * o.scale), usable.w, usable.h,
                                 size.w, size.h);
    const board::Board* shown = script::Session::find_board(o.board);
    const std::string title = fmt::format("ALP85 - {}", (shown ? *shown : script::Session::default_board()).title);
    SDL_Window* window = SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_CENTERED,
                                          SDL_WINDOWPOS_CENTERED, size.w, size.h,
                                          SDL_WINDOW_OPENGL | SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI);
    if (window) SDL_SetWindowMinimumSize(window, kWindowWidth / 4, kWindowHeight / 4);
    SDL_GLContext gl = window ? SDL_GL_CreateContext(window) : nullptr;
    if (!gl) {
        std::cerr << "alp85 gui: cannot create an OpenGL 3 window: " << SDL_GetError() << '\n' << headless;
        if (window) SDL_DestroyWindow(window);
        SDL_Quit();
        return 2;
    }
    SDL_GL_MakeCurrent(window, gl);
    SDL_GL_SetSwapInterval(0);  // the frame clock paces (Xvfb has no vertical sync)
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;
    ImGui::StyleColorsDark();
    ImGui_ImplSDL2_InitForOpenGL(window, gl);
    ImGui_ImplOpenGL3_Init("#version 130");
    struct sigaction ask{}, old_term{}, old_int{};
    ask.sa_handler = on_terminate;
    sigemptyset(&ask.sa_mask);
    sigaction(SIGTERM, &ask, &old_term);
    sigaction(SIGINT, &ask, &old_int);
    int status = 0;
    {
        App app(o, window, hook);
        g_debugger.store(&app.debugger());
        if (!app.canvas_ok()) {
            std::cerr << "alp85 gui: OpenGL has no framebuffer objects\n";
            status = 2;
        }
        if (status == 0) status = app.start();
        if (status == 0) status = app.loop();
        g_debugger.store(nullptr);
    }
    sigaction(SIGTERM, &old_term, nullptr);
    sigaction(SIGINT, &old_int, nullptr);
    if (g_terminate) status = 128 + g_terminate;  // as a shell reports a process a signal ended
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplSDL2_Shutdown();
    ImGui::DestroyContext();
    SDL_GL_DeleteContext(gl);
    SDL_DestroyWindow(window);
    SDL_Quit();
    return status;
}

}  // namespace alp85::gui
