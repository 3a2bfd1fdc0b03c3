// The window's geometry, in pixels from the window's top left corner: where the board's digits and
// their segments are, where each keypad button is, where the table view, the Z gauge and the
// travel strip are, and how the table view maps millimetres to pixels. Plain arithmetic, no
// drawing: the views draw from it and the tests compute the pixels they check from it.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <utility>

#include "emu/front/keys.h"
#include "emu/front/toolpath.h"

namespace alp85::gui {

// The front ends' shared library (emu/front: keys, pacing, the toolpath, views) is the window's own.
using namespace front;

struct Vec2 {
    float x = 0, y = 0;
};

struct Rect {
    float x = 0, y = 0, w = 0, h = 0;
    bool contains(float px, float py) const { return px >= x && px < x + w && py >= y && py < y + h; }
    Vec2 centre() const { return {x + w / 2, y + h / 2}; }
};

// The common part of two rectangles (w or h 0 when there is none), and the smallest holding both.
Rect intersect(const Rect& a, const Rect& b);
Rect unite(const Rect& a, const Rect& b);

struct Rgb {
    std::uint8_t r, g, b;
};

// Colours the views draw with and the tests expect.
namespace colour {
inline constexpr Rgb kBackground{28, 30, 34};
inline constexpr Rgb kBoard{18, 64, 40};           // the PCB around the display and keys
inline constexpr Rgb kDisplayWindow{12, 6, 6};     // the display's dark red filter
inline constexpr Rgb kSegmentLit{255, 52, 36};
inline constexpr Rgb kSegmentUnlit{62, 20, 18};
inline constexpr Rgb kKey{214, 210, 200};
inline constexpr Rgb kKeyFunction{70, 90, 140};
inline constexpr Rgb kKeyPressed{250, 200, 60};
inline constexpr Rgb kTableBed{52, 56, 62};
inline constexpr Rgb kWorkpiece{120, 96, 64};
inline constexpr Rgb kWorkpieceFill{84, 74, 62};  // the workpiece seen on the bed
inline constexpr Rgb kZColumn{64, 130, 170};
inline constexpr Rgb kPanel{36, 38, 44};
inline constexpr Rgb kToolpath{80, 200, 255};
inline constexpr Rgb kIdealLine{120, 255, 120};
inline constexpr Rgb kTool{255, 0, 200};           // magenta: nothing else is drawn in it
inline constexpr Rgb kCurrentLine{90, 80, 20};     // the debugger's source pane: the PC's line
inline constexpr Rgb kBreakpoint{230, 40, 40};     // its breakpoint dots
inline constexpr Rgb kSignal{80, 230, 110};         // the Signals pane: a logic pin's trace
inline constexpr Rgb kSignalFloat{150, 150, 160};   // a pin not driven ('z')
inline constexpr Rgb kCursorA{250, 200, 60};        // its cursors
inline constexpr Rgb kCursorB{90, 200, 255};
}  // namespace colour

// The layout below is logical: kWindowWidth x kWindowHeight. The window may be any size (it is
// resizable); the picture is scaled to fit it with its proportions kept (letterboxed), so that a
// 1366x768 laptop and a HiDPI screen both show all of it.
inline constexpr int kWindowWidth = 1280;
inline constexpr int kWindowHeight = 800;

// Where the logical picture lies in a drawable of w x h pixels: scale, and the top left offset.
struct Fit {
    float scale = 1, ox = 0, oy = 0;
    bool identity() const { return scale == 1 && ox == 0 && oy == 0; }
};
Fit fit_to(int w, int h);
Vec2 to_logical(const Fit& f, float x, float y);
Vec2 to_window(const Fit& f, float x, float y);
// The window's first size: the logical size times `scale` when scale > 0; otherwise the largest
// that fits a usable_w x usable_h desktop with room for a title bar and a panel, at most 1:1
// (1366x768 gives 1133x708). A scale too large for the desktop is brought down to that fit (the
// caller warns); a desktop of unknown size (0 x 0) takes the scale as given.
struct Size {
    int w = 0, h = 0;
};
Size initial_window_size(double scale, int usable_w, int usable_h);

// ---- the board: its digits (as many as its description's display has, up to eight) ----------
inline constexpr float kDigitX0 = 28, kDigitY0 = 44;  // top left of digit 1
inline constexpr float kDigitPitch = 58, kDigitW = 40, kDigitH = 76, kSegT = 8;
inline constexpr float kDpRadius = 4.5f;
inline constexpr Rect kBoardRect{8, 8, 504, 470};
inline constexpr Rect kDisplayRect{16, 30, 488, 104};
inline constexpr Rect kHintRect{16, 138, 488, 18};  // under the display: a prompt's hint (keys.h)
// The display's window for `digits` digits: kDisplayRect for eight, a digit's pitch narrower for
// each one fewer (the digits keep their places from the left).
Rect display_rect(unsigned digits);

// A segment as its centre line (the drawn bar is kSegT thick around it, with pointed ends).
struct Segment {
    Vec2 a, b;
};
// Segment s (0 = a ... 6 = g, the bit order of seven_segment.h) of digit d (0 = leftmost).
Segment segment(unsigned digit, unsigned s);
Vec2 segment_centre(unsigned digit, unsigned s);
Vec2 dp_centre(unsigned digit);

// ---- the board: keypad -----------------------------------------------------------------------------
// The keypad's buttons (front::pad_keys, in rows and columns) in the window.
inline constexpr float kKeyX0 = 24, kKeyY0 = 160, kKeyW = 62, kKeyH = 50, kKeyPitchX = 68, kKeyPitchY = 58;
Rect key_rect(const PadKey& k);
// The button under a point, if any: of the default board's keypad, or of the session's board.
std::optional<PadKey> key_at(float x, float y);
std::optional<PadKey> key_at(float x, float y, const script::Session& s);
// The rectangle holding every one of these buttons (the keypad's silkscreen outline).
Rect keypad_rect(std::span<const PadKey> keys);

// ---- the machine tool --------------------------------------------------------------------------------
inline constexpr Rect kTableRect{528, 8, 660, 440};   // the X-Y table from above
inline constexpr Rect kZGaugeRect{1204, 30, 60, 396}; // Z: 0 (bottom) .. travel (top)
inline constexpr Rect kStripRect{528, 474, 744, 76};  // the whole X-Y travel (1500 x 200 mm)
inline constexpr Rect kAxesRect{520, 556, 760, 244};  // the axis panel (ImGui)
inline constexpr Rect kControlsRect{0, 484, 520, 316};  // the controls (ImGui)
inline constexpr float kTableMargin = 24;  // pixels kept free inside kTableRect

// ---- the debugger's panes (alp85 gui --debug: in place of the machine tool's views) -----------------
inline constexpr Rect kSourceRect{528, 8, 470, 400};
inline constexpr Rect kRegistersRect{1006, 8, 266, 150};
inline constexpr Rect kDisasmRect{1006, 166, 266, 242};
inline constexpr Rect kMemoryRect{528, 416, 470, 120};
inline constexpr Rect kChipsRect{1006, 416, 266, 120};
inline constexpr Rect kWatchRect{528, 544, 300, 110};
inline constexpr Rect kStepButtonsRect{836, 544, 436, 110};
inline constexpr Rect kCommandRect{528, 662, 744, 130};
inline constexpr float kSourceTop = 26, kSourceRowH = 16, kSourceDotX = 10, kSourceTextX = 64;
inline constexpr int kSourceRows = 23;
// Row `i` (0 = the first shown) of the source pane, and the row at a point.
Rect source_row(int i);
std::optional<int> source_row_at(float x, float y);

// ---- the Signals pane: a logic analyzer over the chosen pins (in the table view's place, or the ----
// source's with --debug). Time runs left to right over the span chosen; the right end is the
// machine's present T-state. Each pin has a row: its name left, its trace right.
inline constexpr Rect kSignalsRect{528, 8, 744, 400};
inline constexpr float kSignalsTraceX = 624, kSignalsTraceW = 640;  // the span: 624 (its start) to 1264 (now)
inline constexpr float kSignalsTop = 96, kSignalsRowH = 26;         // the first row's top, the rows' pitch
inline constexpr float kSignalsHigh = 5, kSignalsLow = 20;          // a row's high and low lines, from its top
inline constexpr int kSignalsRows = 11;
// Row i (0 = the first pin) of the trace area, kSignalsTraceW wide.
Rect signals_row(int i);
// The x of T-state t in a span of `span` T-states ending at `end`; the T-state at x (the inverse).
float signals_x(std::uint64_t t, std::uint64_t end, std::uint64_t span);
double signals_t(float x, std::uint64_t end, std::uint64_t span);

// Millimetres of the table to pixels of kTableRect: the bounds fitted with equal scale on both
// axes, centred, Y up.
struct TableView {
    double scale = 1;  // pixels per mm
    double cx = 0, cy = 0;  // mm at the centre of the rect
    static TableView fit(const Bounds& b, const Rect& r = kTableRect);
    Vec2 to_px(double x_mm, double y_mm, const Rect& r = kTableRect) const;
    // The mm under a pixel (the inverse of to_px).
    std::pair<double, double> to_mm(float x, float y, const Rect& r = kTableRect) const;
};

// The user's zoom and pan of the table view, on top of the automatic fit: the mouse wheel zooms
// about the pointer, a right (or middle) drag pans, Home (or a double click) frames the toolpath,
// End goes back to the automatic fit.
struct TableCamera {
    double zoom = 1;          // times the fit's scale
    double dx = 0, dy = 0;    // mm added to the fit's centre
    std::optional<Bounds> framed;  // Home: the toolpath's bounds to fit instead of everything
    TableView apply(const TableView& fitted) const;
    void zoom_at(const TableView& fitted, float x, float y, double factor);  // keeps the mm under (x, y)
    void pan(const TableView& fitted, float dx_px, float dy_px);
    void frame(const Bounds& b) { *this = {}, framed = b; }
    void reset() { *this = {}; }
};

}  // namespace alp85::gui
