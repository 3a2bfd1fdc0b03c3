#include "emu/gui/app.h"

#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
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
#include "emu/gui/input.h"
#include "emu/gui/pacer.h"
#include "emu/gui/screenshot.h"
#include "emu/gui/tool_view.h"
#include "emu/gui/toolpath.h"
#include "emu/program/firmware.h"
#include "emu/script/parser.h"
#include "emu/script/runner.h"
#include "emu/script/debug_shell.h"
#include "emu/script/session.h"

namespace alp85::gui {
namespace {

constexpr auto kMachineBudget = std::chrono::milliseconds(10);  // of a 16.7 ms frame
constexpr std::uint64_t kSamplePeriod = board::tstates_from_ms(1);
constexpr int kSettleFrames = 30;
constexpr std::uint64_t kClickGap = board::tstates_from_ms(100);

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
    return s;
}

class App {
public:
    App(const GuiOptions& o, SDL_Window* w)
        : o_(o), window_(w), shell_(session_options(o)), session_(shell_.session()) {
        if (!o.out_dir.empty()) session_.set_out_dir(o.out_dir);
        machine().tool().set_model(o.motor);
        if (o.parts) o.parts(machine());
        panes_.shown_part = o.show_part;
        session_.debugger().listen([this](const debug::Event& e) { ui_.add_log(e.text); });
        for (const auto& e : firmware::builtin()) ui_.firmware_names.emplace_back(e.name);
        for (std::size_t i = 0; i < ui_.firmware_names.size(); ++i)
            if (ui_.firmware_names[i] == "thesis-fixed") ui_.firmware = static_cast<int>(i);
        ui_.speed = o.speed;
        pacer_.set_speed(kSpeeds[static_cast<std::size_t>(o.speed)].factor, machine().now(), HostClock::now());
        clicks_ = o.clicks;
        if (o.debug) {
            shell_.debugger().set_history(true);
            ui_.running = false;  // the debugger starts paused: Continue (or the prompt) runs it
        }
    }

    int start();
    int loop();
    bool canvas_ok() { return canvas_.init(kWindowWidth, kWindowHeight); }

private:
    Machine& machine() { return session_.machine(); }
    bool command(const std::string& text);
    void after_commands();
    void handle(const SDL_Event& e);
    void step_script(HostClock::time_point until);
    void run_machine(HostClock::time_point until);
    void act(const Action& a);
    void drive_clicks();
    void draw();
    void finish_stats(double wall, double cpu) const;
    std::string absolute(const std::string& p) const { return std::filesystem::absolute(p).string(); }

    const GuiOptions& o_;
    SDL_Window* window_;
    script::DebugShell shell_;
    script::Session& session_;
    DebugPanes panes_;
    std::size_t line_click_pos_ = 0, command_pos_ = 0;
    bool debug_hooks_done() const {
        return line_click_pos_ >= o_.click_lines.size() && command_pos_ >= o_.debug_commands.size();
    }
    void drive_debug_hooks();
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
    std::vector<std::string> clicks_;
    std::size_t click_pos_ = 0;
    std::uint64_t click_t_ = 0;  // machine time of the next click event
    bool click_down_ = false;
    long idle_frames_ = 0;  // frames since the script and the clicks were done
    long frames_ = 0;
    std::string pending_shot_;
    bool quit_ = false;
    double fps_ = 0;
    Canvas canvas_;
    AxesReadout axes_{};
    long presented_ = 0;  // frames that changed the picture
    bool expose_ = true;
    double machine_s_ = 0, render_s_ = 0;  // host time in the machine and in drawing (--stats)
};

bool App::command(const std::string& text) {
    std::vector<script::ParseError> errors;
    auto cmds = script::parse_script(text, "gui", errors);
    if (errors.empty()) session_.check(cmds, errors);
    for (const auto& e : errors) ui_.add_log("error: " + e.message);
    if (!errors.empty()) return false;
    bool ok = true;
    for (const auto& c : cmds) {
        const auto r = session_.execute(c);
        if (r.status != script::Session::Status::Ok) {
            ui_.add_log(r.message);
            ok = false;
            break;
        }
    }
    after_commands();
    return ok;
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
        for (; rec_seen_ < s.size(); ++rec_seen_) path_.observe(s[rec_seen_], machine());
    } else if (!my_sampler_) {
        Machine& m = machine();
        m.set_sampler(kSamplePeriod, [this, &m](std::uint64_t t) { path_.observe(debug::sample_tool(m.tool(), t), m); });
        my_sampler_ = true;
    }
}

