// Opens what scripts/machine/axes.alp recorded and drew (CTest runs that script first, fixture
// machine_axes_outputs) and checks it for sense against the program's own step counts
// (scripts/machine/axes.asm): the CSV's rows and end points, the PNG's size and drawn pixels, the
// SVG's title and path.
#include <gtest/gtest.h>

#include <cairo.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

const std::string kDir = ALP85_AXES_OUT;

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::vector<std::vector<std::string>> csv_rows(const std::string& text) {
    std::vector<std::vector<std::string>> rows;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        std::vector<std::string> cells;
        std::istringstream cols(line);
        for (std::string cell; std::getline(cols, cell, ',');) cells.push_back(cell);
        rows.push_back(cells);
    }
    return rows;
}

TEST(MachineScriptOutputs, TheCsvRecordsTheWholeRunFromRestToTheStaircasesEnd) {
    const auto rows = csv_rows(slurp(kDir + "/axes.csv"));
    ASSERT_GT(rows.size(), 2u) << "no recording in " << kDir;
    const std::vector<std::string>& head = rows[0];
    ASSERT_EQ(head.size(), 16u);  // t_ms and five columns for each of three axes
    EXPECT_EQ(head[0], "t_ms");
    EXPECT_EQ(head[1], "x_commanded");
    EXPECT_EQ(head[2], "x_mm");
    EXPECT_EQ(head[7], "y_mm");
    // Sampled every 1 ms from the reset to the end of the run (585.5 ms: six moves of 20 steps
    // and 20 staircase steps, 12 400 T-states each, plus 20 ms): about 586 rows.
    EXPECT_GE(rows.size(), 560u);
    EXPECT_LE(rows.size(), 600u);
    // Starts at rest at the power-on position; ends at the staircase's top, (10, 10) steps =
    // (0.5, 0.5) mm, with Z back at 0; the commanded counts are signed: +20 - 20 + 10 = 10.
    const auto& first = rows[1];
    EXPECT_EQ(std::stod(first[2]), 0.0);
    EXPECT_EQ(std::stod(first[7]), 0.0);
    const auto& last = rows.back();
    EXPECT_EQ(last[1], "10");                        // X commanded: +20 - 20 + 10
    EXPECT_NEAR(std::stod(last[2]), 0.5, 0.005);     // X mm
    EXPECT_EQ(last[6], "10");                        // Y commanded
    EXPECT_NEAR(std::stod(last[7]), 0.5, 0.005);     // Y mm
    EXPECT_NEAR(std::stod(last[12]), 0.0, 0.005);    // Z mm
    // The farthest X went: 20 steps = 1.0 mm (plus at most a fraction of a step of overshoot).
    double xmax = 0;
    for (std::size_t i = 1; i < rows.size(); ++i) xmax = std::max(xmax, std::stod(rows[i][2]));
    EXPECT_NEAR(xmax, 1.0, 0.03);
}

TEST(MachineScriptOutputs, TheTimePlotIsAPngWithItsCurvesDrawn) {
    cairo_surface_t* s = cairo_image_surface_create_from_png((kDir + "/axes-time.png").c_str());
    ASSERT_EQ(cairo_surface_status(s), CAIRO_STATUS_SUCCESS);
    EXPECT_EQ(cairo_image_surface_get_width(s), 720);
    EXPECT_EQ(cairo_image_surface_get_height(s), 440);
    // Some pixels are neither white nor grey: the coloured curves.
    cairo_surface_flush(s);
    const unsigned char* px = cairo_image_surface_get_data(s);
    const int stride = cairo_image_surface_get_stride(s);
    int coloured = 0;
    for (int y = 0; y < 440; ++y)
        for (int x = 0; x < 720; ++x) {
            const unsigned char* p = px + y * stride + x * 4;  // B G R A
            if (std::abs(p[0] - p[2]) > 60 || std::abs(p[1] - p[2]) > 60) ++coloured;
        }
    EXPECT_GT(coloured, 500);
    cairo_surface_destroy(s);
}

TEST(MachineScriptOutputs, TheToolpathIsAnSvgWithATitleAndAPath) {
    const std::string svg = slurp(kDir + "/axes-path.svg");
    ASSERT_GT(svg.size(), 1000u);
    EXPECT_NE(svg.find("<svg"), std::string::npos);
    EXPECT_NE(svg.find("<title>Toolpath</title>"), std::string::npos);
    EXPECT_NE(svg.find("<path"), std::string::npos);
}

}  // namespace
