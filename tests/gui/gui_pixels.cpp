// Checks pixels of an `alp85 gui --screenshot` PNG against the window's layout (emu/gui/layout.h):
//   gui_pixels SHOT.png --digits B1,B2,...,B8     each digit's segments (hex byte: bit0 = a ...
//                                                  bit6 = g, bit7 = dp; "--" skips a digit): every
//                                                  segment's centre is the lit or the unlit colour
//   gui_pixels SHOT.png --no-digits D1,D2,...    digits (1 = the leftmost) not drawn: no segment's
//                                                  centre nor the dp in the lit or the unlit colour
//   gui_pixels SHOT.png --key ROW,COL,hex|fn|none  the keypad's place ROW, COL (layout.h's key_rect):
//                                                  a hex key's face, a function key's, or the card
//                                                  (no key there), seen at its left edge's middle
//   gui_pixels SHOT.png --current-row N --breakpoint-row M --text-in X,Y,W,H
//                                                  the debugger's source pane (--debug): row N has
//                                                  the current line's colour, row M a breakpoint dot
//                                                  and not that colour; a pane's rect has text drawn
//   gui_pixels SHOT.png --blank-in X,Y,W,H         no text drawn in that rect
//   gui_pixels SHOT.png --tool X,Y --bounds X0,Y0,X1,Y1 [--not-tool X,Y]
//                                                  the tool's colour where the table view (fitted to
//                                                  the bounds, mm) draws the table position X,Y
//   gui_pixels SHOT.png --signal ROW,X0,X1,H|L   the Signals pane: pin ROW's trace is high (H) or low
//                                                  (L) from x X0 to X1: its colour on that level's
//                                                  line at every pixel, and not on the other's
//   gui_pixels SHOT.png --cursor A|B,X             the Signals pane: that cursor's line at x X
//   gui_pixels SHOT.png --fits W,H | --size W,H ...
//                                                  a scaled window: the screenshot lies within W x H
//                                                  (or is exactly W x H), and every check above is
//                                                  made where the scaled picture has that pixel
//                                                  (layout.h's fit_to); without: exactly 1280 x 800
// Exit status 0 when every check holds; each failure is printed.
#include <cairo.h>

#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "emu/gui/layout.h"

using namespace alp85::gui;

