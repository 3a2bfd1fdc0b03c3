// The window's test hooks (tests/gui), installed by `alp85 gui` only when --click, --click-line
// or --debug-command is given: keypad buttons, source rows and named buttons clicked with
// synthesized mouse events, text typed into the Terminal pane, and debugger command lines run as
// typed at the command pane, one step a frame once the script is done.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "emu/gui/frame_hook.h"

namespace alp85::gui {

struct TestHookOptions {
    std::vector<std::string> clicks;          // --click: these keypad buttons
    std::vector<std::string> click_lines;     // --click-line (--debug): then these FILE:LINE source rows
    std::vector<std::string> debug_commands;  // --debug-command: then these command lines or hooks
    bool empty() const { return clicks.empty() && click_lines.empty() && debug_commands.empty(); }
};

class TestHooks final : public FrameHook {
public:
    explicit TestHooks(TestHookOptions o) : o_(std::move(o)) {}
    void frame(HookWindow& w) override;
    bool busy() const override;
    std::optional<std::uint64_t> hold() const override;

private:
    void drive_clicks(HookWindow& w);
    void drive_debug_hooks(HookWindow& w);
    void command(HookWindow& w, const std::string& line);

    TestHookOptions o_;
    std::size_t click_pos_ = 0;
    std::uint64_t click_t_ = 0;  // machine time of the next click event
    bool click_down_ = false;
    std::size_t line_click_pos_ = 0, command_pos_ = 0;
    long wait_ = 0;                  // frames still to let pass ("frames:N")
    std::string serial_;             // "serial:TEXT": typed into the Terminal pane once it has the keyboard
    long serial_wait_ = 0;           // frames it waited for the keyboard
    std::optional<Vec2> button_up_;  // a hook's click, released next frame
};

}  // namespace alp85::gui
