// pisa_figures: the Pisa interpolator's figures for docs/pisa.md - the line and arc of the
// three-generation table and the contour, run through the ROM program: path and end-point error
// against exact geometry, computing time per mm, the busiest 6 ms period, the servo's following
// error; and their plots (SVG and PNG).
//   pisa_figures FIRMWARE.pasm TAPE_DIR OUT_DIR
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "asm/pisa_asm.h"
#include "emu/pisa/run.h"
#include "emu/pisa/run_plot.h"
#include "emu/plot/plot.h"

using namespace alp85;

namespace {

double distance_to(const pisa::Element& e, double x, double y) {
    if (e.arc()) {
        double r = std::hypot(static_cast<double>(e.x0 - e.cx), static_cast<double>(e.y0 - e.cy));
        return std::abs(std::hypot(x - static_cast<double>(e.cx), y - static_cast<double>(e.cy)) - r);
    }
    double ax = static_cast<double>(e.x1 - e.x0), ay = static_cast<double>(e.y1 - e.y0);
    double len = std::hypot(ax, ay);
    if (len == 0) return std::hypot(x - static_cast<double>(e.x0), y - static_cast<double>(e.y0));
    return std::abs((x - static_cast<double>(e.x0)) * ay - (y - static_cast<double>(e.y0)) * ax) / len;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: pisa_figures FIRMWARE.pasm TAPE_DIR OUT_DIR\n");
        return 2;
    }
    auto prog = pisa_asm::assemble_file(argv[1]);
    if (!prog.ok()) return 1;
    const auto* wait = prog.out.find_symbol("WAIT");
    fmt::print("| tape | elements | outputs | path error, largest (µm) | end points off (µm) | path (mm) | "
               "computing (digit steps/mm) | ms/mm at 100 ns | busiest 6 ms period (ms) | following error, largest (mm) |\n");
    fmt::print("|---|---|---|---|---|---|---|---|---|---|\n");
    for (const char* name : {"line", "circle", "contour"}) {
        std::ifstream in(fmt::format("{}/{}.tape", argv[2], name));
        std::stringstream ss;
        ss << in.rdbuf();
        auto parsed = pisa::parse_tape(ss.str());
        if (parsed.error) {
            std::fprintf(stderr, "%s: %d:%d: %s\n", name, parsed.error->line, parsed.error->col, parsed.error->message.c_str());
            return 1;
        }
        pisa::RunParams p;
        p.idle_first = wait->value;
        p.idle_last = static_cast<std::uint16_t>(wait->value + 1);
        auto r = pisa::run_tape(prog.rom, parsed.tape, p);
        const auto& els = parsed.tape.elements;
        // Walk the outputs element by element (an element ends on its end point's output).
        double worst = 0, end_off = 0, path = 0, follow = 0, busiest = 0;
        std::size_t k = 0, outputs = 0;
        double px = 0, py = 0;
        bool moving = false;
        for (std::size_t i = 0; i < r.output_samples && k < els.size(); ++i) {
            const auto& s = r.samples[i];
            double x = static_cast<double>(s.cmd_x_um), y = static_cast<double>(s.cmd_y_um);
            if (!moving && x == 0 && y == 0) continue;
            moving = true;
            ++outputs;
            path += std::hypot(x - px, y - py) / 1000;
            px = x, py = y;
            worst = std::max(worst, distance_to(els[k], x, y));
            if (i > 0) {
                double dt = static_cast<double>(s.t - r.samples[i - 1].t), di = static_cast<double>(s.idle - r.samples[i - 1].idle);
                busiest = std::max(busiest, (dt - di) * 1e-4);
            }
            follow = std::max(follow, std::hypot(static_cast<double>(s.cmd_x_um) / 1000 - s.x_mm,
                                                 static_cast<double>(s.cmd_y_um) / 1000 - s.y_mm));
            if (s.cmd_x_um == els[k].x1 && s.cmd_y_um == els[k].y1) ++k;
        }
        const auto& last = r.samples[r.output_samples - 1];
        end_off = std::hypot(static_cast<double>(last.cmd_x_um - els.back().x1), static_cast<double>(last.cmd_y_um - els.back().y1));
        double busy = static_cast<double>(r.steps - r.idle_steps);
        fmt::print("| {} | {} | {} | {:.3f} | {:.0f} | {:.3f} | {:.0f} | {:.3f} | {:.2f} | {:.3f} |\n", name, els.size(),
                   outputs, worst, end_off + (k == els.size() ? 0 : 1e9), path, busy / path, busy * 1e-4 / path, busiest, follow);
        if (std::string(name) == "circle") {
            // The radial error of the outputs and of the tables against time: the method's
            // +-1 um and the servo's steady shrink R (1 - 1/sqrt(1 + (w/Kv)^2)).
            const auto& e = els.front();
            double cx = static_cast<double>(e.cx) / 1000, cy = static_cast<double>(e.cy) / 1000;
            double rad = std::hypot(static_cast<double>(e.x0 - e.cx), static_cast<double>(e.y0 - e.cy)) / 1000;
            plot::Series out{"6 ms outputs", {}, false, false}, tab{"tables (servo)", {}, false, false};
            bool started = false;
            for (std::size_t i = 0; i < r.output_samples; ++i) {
                const auto& s = r.samples[i];
                if (!started && s.cmd_x_um == 0 && s.cmd_y_um == 0) continue;
                started = true;
                double t = static_cast<double>(s.t) * 1e-7;
                out.points.push_back({t, (std::hypot(static_cast<double>(s.cmd_x_um) / 1000 - cx,
                                                     static_cast<double>(s.cmd_y_um) / 1000 - cy) - rad) * 1000});
                tab.points.push_back({t, (std::hypot(s.x_mm - cx, s.y_mm - cy) - rad) * 1000});
            }
            for (const char* ext : {"svg", "png"})
                plot::write_time_series(fmt::format("{}/circle-error.{}", argv[3], ext),
                                        "Circle R 20 mm, F 750: distance from the circle", {out, tab},
                                        "r - R (um)", "t (s)", plot::Chart::Legend::BottomRight);
        }
        for (const char* ext : {"svg", "png"}) {
            plot::Chart c = pisa::toolpath_chart(fmt::format("Pisa interpolator, {}.tape", name), parsed.tape, r);
            plot::write(c, fmt::format("{}/{}.{}", argv[3], name, ext));
        }
    }
    return 0;
}
