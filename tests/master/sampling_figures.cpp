// Watanabe and Iwai's Figs. 6, 9 and 10 for docs/contours.md, drawn with the project's plot library
// (emu/plot) as SVG and PNG:
//   Fig. 6: eq. 7's eps_L,max against C_L (C_x = 1, the worst: a line near an axis), for the paper's
//           B = 16, M = 20 and the ALP 85's B = 16, M = 15;
//   Fig. 9: eq. 17 (the largest error around a full circle) and eq. 18 (its 0.01 % confidence limit)
//           against C_R, for the paper's M = 20 (R = 1.049 m at dX = 1 um) and M_R = 10, and for the
//           ALP 85's 16.16 arithmetic (dX' = 2^-16 step) at its largest radius, 2047 steps;
//   Fig. 10: the time occupation rate measured on the emulated 8085 (fig10.csv, written by
//           tests/master/fig10_measure.py): T-states of a 2 ms sample's own work / 6144, and for the
//           arc its work with the look-ahead jobs (the next chord's set-up) run in its spare time, for
//           the line its work without the pulse's placement (the paper's software servo's part).
//
//   sampling_figures OUT_DIR FIG10_CSV
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "emu/plot/plot.h"

namespace {

using alp85::plot::Chart;
using alp85::plot::Point;
using alp85::plot::Series;

// eq. 7 with C_x = 1, in dX
double eq7(int m, int b, int cl) { return std::ldexp(1.0, 2 * m - 3 * b + 2 + cl) + std::ldexp(1.0, -cl - 1) + 0.5; }

// eq. 17 (confidence = false) or eq. 18, in dX; r_bits: R = 2^r_bits; lsb: dX'/dX as a power of two
// (the paper's 2^(M-2B): its double precision word spans the largest radius)
double eq17(int r_bits, int lsb_pow, int cr, bool confidence) {
    const double pi = std::numbers::pi;
    const double r = std::ldexp(1.0, r_bits);
    const double poly = r * std::ldexp(1.0, -2 * cr - 4) + pi * r * std::ldexp(1.0, -5 * cr - 6);
    const double k = 1 + std::ldexp(1.0, -cr) + std::ldexp(1.0, -2 * cr - 1);
    const double round_off = confidence ? 3.2 * std::sqrt(pi) * std::ldexp(1.0, lsb_pow + 1) * std::pow(2.0, 0.5 * cr) * k
                                        : std::ldexp(1.0, lsb_pow + cr + 4) * k;
    return poly + round_off + 0.5;
}

void both(const Chart& c, const std::string& out, const std::string& name) {
    alp85::plot::write(c, out + "/" + name + ".svg");
    alp85::plot::write(c, out + "/" + name + ".png");
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: sampling_figures OUT_DIR FIG10_CSV\n");
        return 2;
    }
    const std::string out = argv[1];
    try {
        Chart f6{.title = "Fig. 6: eps_L,max (eq. 7, C_x = 1) against C_L", .x_label = "C_L", .y_label = "eps_L,max (dX)", .series = {}};
        Series p6{"paper: B 16, M 20", {}, true, false}, a6{"ALP 85: B 16, M 15", {}, true, false};
        for (int cl = 0; cl <= 14; ++cl) {
            p6.points.push_back({double(cl), std::min(eq7(20, 16, cl), 1.2)});
            a6.points.push_back({double(cl), std::min(eq7(15, 16, cl), 1.2)});
        }
        f6.series = {p6, a6};
        both(f6, out, "fig6");

        Chart f9{.title = "Fig. 9: path error around a full circle against C_R", .x_label = "C_R", .y_label = "error (dX), above 8 cut", .series = {}};
        Series m20{"eq. 17, paper M 20", {}, true, false}, c20{"eq. 18, paper M 20", {}, true, true},
            c10{"eq. 18, paper M_R 10", {}, true, true}, alp{"eq. 17, ALP 85 R 2047, dX' 2^-16", {}, true, false};
        for (int cr = 1; cr <= 16; ++cr) {
            const auto clip = [](double v) { return std::min(v, 8.0); };
            m20.points.push_back({double(cr), clip(eq17(20, 20 - 32, cr, false))});
            c20.points.push_back({double(cr), clip(eq17(20, 20 - 32, cr, true))});
            c10.points.push_back({double(cr), clip(eq17(10, 20 - 32, cr, true))});
            alp.points.push_back({double(cr), clip(eq17(11, -16, cr, false))});
        }
        f9.series = {m20, c20, c10, alp};
        both(f9, out, "fig9");

        // Not the paper's comparison (its Koren DDA and Middleditch method are not implemented here):
        // the sampling curves are a 2 ms sample's whole work, and the DDA a bare two-add line loop.
        Chart f10{.title = "Fig. 10 on the ALP 85: a 2 ms sample's whole work / 6144 T-states",
                  .x_label = "feedrate (mm/min)", .y_label = "share of the 8085's 2 ms period", .series = {}, .height = 600};
        Series l10{"sampling, line: whole sample (timer, ramp, eqs. 4-6, placement, OUT)", {}, true, false}, r10{"sampling, arc R 20 mm C_R 3: whole sample", {}, true, false},
            j10{"sampling, arc: whole sample + look-ahead jobs", {}, true, true},
            p10{"sampling, line: whole sample less the pulse placement", {}, true, true},
            d10{"bare DDA line loop (dda.asm: 2 adds + OUT; no timer, ramp, arcs), every 2 ms", {}, true, true};
        std::ifstream in(argv[2]);
        if (!in) throw std::runtime_error(std::string("cannot read ") + argv[2]);
        // columns by name (fig10_measure.py's header): the feed, each sample's whole work and whole
        // work + jobs (T-states a sample), the bare DDA loop's iteration
        const auto split = [](const std::string& text) {
            std::vector<std::string> cells;
            std::istringstream s(text);
            for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
            return cells;
        };
        std::string line;
        std::getline(in, line);
        const auto header = split(line);
        const auto column = [&](const char* name) {
            for (std::size_t i = 0; i < header.size(); ++i)
                if (header[i] == name) return i;
            throw std::runtime_error(std::string(argv[2]) + ": no column " + name);
        };
        const std::size_t cf = column("feed"), cl = column("line_sample"), ca = column("arc_sample"),
                          cj = column("arc_sample_jobs"), cd = column("bare_dda_line"), cp = column("line_place");
        for (int row = 2; std::getline(in, line); ++row) {
            const auto cells = split(line);
            if (cells.size() != header.size())
                throw std::runtime_error(std::string(argv[2]) + ":" + std::to_string(row) + ": " + std::to_string(cells.size()) +
                                         " columns, the header has " + std::to_string(header.size()));
            const double f = std::stod(cells[cf]);
            l10.points.push_back({f, std::stod(cells[cl]) / 6144});
            r10.points.push_back({f, std::stod(cells[ca]) / 6144});
            j10.points.push_back({f, std::stod(cells[cj]) / 6144});
            p10.points.push_back({f, (std::stod(cells[cl]) - std::stod(cells[cp])) / 6144});
            d10.points.push_back({f, std::stod(cells[cd]) / 6144});
        }
        // an unnamed point at 0: the rate's axis from 0
        const Series zero{"", {{d10.points.empty() ? 0.0 : d10.points.front().x, 0.0}}, false, false};
        f10.series = {l10, r10, j10, p10, d10, zero};
        // The legend where the plot puts it: a corner the lines leave free, else (its labels are
        // long) below the axis label, so that the curves keep the picture's width.
        both(f10, out, "fig10");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "sampling_figures: %s\n", e.what());
        return 1;
    }
    for (int cr = 1; cr <= 16; ++cr)
        std::printf("C_R %2d: eq17 M20 %.3f  eq18 M20 %.3f  eq18 M_R10 %.3f  eq17 ALP85 %.3f\n", cr, eq17(20, -12, cr, false),
                    eq17(20, -12, cr, true), eq17(10, -12, cr, true), eq17(11, -16, cr, false));
    for (int cl = 0; cl <= 14; ++cl) std::printf("C_L %2d: eq7 M20 %.4f  M15 %.4f\n", cl, eq7(20, 16, cl), eq7(15, 16, cl));
    return 0;
}
