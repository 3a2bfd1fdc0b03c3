// What the window (App, emu/gui/app.cpp) offers a driver from outside: one call a frame, seeing
// the session's shell, the panes a driver reads or steers, and the window to send events to. The
// window's tests drive it so (emu/gui/test_hooks.h); the window itself has none of their code.
#pragma once

#include <cstdint>
#include <optional>

#include "emu/gui/layout.h"

struct SDL_Window;

namespace alp85::script {
class DebugShell;
}

namespace alp85::gui {

struct DebugPanes;
struct SignalsPane;
struct TerminalPane;

// The window as a hook sees it.
class HookWindow {
public:
    virtual script::DebugShell& shell() = 0;
    virtual DebugPanes& panes() = 0;
    virtual TerminalPane& terminal() = 0;
    virtual const SignalsPane& signals() const = 0;
    virtual const Toolpath& toolpath() const = 0;
    virtual SDL_Window* window() = 0;
    virtual Vec2 window_point(Vec2 logical) const = 0;  // a point of the picture in window coordinates
    virtual void pause_asked() = 0;                     // a click on Pause follows: the stop says how long it took
    virtual void fail(int status) = 0;                  // the window's exit status from now on
    virtual void quit() = 0;                            // close the window after this frame

protected:
    ~HookWindow() = default;
};

class FrameHook {
public:
    virtual ~FrameHook() = default;
    // Once a frame after the script (if any) is done: after the machine's slice, before drawing.
    virtual void frame(HookWindow& w) = 0;
    // Still acting: the window keeps 60 frames a second, and a --screenshot waits.
    virtual bool busy() const = 0;
    // A machine time the run must not pass this frame (an event timed in machine time).
    virtual std::optional<std::uint64_t> hold() const = 0;
};

}  // namespace alp85::gui
