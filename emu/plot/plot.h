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

// The tick positions chosen for [lo, hi] (1-2-5 steps, about `target` of them): for tests.
std::vector<double> ticks(double lo, double hi, int target = 6);

}  // namespace alp85::plot