int App::start() {
    if (!o_.script.empty()) {
        std::vector<script::ParseError> errors;
        script::RunnerOptions ro;
        ro.monitor_rom = session_options(o_).monitor_rom;
        ro.out_dir = o_.out_dir;
        ro.err = &std::cerr;
        if (!script::prepare(o_.script, script_, errors, ro)) {
            for (const auto& e : errors) std::cerr << e.format();
            std::cerr << fmt::format("alp85 gui: {} error(s) in {}; nothing was run\n", errors.size(), o_.script);
            return 2;
        }
        std::vector<script::ParseError> more;
        session_.check(script_, more);  // this session keeps the assembled sources
        script_active_ = true;
        ui_.add_log("script " + o_.script);
        after_commands();
        return 0;
    }
    std::string text = "monitor\n";
    const auto& fw = o_.firmware.empty() ? std::vector<std::string>{"thesis-fixed"} : o_.firmware;
    for (const auto& f : fw) text += (firmware::find(f) ? "firmware " + f : "load " + absolute(f)) + "\n";
    text += "reset\n";
    if (!command(text)) {
        std::cerr << "alp85 gui: could not load the firmware:\n";
        for (const auto& l : ui_.log) std::cerr << "  " << l << '\n';
        return 2;
    }
    return 0;
}

void App::handle(const SDL_Event& e) {
    ImGui_ImplSDL2_ProcessEvent(&e);
    const ImGuiIO& io = ImGui::GetIO();
    switch (e.type) {
        case SDL_QUIT: quit_ = true; break;
        case SDL_WINDOWEVENT:
            if (e.window.event == SDL_WINDOWEVENT_CLOSE) quit_ = true;
            if (e.window.event == SDL_WINDOWEVENT_EXPOSED) expose_ = true, canvas_.expose();
            break;
        case SDL_MOUSEBUTTONDOWN:
            if (o_.debug && e.button.button == SDL_BUTTON_LEFT) {
                if (const auto row = source_row_at(static_cast<float>(e.button.x), static_cast<float>(e.button.y))) {
                    toggle_breakpoint(panes_, shell_, *row);
                    break;
                }
            }
            if (e.button.button == SDL_BUTTON_LEFT) {
                mouse_key_ = key_at(static_cast<float>(e.button.x), static_cast<float>(e.button.y));
                if (mouse_key_) presser_.down(*mouse_key_, machine());
            }
            break;
        case SDL_MOUSEBUTTONUP:
            if (e.button.button == SDL_BUTTON_LEFT && mouse_key_) {
                presser_.up(*mouse_key_, machine());
                mouse_key_.reset();
            }
            break;
        case SDL_KEYDOWN:
        case SDL_KEYUP:
            if (io.WantTextInput || e.key.repeat) break;
            if (const auto k = pad_key_for(e.key.keysym.sym)) {
                if (e.type == SDL_KEYDOWN) presser_.down(*k, machine());
                else presser_.up(*k, machine());
            }
            break;
        default: break;
    }
}

