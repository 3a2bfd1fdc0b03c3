// `alp85 gui`: the ALP 85 and its machine tool in a window (SDL2, OpenGL 3, Dear ImGui), driving
// one script Session (and so one Machine and its Debugger) - the same engine as `alp85 script`.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "emu/script/session.h"

namespace alp85::gui {

class FrameHook;

struct GuiOptions {
    std::vector<std::string> firmware;  // built-in names or .asm/.hex paths; default thesis-fixed
    std::string script;                 // run in the window first (as `alp85 script` would)
    std::string screenshot;             // then save the window here and quit
    std::string expect_display;         // at exit: the display must read this (else status 1)
    std::optional<long> frames;         // quit after this many frames
    std::optional<double> seconds;      // quit after this many host seconds
    bool stats = false;                 // print frames per second and CPU use at exit
    int speed = 1;                      // index into kSpeeds (controls.h)
    periph::MachineTool::MotorModel motor = periph::MachineTool::MotorModel::Physical;
    std::string board = "alp85";        // --board: the board to build (alp85, sdk85)
    std::string rom;                    // --rom: that board's ROM at 0000H (the user's file; sdk85)
    std::string out_dir;                // where the script's files go (as alp85 script --out-dir)
    bool debug = false;                 // the debugger's panes in place of the machine tool's views
    double scale = 0;                   // the window's first size: layout x scale; 0: fit the screen
    bool key_map = false;               // open with the key map shown (F1 or ? toggles it)
    // An embedder's or a test's own parts: called with the session before the script runs (it
    // attaches them, Session::attach); the front end shows them from their descriptions alone.
    std::function<void(script::Session&)> parts;
    std::string show_part;                    // --debug: the chip pane brings this part's tab forward
    // --serial: a terminal on SID/SOD and its Terminal pane (emu/gui/terminal_pane.h).
    std::optional<periph::UartFormat> serial;
    std::vector<std::string> signals;         // open the Signals pane on these pins (record signals' words)
    int signals_ms = 10;                      // over the last this many ms (1 to 1000)
};

// Opens the window and runs until it is closed or an exit condition of `o` is met; `hook`, if
// given, is called once a frame (emu/gui/frame_hook.h: the tests' hooks). Returns the exit status:
// 0, 1 (the script failed or the display was not as expected), 2 (no display, or the script has
// errors).
int run(const GuiOptions& o, FrameHook* hook = nullptr);

}  // namespace alp85::gui
