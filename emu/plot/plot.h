// Line charts drawn with cairo, to SVG or PNG chosen by the file's extension (.svg / .png): axes
// with labelled ticks at 1-2-5 steps, axis titles with their units, a title, a legend, several
// series (lines, optionally with markers). Plain data in; no emulator types.
//
//   plot::Chart c{.title = "Step response", .x_label = "t (ms)", .y_label = "angle (deg)"};
//   c.series.push_back({"rotor", points});
//   plot::write(c, "docs/img/step.svg");
//
// Data lines have round joins and caps. The legend never covers the data: it goes to the corner
// asked for when no line passes there, else to the first free corner, else beside the plot area.
//
// Not done: logarithmic axes, several y axes, text layout beyond cairo's toy font API (labels are
// not wrapped).
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace alp85::plot {

struct Point {
    double x = 0;
    double y = 0;
};

struct Series {
    std::string label;
    std::vector<Point> points;
    bool markers = false;  // a dot at each point
    bool dashed = false;
};

struct Chart {
    std::string title;
    std::string x_label = "x (mm)";
    std::string y_label = "y (mm)";
    std::vector<Series> series;
    int width = 720;   // pixels (PNG) or points (SVG)
    int height = 440;
    bool equal_scale = false;  // one unit is the same length on both axes (toolpaths)
    // Where the legend goes if no data passes there (a corner inside the plot area), or Right:
    // beside the plot area, always.
    enum class Legend { TopRight, TopLeft, BottomRight, BottomLeft, Right } legend = Legend::TopRight;
};

class PlotError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Draws the chart to `path`; the extension picks the format. Throws PlotError (unknown
// extension, no data, cairo failure).
void write(const Chart& chart, const std::string& path);

// An XY toolpath in mm: the actual paths, and optionally the ideal straight line from a to b.
void write_toolpath(const std::string& path, const std::string& title, const std::vector<Series>& paths,
                    std::optional<std::pair<Point, Point>> ideal = std::nullopt);

// Series against time (x in `t_label`'s units).
void write_time_series(const std::string& path, const std::string& title, const std::vector<Series>& series,
                       const std::string& y_label, const std::string& t_label = "t (s)",
                       Chart::Legend legend = Chart::Legend::TopRight);

// A timing diagram (the 8085's bus cycles, `alp85 timing`): named rows of waveforms against time
// in whole units (T-states), under a row of spans (machine cycles) and one of ticks (T1, T2...).
struct TimingDiagram {
    struct Segment {
        double from = 0, to = 0;  // time units
        char level = '0';         // a wire: '0', '1'; a bus: 'v' (text holds the value); both: 'z', 'x'
        std::string text;
    };
    struct Wave {
        std::string name;  // "ALE", "AD7-AD0"
        bool bus = false;
        std::vector<Segment> segments;
    };
    struct Span {
        double from = 0, to = 0;
        std::string label;  // "M1 opcode fetch"
    };
    struct Tick {
        double at = 0;      // start of the unit labelled
        std::string label;  // "T1"
    };
    std::string title;
    double length = 0;
    std::vector<Span> spans;
    std::vector<Tick> ticks;
    std::vector<Wave> waves;
};
// Draws it to `path` (.svg or .png), whole or not at all. Throws PlotError.
void write_timing(const TimingDiagram& d, const std::string& path);

// The tick positions chosen for [lo, hi] (1-2-5 steps, about `target` of them): for tests.
std::vector<double> ticks(double lo, double hi, int target = 6);

}  // namespace alp85::plot
