// emu/plot: a chart written as PNG (signature, IHDR size) and SVG (text, the title, an <svg>
// element), the toolpath and time-series helpers, tick choice, and the errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
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

fs::path scratch(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("alp85_plot_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir / name;
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

TEST(Plot, Errors) {
    EXPECT_THROW(plot::write(sample(), scratch("chart.gif").string()), plot::PlotError);
    plot::Chart empty;
    EXPECT_THROW(plot::write(empty, scratch("e.svg").string()), plot::PlotError);
}

}  // namespace
}  // namespace alp85::test