namespace {

struct Image {
    cairo_surface_t* s = nullptr;
    Rgb at(int x, int y) const {
        const auto* row = cairo_image_surface_get_data(s) + static_cast<std::ptrdiff_t>(y) * cairo_image_surface_get_stride(s);
        const std::uint32_t w = reinterpret_cast<const std::uint32_t*>(row)[x];
        return {static_cast<std::uint8_t>(w >> 16), static_cast<std::uint8_t>(w >> 8), static_cast<std::uint8_t>(w)};
    }
};

bool near(Rgb a, Rgb b) {
    return std::abs(a.r - b.r) <= 10 && std::abs(a.g - b.g) <= 10 && std::abs(a.b - b.b) <= 10;
}

std::vector<std::string> split(const std::string& s) {
    std::vector<std::string> out;
    std::stringstream in(s);
    for (std::string item; std::getline(in, item, ',');) out.push_back(item);
    return out;
}

int failures = 0;
Fit g_fit;  // where the logical picture lies in the screenshot

void expect(const Image& img, Vec2 logical, Rgb want, const std::string& what) {
    const Vec2 p = to_window(g_fit, logical.x, logical.y);
    const int x = static_cast<int>(p.x), y = static_cast<int>(p.y);
    const Rgb got = img.at(x, y);
    if (!near(got, want)) {
        std::printf("FAIL %s at (%d,%d): expected %d,%d,%d, found %d,%d,%d\n", what.c_str(), x, y, want.r, want.g, want.b,
                    got.r, got.g, got.b);
        ++failures;
    } else {
        std::printf("ok   %s at (%d,%d)\n", what.c_str(), x, y);
    }
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: gui_pixels SHOT.png [--digits ...] [--tool X,Y --bounds X0,Y0,X1,Y1]\n");
        return 2;
    }
    Image img{cairo_image_surface_create_from_png(argv[1])};
    if (cairo_surface_status(img.s) != CAIRO_STATUS_SUCCESS) {
        std::fprintf(stderr, "gui_pixels: cannot read %s\n", argv[1]);
        return 2;
    }
    const int iw = cairo_image_surface_get_width(img.s), ih = cairo_image_surface_get_height(img.s);
    bool scaled = false;
    for (int i = 2; i + 1 < argc; i += 2) {
        const std::string opt = argv[i];
        if (opt != "--fits" && opt != "--size") continue;
        const auto wh = split(argv[i + 1]);
        const int w = std::stoi(wh.at(0)), h = std::stoi(wh.at(1));
        const bool ok = opt == "--size" ? iw == w && ih == h : iw <= w && ih <= h;
        std::printf("%s  the screenshot is %dx%d: %s %dx%d\n", ok ? "ok  " : "FAIL", iw, ih, opt == "--size" ? "expected" : "within", w, h);
        if (!ok) return 1;
        scaled = true;
    }
    if (scaled) g_fit = fit_to(iw, ih);
    if (!scaled && (iw != kWindowWidth || ih != kWindowHeight)) {
        std::printf("FAIL the screenshot is %dx%d, the window %dx%d\n", cairo_image_surface_get_width(img.s),
                    cairo_image_surface_get_height(img.s), kWindowWidth, kWindowHeight);
        return 1;
    }
    std::vector<double> tool, not_tool, bounds;
    for (int i = 2; i + 1 < argc; i += 2) {
        const std::string opt = argv[i];
        const auto items = split(argv[i + 1]);
        if (opt == "--digits") {
            for (unsigned d = 0; d < items.size() && d < 8; ++d) {
                if (items[d] == "--") continue;
                const auto bits = static_cast<unsigned>(std::stoul(items[d], nullptr, 16));
                for (unsigned s = 0; s < 7; ++s)
                    expect(img, segment_centre(d, s), (bits >> s & 1) ? colour::kSegmentLit : colour::kSegmentUnlit,
                           "digit " + std::to_string(d + 1) + " segment " + std::string(1, static_cast<char>('a' + s)) +
                               ((bits >> s & 1) ? " lit" : " unlit"));
                expect(img, dp_centre(d), (bits & 0x80) ? colour::kSegmentLit : colour::kSegmentUnlit,
                       "digit " + std::to_string(d + 1) + " dp" + ((bits & 0x80) ? " lit" : " unlit"));
            }
        } else if (opt == "--no-digits") {
            for (const std::string& item : items) {
                const unsigned d = static_cast<unsigned>(std::stoul(item)) - 1;
                std::vector<Vec2> points{dp_centre(d)};
                for (unsigned s = 0; s < 7; ++s) points.push_back(segment_centre(d, s));
                int drawn = 0;
                for (const Vec2 q : points) {
                    const Vec2 p = to_window(g_fit, q.x, q.y);
                    const Rgb c = img.at(static_cast<int>(p.x), static_cast<int>(p.y));
                    drawn += near(c, colour::kSegmentLit) || near(c, colour::kSegmentUnlit);
                }
                std::printf("%s digit %s %s\n", drawn ? "FAIL" : "ok  ", item.c_str(),
                            drawn ? ("is drawn (" + std::to_string(drawn) + " of its 8 segments)").c_str() : "not drawn");
                failures += drawn != 0;
            }
        } else if (opt == "--key") {
            PadKey k;
            k.row = std::stoi(items.at(0)), k.col = std::stoi(items.at(1));
            const Rect r = key_rect(k);
            const Rgb want = items.at(2) == "hex" ? colour::kKey : items.at(2) == "fn" ? colour::kKeyFunction : colour::kBoard;
            expect(img, {r.x + 4, r.y + r.h / 2}, want, "keypad row " + items[0] + " column " + items[1] + ": " + items[2]);
        } else if (opt == "--current-row" || opt == "--breakpoint-row") {
            const int row = std::stoi(items[0]);
            const Rect r = source_row(row);
            const Vec2 edge{r.x + 2, r.y + r.h / 2};
            if (opt == "--current-row") {
                expect(img, edge, colour::kCurrentLine, "source row " + items[0] + " is the current line");
            } else {
                expect(img, {r.x + kSourceDotX, r.y + r.h / 2}, colour::kBreakpoint, "source row " + items[0] + " has a breakpoint dot");
                if (near(img.at(static_cast<int>(edge.x), static_cast<int>(edge.y)), colour::kCurrentLine)) {
                    std::printf("FAIL source row %s is highlighted as the current line too\n", items[0].c_str());
                    ++failures;
                }
            }
        } else if (opt == "--fits" || opt == "--size") {
            continue;
        } else if (opt == "--signal") {
            // The lines are drawn 2 pixels thick about y + 0.5 (ImGui's pixel centres): row y is inside.
            const Rect row = signals_row(std::stoi(items[0]));
            const float x0 = std::stof(items[1]), x1 = std::stof(items[2]);
            const bool high = items[3] == "H";
            const float on = row.y + (high ? kSignalsHigh : kSignalsLow), off = row.y + (high ? kSignalsLow : kSignalsHigh);
            int bad = 0;
            for (float x = x0; x <= x1; ++x) {
                const Vec2 a = to_window(g_fit, x, on), b = to_window(g_fit, x, off);
                const bool ok = near(img.at(static_cast<int>(a.x), static_cast<int>(a.y)), colour::kSignal) &&
                                !near(img.at(static_cast<int>(b.x), static_cast<int>(b.y)), colour::kSignal);
                if (!ok && bad++ == 0) std::printf("FAIL signal row %s is not %s at x %g\n", items[0].c_str(), high ? "high" : "low", x);
            }
            if (bad) ++failures;
            else std::printf("ok   signal row %s %s from x %g to %g\n", items[0].c_str(), high ? "high" : "low", x0, x1);
        } else if (opt == "--cursor") {
            expect(img, {std::stof(items[1]), kSignalsTop - 2}, items[0] == "A" ? colour::kCursorA : colour::kCursorB,
                   "cursor " + items[0]);
        } else if (opt == "--text-in" || opt == "--blank-in") {
            // Text drawn: enough light pixels (ImGui's text is near white on the dark panes);
            // blank: none at all.
            const Vec2 a = to_window(g_fit, std::stof(items[0]), std::stof(items[1]));
            const int x0 = static_cast<int>(a.x), y0 = static_cast<int>(a.y);
            const int w = static_cast<int>(std::stof(items[2]) * g_fit.scale), h = static_cast<int>(std::stof(items[3]) * g_fit.scale);
            int light = 0;
            for (int y = y0; y < y0 + h; ++y)
                for (int x = x0; x < x0 + w; ++x) {
                    const Rgb c = img.at(x, y);
                    light += c.r > 180 && c.g > 180 && c.b > 180;
                }
            const bool want_text = opt == "--text-in";
            if (want_text ? light < 50 : light > 0) {
                std::printf("FAIL %s in %d,%d %dx%d (%d light pixels)\n", want_text ? "no text" : "text", x0, y0, w, h, light);
                ++failures;
            } else {
                std::printf("ok   %s in %d,%d %dx%d (%d light pixels)\n", want_text ? "text" : "blank", x0, y0, w, h, light);
            }
        } else {
            std::vector<double>& v = opt == "--tool" ? tool : opt == "--not-tool" ? not_tool : bounds;
            for (const auto& it : items) v.push_back(std::stod(it));
        }
    }
    if (tool.size() == 2 && bounds.size() == 4) {
        Bounds b = Bounds::none();
        b.add(bounds[0], bounds[1]);
        b.add(bounds[2], bounds[3]);
        const TableView view = TableView::fit(b);
        expect(img, view.to_px(tool[0], tool[1]), colour::kTool, "tool at table X,Y mm " + std::to_string(tool[0]) + "," + std::to_string(tool[1]));
        if (not_tool.size() == 2) {
            const Vec2 q = view.to_px(not_tool[0], not_tool[1]);
            const Vec2 p = to_window(g_fit, q.x, q.y);
            if (near(img.at(static_cast<int>(p.x), static_cast<int>(p.y)), colour::kTool)) {
                std::printf("FAIL the tool is also drawn at %g,%g mm\n", not_tool[0], not_tool[1]);
                ++failures;
            }
        }
    }
    cairo_surface_destroy(img.s);
    std::printf("%s\n", failures ? "FAILED" : "all pixels as expected");
    return failures ? 1 : 0;
}
