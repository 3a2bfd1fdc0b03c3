// The controls panel (an ImGui window at kControlsRect): run/pause, reset, speed, firmware,
// snapshots, screenshot, toolpath recording and plot, and the log of the session's messages.
// It only reports what the user asked for; the app carries it out through the script Session.
#pragma once

#include <array>
#include <deque>
#include <map>
#include <string>
#include <vector>

namespace alp85::gui {

struct Speed {
    const char* label;
    double factor;  // 0: as fast as possible
};
inline constexpr std::array<Speed, 5> kSpeeds{{
    {"x0.1", 0.1}, {"real time (3.072 MHz)", 1}, {"x10", 10}, {"x100", 100}, {"as fast as possible", 0}}};

struct Action {
    enum class Kind { RunPause, Reset, Speed, Firmware, LoadFile, SaveSnapshot, LoadSnapshot, Screenshot, RecordStart, RecordStop, Plot, NewWorkpiece, Signals };
    Kind kind;
    std::string arg;  // firmware name or a path (as typed)
    int speed = 1;    // index into kSpeeds
};

struct ControlsState {
    bool running = true;
    int speed = 1;
    bool recording = false;
    bool signals = false;  // the Signals pane is open (the menu bar's Signals toggles it)
    int firmware = 0;  // index into the built-in list
    std::vector<std::string> firmware_names;  // empty: none for this board (no firmware choice shown)
    bool tool = true;  // the board has the machine tool (its menu is shown)
    std::string file = "program.asm", snapshot = "alp85.snap", screenshot = "alp85.png";
    std::string record = "toolpath.csv", plot = "toolpath.png";
    std::deque<std::string> log;
    std::string status;  // one line: time, speed, fps
    // A line that repeats the last but for its time (" at TIME", as "the Y table reached its high
    // end stop at ..." comes at every step of a runaway) replaces it with a count:
    // "... at 1.200 s (600 times, the last at 3.400 s)".
    void add_log(std::string line);

private:
    std::string repeated_;  // the last line as first logged, and how often it came
    int repeats_ = 0;
};

std::vector<Action> controls_panel(ControlsState& s);

// Where each named button was last drawn (window pixels): the test hooks click it there with
// synthesized mouse events, as a user's click arrives.
struct ButtonRect {
    float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};
std::map<std::string, ButtonRect, std::less<>>& drawn_buttons();
// ImGui::Button that remembers where it was drawn under `name`.
bool named_button(const char* name, const char* label, float width = 0);

}  // namespace alp85::gui
