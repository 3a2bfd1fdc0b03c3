#include "emu/gui/test_hooks.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include <SDL.h>
#include <fmt/format.h>

#include "emu/front/views.h"
#include "emu/gui/controls.h"
#include "emu/gui/debug_panes.h"
#include "emu/gui/signals_pane.h"
#include "emu/gui/terminal_pane.h"
#include "emu/script/debug_shell.h"

namespace alp85::gui {
namespace {

constexpr std::uint64_t kClickGap = board::tstates_from_ms(100);

// A left-button event at a point of the logical picture, as a click on the window delivers it.
void push_button(HookWindow& w, Vec2 logical, bool down) {
    const Vec2 at = w.window_point(logical);
    SDL_Event e{};
    e.type = down ? SDL_MOUSEBUTTONDOWN : SDL_MOUSEBUTTONUP;
    e.button.windowID = SDL_GetWindowID(w.window());
    e.button.button = SDL_BUTTON_LEFT;
    e.button.state = down ? SDL_PRESSED : SDL_RELEASED;
    e.button.clicks = 1;
    e.button.x = static_cast<int>(at.x);
    e.button.y = static_cast<int>(at.y);
    SDL_PushEvent(&e);
}

// A click on a Dear ImGui button: ImGui (1.86) reads the pointer's place from SDL's mouse state,
// so the pointer goes there first.
void push_click(HookWindow& w, Vec2 logical, bool down) {
    const Vec2 at = w.window_point(logical);
    SDL_WarpMouseInWindow(w.window(), static_cast<int>(at.x), static_cast<int>(at.y));
    push_button(w, logical, down);
}

}  // namespace

bool TestHooks::busy() const {
    return click_pos_ < o_.clicks.size() || line_click_pos_ < o_.click_lines.size() ||
           command_pos_ < o_.debug_commands.size() || wait_ != 0 || button_up_;
}

std::optional<std::uint64_t> TestHooks::hold() const {
    if (click_pos_ < o_.clicks.size()) return click_t_;
    return std::nullopt;
}

void TestHooks::frame(HookWindow& w) {
    drive_clicks(w);
    if (click_pos_ >= o_.clicks.size()) drive_debug_hooks(w);
}

// --click: each button is pressed by a synthesized left-button-down event at its centre and
// released by a button-up event, as a real click arrives. They are timed in machine time (held
// kKeyHold, then kClickGap before the next), and the machine is not run past the next one
// (hold()), so that a slow host gives the same presses as a fast one.
void TestHooks::drive_clicks(HookWindow& w) {
    const std::uint64_t now = w.shell().session().now();
    if (click_pos_ >= o_.clicks.size() || now < click_t_) return;
    const auto k = find_pad_key(o_.clicks[click_pos_], w.shell().session());
    if (!k) {
        std::cerr << "alp85 gui: --click " << o_.clicks[click_pos_] << ": no such key\n";
        ++click_pos_;
        w.fail(2);
        return;
    }
    push_button(w, key_rect(*k).centre(), !click_down_);  // handled at the start of the next frame, before the machine runs
    click_t_ = now + (click_down_ ? kClickGap : kKeyHold);
    if (click_down_) ++click_pos_;
    click_down_ = !click_down_;
}

// --click-line and --debug-command, one a frame after the keypad clicks: a click on the source
// row of each FILE:LINE (a synthesized left-button press at the row's centre, hit-tested as a
// user's), then each command line, as typed at the command pane.
void TestHooks::drive_debug_hooks(HookWindow& w) {
    script::DebugShell& shell = w.shell();
    DebugPanes& panes = w.panes();
    if (line_click_pos_ < o_.click_lines.size()) {
        const std::string& spec = o_.click_lines[line_click_pos_++];
        const auto colon = spec.rfind(':');
        const auto loc = colon == std::string::npos ? debug::Debugger::Location{{}, {}, "expected FILE:LINE", 0}
                                                    : shell.debugger().locate_line(spec.substr(0, colon), std::atoi(spec.c_str() + colon + 1));
        if (!loc.error.empty()) {
            std::cerr << "alp85 gui: --click-line " << spec << ": " << loc.error << '\n';
            w.fail(2);
            return;
        }
        const SourceLine l{shell.debugger().program().line_of(loc.addresses.front())->file, std::atoi(spec.c_str() + colon + 1)};
        panes.show(l);
        panes.last_pc = cpu_view(shell.session()).pc;  // the pane stays on this line until the PC moves
        const Vec2 c = source_row(l.line - panes.first).centre();
        for (const bool down : {true, false}) push_button(w, c, down);
        return;
    }
    if (wait_ > 0) {
        --wait_;
        return;
    }
    if (!serial_.empty()) {  // typed as a keyboard types: text input events to the focused line
        TerminalPane& terminal = w.terminal();
        if (!terminal.focused) {
            // Asked again each frame: a focus change of the window (Xvfb has no window manager)
            // takes the keyboard from the line.
            if (++serial_wait_ > 600) {
                std::cerr << "alp85 gui: --debug-command serial: the Terminal pane's line never had the keyboard\n";
                w.fail(2);
                w.quit();
                serial_.clear();
                return;
            }
            terminal.focus = true;
            return;
        }
        for (std::size_t at = 0; at < serial_.size(); at += sizeof(SDL_TextInputEvent::text) - 1) {
            SDL_Event e{};
            e.type = SDL_TEXTINPUT;
            e.text.windowID = SDL_GetWindowID(w.window());
            const std::string piece = serial_.substr(at, sizeof(SDL_TextInputEvent::text) - 1);
            std::copy(piece.begin(), piece.end(), e.text.text);
            SDL_PushEvent(&e);
        }
        serial_.clear();
        return;
    }
    if (button_up_) {  // the second half of a click: released a frame after it was pressed
        push_click(w, *button_up_, false);
        button_up_.reset();
        return;
    }
    if (command_pos_ < o_.debug_commands.size()) command(w, o_.debug_commands[command_pos_++]);
}

// Hooks beside command lines: "click:NAME" clicks a named button (controls.run, debug.continue,
// debug.step, ...), "frames:N" lets N frames pass, "status" prints whether the board runs and its
// time, "toolpath" how many points the drawn path has and its ideal line, "clickrow:N" clicks
// source row N as shown, "source" prints the file and first line the pane shows, "where:NAME" a
// button's centre in screen coordinates, "clickat:X,Y" clicks a point of the picture, "signals"
// prints what the Signals pane's cursors read, "serial:TEXT" types into the Terminal pane and
// "terminal" prints its text.
void TestHooks::command(HookWindow& w, const std::string& line) {
    script::DebugShell& shell = w.shell();
    script::Session& session = shell.session();
    if (line.starts_with("click:")) {
        const auto it = drawn_buttons().find(line.substr(6));
        if (it == drawn_buttons().end()) {
            std::cerr << "alp85 gui: --debug-command " << line << ": no such button\n";
            w.fail(2);
            return;
        }
        const Vec2 c{(it->second.x0 + it->second.x1) / 2, (it->second.y0 + it->second.y1) / 2};
        if (session.debugger().running() && (it->first == "debug.continue" || it->first == "controls.run"))
            w.pause_asked();  // a click on Pause: the stop says how long it took
        push_click(w, c, true);
        button_up_ = c;
        return;
    }
    if (line.starts_with("frames:")) {
        wait_ = std::atol(line.c_str() + 7);
        return;
    }
    if (line.starts_with("serial:") || line == "terminal") {  // type into the Terminal pane; print its text
        if (!session.serial()) {
            std::cerr << "alp85 gui: --debug-command " << line << ": no serial terminal (--serial)\n";
            w.fail(2);
            return;
        }
        if (line == "terminal")
            std::cout << fmt::format("[gui] terminal: {}\n", terminal_text(*session.serial())) << std::flush;
        else {
            w.terminal().focus = true;
            serial_ = line.substr(7);
            serial_wait_ = 0;
        }
        return;
    }
    if (line.starts_with("clickrow:")) {  // a click on a source row as shown (no line looked up first)
        const Vec2 c = source_row(std::atoi(line.c_str() + 9)).centre();
        push_click(w, c, true);  // the pointer goes there too: ImGui sees the click where it lands
        button_up_ = c;
        return;
    }
    if (line == "source") {
        std::cout << fmt::format("[gui] source: {} from line {}\n", std::filesystem::path(w.panes().file).filename().string(),
                                 w.panes().first)
                  << std::flush;
        return;
    }
    if (line.starts_with("where:")) {  // a button's centre on the screen, for a test's real click
        const auto it = drawn_buttons().find(line.substr(6));
        if (it == drawn_buttons().end()) {
            std::cerr << "alp85 gui: --debug-command " << line << ": no such button\n";
            w.fail(2);
            return;
        }
        const Vec2 c = w.window_point({(it->second.x0 + it->second.x1) / 2, (it->second.y0 + it->second.y1) / 2});
        int wx = 0, wy = 0;
        SDL_GetWindowPosition(w.window(), &wx, &wy);
        std::cout << fmt::format("[gui] {} at {},{}\n", line.substr(6), wx + static_cast<int>(c.x), wy + static_cast<int>(c.y))
                  << std::flush;
        return;
    }
    if (line.starts_with("clickat:")) {  // a click at a point of the picture (logical pixels), as a user's
        float x = 0, y = 0;
        if (std::sscanf(line.c_str() + 8, "%f,%f", &x, &y) != 2) {
            std::cerr << "alp85 gui: --debug-command " << line << ": expected clickat:X,Y\n";
            w.fail(2);
            return;
        }
        push_click(w, {x, y}, true);
        button_up_ = Vec2{x, y};
        return;
    }
    if (line == "signals") {  // what the Signals pane's cursors read
        std::cout << "[gui] signals: " << cursor_readout(w.signals()) << '\n' << std::flush;
        return;
    }
    if (line == "toolpath") {
        const Toolpath& path = w.toolpath();
        const auto l = path.ideal(session);
        std::cout << fmt::format("[gui] toolpath: {} points, {}\n", path.points().size(),
                                 l ? fmt::format("ideal line from {:g},{:g} to {:g},{:g} mm", l->from.x, l->from.y, l->to.x, l->to.y)
                                   : std::string("no ideal line"))
                  << std::flush;
        return;
    }
    if (line == "status") {
        std::cout << fmt::format("[gui] status: {} t={}\n", session.debugger().running() ? "running" : "stopped", session.now())
                  << std::flush;
        return;
    }
    const Typed t = run_typed(w.panes(), shell, line, session.debugger().running());
    std::cout << "(alp85) " << line << '\n' << t.out << std::flush;
    if (shell.console().errors()) w.fail(1);
}

}  // namespace alp85::gui
