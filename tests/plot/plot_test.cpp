// emu/plot: a chart written as PNG (signature, IHDR size) and SVG (text, the title, an <svg>
// element), the toolpath and time-series helpers, tick choice, and the errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <sstream>
#include <string>

#include <unistd.h>

#include "emu/plot/plot.h"

namespace alp85::test {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// This process's folder of charts, removed when the process ends (each test runs in a process).
struct Scratch {
    fs::path dir = fs::temp_directory_path() / ("alp85_plot_test_" + std::to_string(::getpid()));
    ~Scratch() {
        std::error_code ec;
        fs::remove_all(dir, ec);
    }
};

fs::path scratch(const std::string& name) {
    static Scratch s;
    fs::create_directories(s.dir);
    return s.dir / name;
}

plot::Chart sample() {
    plot::Chart c;
    c.title = "Two lines & a <title>";
    c.x_label = "t (ms)";
    c.y_label = "angle (deg)";
    plot::Series a{"rising", {}}, b{"falling", {}, true, true};
    for (int i = 0; i <= 50; ++i) {
        a.points.push_back({i * 0.1, i * 0.2});
        b.points.push_back({i * 0.1, 10.0 - i * 0.2});
    }
    c.series = {a, b};
    return c;
}

TEST(Plot, PngHasSignatureAndIhdrSize) {
    auto c = sample();
    c.width = 640;
    c.height = 360;
    const auto p = scratch("chart.png");
    plot::write(c, p.string());
    const std::string d = slurp(p);
    ASSERT_GT(d.size(), 33u);
    EXPECT_EQ(d.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
    EXPECT_EQ(d.substr(12, 4), "IHDR");
    auto be32 = [&](std::size_t o) {
        return (static_cast<unsigned>(static_cast<unsigned char>(d[o])) << 24) |
               (static_cast<unsigned>(static_cast<unsigned char>(d[o + 1])) << 16) |
               (static_cast<unsigned>(static_cast<unsigned char>(d[o + 2])) << 8) |
               static_cast<unsigned>(static_cast<unsigned char>(d[o + 3]));
    };
    EXPECT_EQ(be32(16), 640u);
    EXPECT_EQ(be32(20), 360u);
}

TEST(Plot, SvgIsTextWithTheTitle) {
    const auto p = scratch("chart.svg");
    plot::write(sample(), p.string());
    const std::string d = slurp(p);
    EXPECT_EQ(d.find('\0'), std::string::npos);
    EXPECT_NE(d.find("<?xml"), std::string::npos);
    EXPECT_NE(d.find("<svg"), std::string::npos);
    EXPECT_NE(d.find("</svg>"), std::string::npos);
    EXPECT_NE(d.find("<title>Two lines &amp; a &lt;title&gt;</title>"), std::string::npos);
    EXPECT_NE(d.find("width=\"720"), std::string::npos);
}

TEST(Plot, ToolpathAndTimeSeries) {
    const auto a = scratch("path.svg"), b = scratch("time.png");
    plot::write_toolpath(a.string(), "Toolpath", {{"actual", {{0, 0}, {0.05, 0}, {0.05, 0.05}, {0.1, 0.05}}}},
                         std::pair<plot::Point, plot::Point>{{0, 0}, {0.1, 0.05}});
    plot::write_time_series(b.string(), "Speed", {{"x", {{0, 0}, {1, 2}, {2, 1}}}}, "v (mm/s)");
    EXPECT_NE(slurp(a).find("<title>Toolpath</title>"), std::string::npos);
    EXPECT_EQ(slurp(b).substr(1, 3), "PNG");
}

TEST(Plot, TicksAreOneTwoFiveSteps) {
    EXPECT_EQ(plot::ticks(0, 10, 5), (std::vector<double>{0, 2, 4, 6, 8, 10}));
    const auto t = plot::ticks(-0.3, 0.3, 6);
    const std::vector<double> want{-0.3, -0.2, -0.1, 0, 0.1, 0.2, 0.3};
    ASSERT_EQ(t.size(), want.size());
    for (std::size_t i = 0; i < t.size(); ++i) EXPECT_NEAR(t[i], want[i], 1e-12);
    EXPECT_EQ(plot::ticks(0, 700, 7).size(), 8u);  // 0..700 by 100
}

// A span starting just below zero (a table view's grid from -2.3 mm): the tick at zero is +0,
// labelled "0" (std::format's "{:g}" of -0.0 is "-0").
TEST(Plot, TheTickAtZeroIsNotNegative) {
    for (const double lo : {-2.3, -0.4, -1e-3}) {
        const auto t = plot::ticks(lo, 10, 5);  // steps of 2: the first tick is at 0
        ASSERT_FALSE(t.empty());
        EXPECT_EQ(t.front(), 0.0);
        EXPECT_FALSE(std::signbit(t.front())) << "from " << lo;
    }
}

// The drawn paths of an SVG as cairo writes them (<path style="..." d="M x y L x y ... Z"/>),
// outside <defs> (the glyphs): their style and their points (a curve by its end point).
struct SvgPath {
    std::string style;
    std::vector<std::vector<plot::Point>> parts;  // one per M
};

std::vector<SvgPath> svg_paths(const std::string& doc) {
    std::vector<SvgPath> out;
    const std::string body = doc.substr(doc.find("</defs>"));
    static const std::regex path_re(R"re(<path style="([^"]*)" d="([^"]*)")re");
    for (auto it = std::sregex_iterator(body.begin(), body.end(), path_re); it != std::sregex_iterator(); ++it) {
        SvgPath p{(*it)[1].str(), {}};
        std::istringstream d((*it)[2].str());
        std::string op;
        while (d >> op) {
            const int n = op == "M" || op == "L" ? 1 : op == "C" ? 3 : 0;
            plot::Point pt;
            for (int i = 0; i < n; ++i) d >> pt.x >> pt.y;
            if (op == "M") p.parts.emplace_back();
            if (n > 0 && !p.parts.empty()) p.parts.back().push_back(pt);
        }
        out.push_back(std::move(p));
    }
    return out;
}

struct Rect {
    double x0, y0, x1, y1;
};

// The legend's box: the one path filled white at 90 % opacity.
std::optional<Rect> legend_box(const std::vector<SvgPath>& paths) {
    for (const auto& p : paths) {
        if (p.style.find("fill-opacity:0.9;") == std::string::npos || p.parts.empty()) continue;
        Rect r{1e9, 1e9, -1e9, -1e9};
        for (const auto& pt : p.parts[0])
            r = {std::min(r.x0, pt.x), std::min(r.y0, pt.y), std::max(r.x1, pt.x), std::max(r.y1, pt.y)};
        return r;
    }
    return std::nullopt;
}

// The data's lines: the paths stroked 1.6 wide.
std::vector<SvgPath> data_lines(const std::vector<SvgPath>& paths) {
    std::vector<SvgPath> out;
    for (const auto& p : paths)
        if (p.style.find("stroke-width:1.6;") != std::string::npos) out.push_back(p);
    return out;
}

// A square's outline and both its diagonals, so that every corner of the plot area has data,
// under the two labels given; the file written.
std::filesystem::path corners(const char* file, const std::string& outline, const std::string& diagonals) {
    const auto p = scratch(file);
    plot::write_time_series(p.string(), "Corners",
                            {{outline, {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0}}},
                             {diagonals, {{0, 0}, {10, 10}, {plot::Point{NAN, NAN}}, {0, 10}, {10, 0}}}},
                            "y");
    return p;
}

// How many points of the data's lines, walked a quarter of a unit at a time, lie inside `r`
// grown by half the line's width (0.8): ink under the legend.
int points_under(const std::vector<SvgPath>& lines, const Rect& r) {
    int n = 0;
    for (const auto& l : lines)
        for (const auto& part : l.parts)
            for (std::size_t i = 0; i < part.size(); ++i) {
                const plot::Point a = part[i], b = i + 1 < part.size() ? part[i + 1] : part[i];
                const int steps = 1 + static_cast<int>(std::hypot(b.x - a.x, b.y - a.y) / 0.25);
                for (int k = 0; k <= steps; ++k) {
                    const double x = a.x + (b.x - a.x) * k / steps, y = a.y + (b.y - a.y) * k / steps;
                    if (x >= r.x0 - 0.8 && x <= r.x1 + 0.8 && y >= r.y0 - 0.8 && y <= r.y1 + 0.8) ++n;
                }
            }
    return n;
}

// A toolpath with a motor's ringing: the path overshoots each step and swings back (turns of
// under 90 degrees). Mitred joins would draw each turn as a spike; round joins do not.
TEST(Plot, DataLinesHaveRoundJoinsAndCaps) {
    std::vector<plot::Point> ringing;
    for (int step = 0; step < 20; ++step) {
        const double x = step * 0.05;
        for (const double over : {0.0, 0.012, -0.008, 0.004, 0.0}) ringing.push_back({x + over, x * 0.5 + over * 0.8});
    }
    const auto p = scratch("ringing.svg");
    plot::write_toolpath(p.string(), "Ringing", {{"actual", ringing}},
                         std::pair<plot::Point, plot::Point>{{0, 0}, {0.95, 0.475}});
    const auto lines = data_lines(svg_paths(slurp(p)));
    ASSERT_EQ(lines.size(), 2u);  // the path and the ideal line
    for (const auto& l : lines) {
        EXPECT_NE(l.style.find("stroke-linejoin:round;"), std::string::npos) << l.style;
        EXPECT_NE(l.style.find("stroke-linecap:round;"), std::string::npos) << l.style;
    }
}

// The legend asked for at the top right (the default) stays there when that corner is empty, and
// moves when the data pass under it: a line from the bottom left to the top right (the thesis's
// line ends in that corner), then a path through all four corners (none is free).
TEST(Plot, TheLegendNeverCoversTheData) {
    // Empty top right: a falling line (top left to bottom right). The legend keeps its corner,
    // 8 units in from the plot area's right edge (720 - 18 = 702) and top (44).
    {
        const auto p = scratch("falling.svg");
        plot::write_time_series(p.string(), "Falling", {{"x", {{0, 10}, {1, 0}}}}, "v");
        const auto paths = svg_paths(slurp(p));
        const auto box = legend_box(paths);
        ASSERT_TRUE(box);
        EXPECT_NEAR(box->x1, 702 - 8, 0.5);
        EXPECT_NEAR(box->y0, 44 + 8, 0.5);
        EXPECT_EQ(points_under(data_lines(paths), *box), 0);
    }
    // A toolpath and its ideal line from the bottom left to the top right corner: 6.24 by 3.40 mm
    // has the plot area's own proportions (624 by 340 units), so at equal scale both fill it.
    {
        const auto p = scratch("rising.svg");
        plot::write_toolpath(p.string(), "Rising", {{"actual", {{0, 0}, {6.24, 3.40}}}},
                             std::pair<plot::Point, plot::Point>{{0, 0}, {6.24, 3.40}});
        const auto paths = svg_paths(slurp(p));
        const auto box = legend_box(paths);
        ASSERT_TRUE(box);
        EXPECT_EQ(points_under(data_lines(paths), *box), 0) << "legend at " << box->x0 << "," << box->y0;
        EXPECT_GE(box->x0, 0);
        EXPECT_LE(box->x1, 720);
    }
    // A square's outline and both diagonals: every corner of the plot area has data; the legend
    // goes beside it, still inside the picture.
    {
        const auto paths = svg_paths(slurp(corners("corners.svg", "outline", "diagonals")));
        const auto box = legend_box(paths);
        ASSERT_TRUE(box);
        EXPECT_EQ(points_under(data_lines(paths), *box), 0) << "legend at " << box->x0 << "," << box->y0;
        EXPECT_GE(box->x0, 0);
        EXPECT_LE(box->x1, 720);
    }
    // The same with labels as long as Fig. 10's, wider than a third of the plot area: beside it
    // they would squeeze the data into a strip, so the legend goes below, under the axis label,
    // and the data keep the picture's width (the plot area spans x 78 to 702 of 720).
    {
        const auto paths = svg_paths(slurp(corners("corners-long.svg",
                                                   "the square's outline, corner to corner and back to where it began",
                                                   "both of its diagonals, one after the other, lifted in between")));
        const auto box = legend_box(paths);
        ASSERT_TRUE(box);
        const auto lines = data_lines(paths);
        EXPECT_EQ(points_under(lines, *box), 0) << "legend at " << box->x0 << "," << box->y0;
        double lowest = 0, x_min = 720, x_max = 0;
        for (const auto& l : lines)
            for (const auto& part : l.parts)
                for (const auto& pt : part) lowest = std::max(lowest, pt.y), x_min = std::min(x_min, pt.x), x_max = std::max(x_max, pt.x);
        EXPECT_GT(box->y0, lowest + 20);  // below the data and the tick labels under them
        EXPECT_LE(box->y1, 440);
        EXPECT_GE(box->x0, 0);
        EXPECT_LE(box->x1, 720);
        EXPECT_LT(x_min, 110);  // the data still span the plot area (padded 4 % each side); beside, x_max would be ~290
        EXPECT_GT(x_max, 670);
    }
}

TEST(Plot, Errors) {
    EXPECT_THROW(plot::write(sample(), scratch("chart.gif").string()), plot::PlotError);
    plot::Chart empty;
    EXPECT_THROW(plot::write(empty, scratch("e.svg").string()), plot::PlotError);
}

}  // namespace
}  // namespace alp85::test