void App::step_script(HostClock::time_point until) {
    do {
        if (script_pos_ >= script_.size()) {
            const auto r = session_.finish();
            if (r.status != script::Session::Status::Ok) {
                std::cout << "FAIL " << o_.script << '\n' << r.message << '\n';
                status_ = 1;
            } else if (status_ == 0) {
                std::cout << fmt::format("PASS {} ({} commands, {} simulated)\n", o_.script, script_.size(),
                                         script::Session::format_time(machine().now()));
            }
            script_active_ = false;
            pacer_.rebase(machine().now(), HostClock::now());
            after_commands();
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

void App::run_machine(HostClock::time_point until) {
    Machine& m = machine();
    std::uint64_t goal = pacer_.target(m.now(), HostClock::now());
    if (!script_active_ && click_pos_ < clicks_.size()) goal = std::min(goal, std::max(click_t_, m.now()));
    std::uint64_t slice = board::tstates_from_ms(5);
    while (m.now() < goal) {
        const auto t0 = HostClock::now();
        if (t0 >= until) break;
        const std::uint64_t to = goal - m.now() > slice ? m.now() + slice : goal;
        const debug::Stop s = session_.debugger().run_until(to);
        if (s.reason == debug::StopReason::Breakpoint || s.reason == debug::StopReason::Watchpoint) {
            ui_.running = false;
            ui_.add_log(fmt::format("stopped: {} at {:04X}H", debug::name(s.reason), m.cpu().regs().pc));
            if (o_.debug) panes_.add_log(shell_.console().describe(s));
            break;
        }
        // Slices of about 2 ms of host time, so the budget is kept.
        const double took = std::chrono::duration<double>(HostClock::now() - t0).count();
        if (took < 0.001 && slice < board::tstates_from_ms(1000)) slice *= 2;
        else if (took > 0.004 && slice > 3072) slice /= 2;
    }
    after_commands();
}

void App::act(const Action& a) {
    using K = Action::Kind;
    const auto host = HostClock::now();
    switch (a.kind) {
        case K::RunPause:
            ui_.running = !ui_.running;
            pacer_.rebase(machine().now(), host);
            break;
        case K::Reset: command("reset"); break;
        case K::Speed:
            ui_.speed = a.speed;
            pacer_.set_speed(kSpeeds[static_cast<std::size_t>(a.speed)].factor, machine().now(), host);
            break;
        case K::Firmware:
            if (command("firmware " + a.arg + "\nreset")) ui_.add_log("loaded " + a.arg);
            path_.clear();
            break;
        case K::LoadFile:
            if (command("load " + absolute(a.arg))) ui_.add_log("loaded " + absolute(a.arg));
            break;
        case K::SaveSnapshot:
            if (command("save " + absolute(a.arg))) ui_.add_log("saved " + absolute(a.arg));
            break;
        case K::LoadSnapshot:
            if (command("restore " + absolute(a.arg))) ui_.add_log("restored " + absolute(a.arg));
            path_.clear();
            pacer_.rebase(machine().now(), host);
            break;
        case K::Screenshot: pending_shot_ = absolute(a.arg); break;
        case K::RecordStart: command("record " + absolute(a.arg) + " every 1ms"); break;
        case K::RecordStop:
            if (command("record stop")) ui_.add_log("wrote " + absolute(a.arg));
            break;
        case K::Plot:
            if (command("plot toolpath " + absolute(a.arg))) ui_.add_log("plotted " + absolute(a.arg));
            break;
    }
}

// The --click test hook: each button is pressed by a synthesized left-button-down event at its
// centre and released by a button-up event, as a real click arrives. They are timed in machine
// time (held kKeyHold, then kClickGap before the next), and the machine is not run past the next
// one, so that a slow host gives the same presses as a fast one.
void App::drive_clicks() {
    if (click_pos_ >= clicks_.size() || machine().now() < click_t_) return;
    const auto k = find_pad_key(clicks_[click_pos_]);
    if (!k) {
        std::cerr << "alp85 gui: --click " << clicks_[click_pos_] << ": no such key\n";
        ++click_pos_;
        status_ = 2;
        return;
    }
    const Vec2 c = key_rect(*k).centre();
    SDL_Event e{};
    e.type = click_down_ ? SDL_MOUSEBUTTONUP : SDL_MOUSEBUTTONDOWN;
    e.button.windowID = SDL_GetWindowID(window_);
    e.button.button = SDL_BUTTON_LEFT;
    e.button.state = click_down_ ? SDL_RELEASED : SDL_PRESSED;
    e.button.clicks = 1;
    e.button.x = static_cast<int>(c.x);
    e.button.y = static_cast<int>(c.y);
    SDL_PushEvent(&e);  // handled at the start of the next frame, before the machine runs
    click_t_ = machine().now() + (click_down_ ? kClickGap : kKeyHold);
    if (click_down_) ++click_pos_;
    click_down_ = !click_down_;
}

// The --debug test hooks, one a frame after the script and the keypad clicks: a click on the source
// row of each FILE:LINE (a synthesized left-button press at the row's centre, hit-tested as a
// user's), then each command line, as typed at the command pane.
void App::drive_debug_hooks() {
    if (!o_.debug) return;
    if (line_click_pos_ < o_.click_lines.size()) {
        const std::string& spec = o_.click_lines[line_click_pos_++];
        const auto colon = spec.rfind(':');
        const auto loc = colon == std::string::npos ? debug::Debugger::Location{{}, {}, "expected FILE:LINE", 0}
                                                    : shell_.debugger().locate_line(spec.substr(0, colon), std::atoi(spec.c_str() + colon + 1));
        if (!loc.error.empty()) {
            std::cerr << "alp85 gui: --click-line " << spec << ": " << loc.error << '\n';
            status_ = 2;
            return;
        }
        const SourceLine l{shell_.debugger().program().line_of(loc.addresses.front())->file, std::atoi(spec.c_str() + colon + 1)};
        panes_.show(l);
        panes_.last_pc = machine().cpu().regs().pc;  // the pane stays on this line until the PC moves
        const Vec2 c = source_row(l.line - panes_.first).centre();
        for (const bool down : {true, false}) {
            SDL_Event e{};
            e.type = down ? SDL_MOUSEBUTTONDOWN : SDL_MOUSEBUTTONUP;
            e.button.windowID = SDL_GetWindowID(window_);
            e.button.button = SDL_BUTTON_LEFT;
            e.button.state = down ? SDL_PRESSED : SDL_RELEASED;
            e.button.clicks = 1;
            e.button.x = static_cast<int>(c.x);
            e.button.y = static_cast<int>(c.y);
            SDL_PushEvent(&e);
        }
        return;
    }
    if (command_pos_ < o_.debug_commands.size()) {
        const std::string& line = o_.debug_commands[command_pos_++];
        const std::string out = shell_.execute(line);
        panes_.add_log("(alp85) " + line);
        panes_.add_log(out);
        std::cout << "(alp85) " << line << '\n' << out << std::flush;
        panes_.last_t = ~0ull;
        if (shell_.console().errors()) status_ = 1;
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
    backdrop_.fill(kAxesRect, colour::kPanel);
    // Each view in its own window, so that the canvas sees which one changed.
    draw_keypad(begin_layer("##keypad", kBoardRect), presser_);
    ImGui::End();
    draw_display(begin_layer("##display", kDisplayRect), backdrop_, machine().display());
    ImGui::End();
    if (o_.debug) {
        draw_debug_panes(panes_, shell_, ui_.running);
        if (panes_.run_requested != ui_.running) {
            ui_.running = panes_.run_requested;
            pacer_.rebase(machine().now(), HostClock::now());
        }
        panes_.run_requested = ui_.running;
        if (frames_ % 15 == 0)
            ui_.status = fmt::format("{}  t = {}  {:.0f} fps", script_active_ ? "script" : ui_.running ? "running" : "paused",
                                     script::Session::format_time(machine().now()), fps_);
        for (const Action& a : controls_panel(ui_)) act(a);
        return;
    }
    const TableView view = table_view(machine(), path_);
    draw_table(begin_layer("##table", kTableRect), backdrop_, machine(), path_, view);
    ImGui::End();
    draw_toolpath(begin_layer("##toolpath", kTableRect), machine(), path_, view);
    ImGui::End();
    draw_z_gauge(begin_layer("##z", {kZGaugeRect.x - 8, kTableRect.y, kWindowWidth - kZGaugeRect.x + 8, kTableRect.h}), backdrop_,
                 machine());
    ImGui::End();
    draw_travel_strip(begin_layer("##strip", kStripRect), backdrop_, machine());
    ImGui::End();
    if (frames_ % 4 == 0) axes_ = read_axes(machine());
    if (const auto model = axes_panel(axes_, machine().tool().model())) command(*model == periph::MachineTool::MotorModel::Ideal ? "motor ideal" : "motor physical");
    // Four times a second: a clock that changes every frame would redraw its panel every frame.
    if (frames_ % 15 == 0)
        ui_.status = fmt::format("{}  t = {}  {:.0f} fps", script_active_ ? "script" : ui_.running ? "running" : "paused",
                             script::Session::format_time(machine().now()), fps_);
    for (const Action& a : controls_panel(ui_)) act(a);
}

int App::loop() {
    const auto start = HostClock::now();
    const double cpu0 = cpu_seconds();
    FrameClock clock(start);
    auto fps_t = start;
    long fps_frames = 0;
    while (!quit_) {
        const auto frame_start = HostClock::now();
        SDL_Event e;
        while (SDL_PollEvent(&e)) handle(e);
        const auto budget = frame_start + kMachineBudget;
        if (script_active_) step_script(budget);
        else if (ui_.running) run_machine(budget);
        const auto machine_end = HostClock::now();
        machine_s_ += std::chrono::duration<double>(machine_end - frame_start).count();
        const bool done = !script_active_ && click_pos_ >= clicks_.size() && debug_hooks_done();
        if (!script_active_) drive_clicks();
        if (!script_active_ && click_pos_ >= clicks_.size()) drive_debug_hooks();
        if (done) ++idle_frames_;

        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplSDL2_NewFrame();
        ImGui::NewFrame();
        draw();
        ImGui::Render();
        const bool painted = canvas_.render(ImGui::GetDrawData(), backdrop_, colour::kBackground);
        ++frames_;
        const bool end = (o_.frames && frames_ >= *o_.frames) ||
                         (o_.seconds && std::chrono::duration<double>(HostClock::now() - start).count() >= *o_.seconds) ||
                         (!o_.screenshot.empty() && !o_.frames && !o_.seconds && idle_frames_ > kSettleFrames);
        if (end && !o_.screenshot.empty()) pending_shot_ = o_.screenshot;
        if (!pending_shot_.empty()) {
            try {
                canvas_.bind_for_read();
                save_screenshot(pending_shot_, kWindowWidth, kWindowHeight);
                canvas_.unbind();
                ui_.add_log("screenshot " + pending_shot_);
            } catch (const std::exception& x) {
                std::cerr << "alp85 gui: " << x.what() << '\n';
                status_ = 2;
            }
            pending_shot_.clear();
        }
        if (painted || expose_) {  // the window is only sent a picture that changed
            canvas_.present();
            SDL_GL_SwapWindow(window_);
            ++presented_;
            expose_ = false;
        }
        render_s_ += std::chrono::duration<double>(HostClock::now() - machine_end).count();
        if (end) break;
        ++fps_frames;
        const auto now = HostClock::now();
        if (now - fps_t >= std::chrono::seconds(1)) {
            fps_ = static_cast<double>(fps_frames) / std::chrono::duration<double>(now - fps_t).count();
            fps_t = now, fps_frames = 0;
        }
        std::this_thread::sleep_until(clock.next(now));  // pace the frames: no spinning
    }
    const double wall = std::chrono::duration<double>(HostClock::now() - start).count();
    if (o_.stats) finish_stats(wall, cpu_seconds() - cpu0);
    if (!o_.expect_display.empty()) {
        const std::string got = trim_right(machine().display_text());
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
    const double sim = board::ms_from_tstates(session_.machine().now()) / 1000;
    std::cout << fmt::format("stats: {} frames in {:.2f} s = {:.1f} fps ({} of them changed the picture); CPU {:.2f} s = {:.1f}% of one core; "
                             "simulated {:.3f} s ({:.2f}x real time); speed {}; per frame {:.2f} ms emulating, {:.2f} ms drawing\n",
                             frames_, wall, static_cast<double>(frames_) / wall, presented_, cpu, 100 * cpu / wall, sim, sim / wall,
                             kSpeeds[static_cast<std::size_t>(ui_.speed)].label,
                             1000 * machine_s_ / static_cast<double>(frames_), 1000 * render_s_ / static_cast<double>(frames_));
}

}  // namespace

int run(const GuiOptions& o) {
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
    SDL_Window* window = SDL_CreateWindow("ALP85 - the ALP 85 and its machine tool", SDL_WINDOWPOS_CENTERED,
                                          SDL_WINDOWPOS_CENTERED, kWindowWidth, kWindowHeight, SDL_WINDOW_OPENGL);
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
    int status = 0;
    {
        App app(o, window);
        if (!app.canvas_ok()) {
            std::cerr << "alp85 gui: OpenGL has no framebuffer objects\n";
            status = 2;
        }
        if (status == 0) status = app.start();
        if (status == 0) status = app.loop();
    }
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplSDL2_Shutdown();
    ImGui::DestroyContext();
    SDL_GL_DeleteContext(gl);
    SDL_DestroyWindow(window);
    SDL_Quit();
    return status;
}

}  // namespace alp85::gui
