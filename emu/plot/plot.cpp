// Line charts to SVG or PNG with cairo; see plot.h.
#include "emu/plot/plot.h"
#include "emu/util/text.h"

// The web build (emscripten, docs/web.md) has no cairo: there the page draws its own charts and
// write() says so.
#if __has_include(<cairo.h>)
#define ALP85_PLOT_CAIRO 1
#include <cairo-svg.h>
#include <cairo.h>
#else
#define ALP85_PLOT_CAIRO 0
#endif

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <sstream>

namespace alp85::plot {

namespace {

double nice_step(double span, int target) {
    const double raw = span / std::max(1, target);
    const double mag = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * mag >= raw) return m * mag;
    return 10.0 * mag;
}

#if ALP85_PLOT_CAIRO
struct Rgb {
    double r, g, b;
};
constexpr Rgb kPalette[] = {{0.12, 0.47, 0.71}, {0.84, 0.15, 0.16}, {0.17, 0.63, 0.17},
                            {1.00, 0.50, 0.05}, {0.58, 0.40, 0.74}, {0.55, 0.34, 0.29}};


std::string label(double v, double step) {
    const int digits = std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9)));
    v = std::round(v / step) * step;
    if (std::fabs(v) < step * 1e-9) v = 0.0;
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", digits, v);
    return buf;
}

struct Range {
    double lo, hi;
};

Range padded(double lo, double hi) {
    if (!(hi > lo)) {
        const double d = lo == 0 ? 1.0 : std::fabs(lo) * 0.1;
        return {lo - d, hi + d};
    }
    const double pad = (hi - lo) * 0.04;
    return {lo - pad, hi + pad};
}

class Surface {
public:
    Surface(const std::string& path, int w, int h) : path_(path) {
        const auto dot = path.rfind('.');
        const std::string ext = dot == std::string::npos ? "" : path.substr(dot + 1);
        if (ext == "svg") {
            svg_ = true;
            s_ = cairo_svg_surface_create(path.c_str(), w, h);
        } else if (ext == "png") {
            s_ = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h);
        } else {
            throw PlotError("plot: unknown file type (want .svg or .png): " + path);
        }
        if (cairo_surface_status(s_) != CAIRO_STATUS_SUCCESS) {
            cairo_surface_destroy(s_);
            throw PlotError("plot: cannot create " + path);
        }
        cr_ = cairo_create(s_);
    }
    ~Surface() {
        if (cr_) cairo_destroy(cr_);
        if (s_) cairo_surface_destroy(s_);
    }
    Surface(const Surface&) = delete;
    Surface& operator=(const Surface&) = delete;
    cairo_t* cr() { return cr_; }
    void finish() {
        cairo_destroy(cr_);
        cr_ = nullptr;
        cairo_status_t st = CAIRO_STATUS_SUCCESS;
        if (!svg_) st = cairo_surface_write_to_png(s_, path_.c_str());
        cairo_surface_finish(s_);
        if (st == CAIRO_STATUS_SUCCESS) st = cairo_surface_status(s_);
        if (st != CAIRO_STATUS_SUCCESS) throw PlotError("plot: writing " + path_ + ": " + cairo_status_to_string(st));
    }

private:
public:
    bool svg() const { return svg_; }

private:
    std::string path_;
    bool svg_ = false;
    cairo_surface_t* s_ = nullptr;
    cairo_t* cr_ = nullptr;
};

// A rectangle in device units (pixels or points).
struct Box {
    double x, y, w, h;
};

// Whether the segment (x0,y0)-(x1,y1) meets the box: Liang-Barsky clipping of the segment to it.
bool meets(const Box& b, double x0, double y0, double x1, double y1) {
    double t0 = 0, t1 = 1;
    const double dx = x1 - x0, dy = y1 - y0;
    const double p[] = {-dx, dx, -dy, dy};
    const double q[] = {x0 - b.x, b.x + b.w - x0, y0 - b.y, b.y + b.h - y0};
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0) {
            if (q[i] < 0) return false;  // parallel to this edge and outside it
            continue;
        }
        const double t = q[i] / p[i];
        if (p[i] < 0) t0 = std::max(t0, t);
        else t1 = std::min(t1, t);
        if (t0 > t1) return false;
    }
    return true;
}

void text(cairo_t* cr, const std::string& s, double x, double y, double ax, double ay, double size,
          bool bold = false, double angle = 0.0) {
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size);
    cairo_text_extents_t e;
    cairo_text_extents(cr, s.c_str(), &e);
    cairo_save(cr);
    cairo_translate(cr, x, y);
    cairo_rotate(cr, angle);
    cairo_move_to(cr, -e.x_bearing - e.width * ax, -e.y_bearing - e.height * ay);
    cairo_show_text(cr, s.c_str());
    cairo_restore(cr);
}


// cairo draws text as glyph outlines; an SVG <title> element carries the title as text (for
// readers, search and tests).
void add_svg_title(const std::string& path, const std::string& title) {
    std::string doc;
    {
        std::ifstream in(path, std::ios::binary);
        std::ostringstream ss;
        ss << in.rdbuf();
        doc = ss.str();
    }
    const auto open = doc.find("<svg");
    const auto end = open == std::string::npos ? open : doc.find('>', open);
    if (end == std::string::npos) throw PlotError("plot: cairo wrote no <svg> element to " + path);
    doc.insert(end + 1, "\n<title>" + xml_escape(title) + "</title>");
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << doc;
    if (!out) throw PlotError("plot: cannot rewrite " + path);
}

#endif
}  // namespace

std::vector<double> ticks(double lo, double hi, int target) {
    std::vector<double> out;
    if (!(hi > lo)) return out;
    const double step = nice_step(hi - lo, target);
    // + 0.0: ceil of a small negative is -0.0, and a tick there would be labelled "-0".
    for (double k = std::ceil(lo / step - 1e-9); k * step <= hi + step * 1e-9; k += 1.0) out.push_back(k * step + 0.0);
    return out;
}

namespace {
void draw(const Chart& c, const std::string& path);
void draw_timing(const TimingDiagram& d, const std::string& path);

// The picture is drawn to a temporary file beside `path` and renamed over it when complete, so a
// failed plot never leaves a half-written file (nor removes an older one).
template <class Draw>
void write_whole(const std::string& path, Draw draw) {
    if (!ALP85_PLOT_CAIRO) throw PlotError("plot: " + path + ": this build draws no charts (no cairo)");
    const std::filesystem::path target(path);
    std::filesystem::path tmp = target;
    tmp.replace_filename("." + target.stem().string() + ".partial" + target.extension().string());
    try {
        draw(tmp.string());
        std::filesystem::rename(tmp, target);
    } catch (const PlotError& e) {
        std::error_code ec;
        std::filesystem::remove(tmp, ec);
        std::string msg = e.what();  // name the file the user asked for, not the temporary
        if (const auto at = msg.find(tmp.string()); at != std::string::npos) msg.replace(at, tmp.string().size(), path);
        throw PlotError(msg);
    } catch (const std::filesystem::filesystem_error& e) {
        std::error_code ec;
        std::filesystem::remove(tmp, ec);
        throw PlotError("plot: cannot write " + path + ": " + e.code().message());
    }
}
}  // namespace

void write(const Chart& c, const std::string& path) {
    write_whole(path, [&](const std::string& tmp) { draw(c, tmp); });
}

void write_timing(const TimingDiagram& d, const std::string& path) {
    if (d.waves.empty() || d.length <= 0) throw PlotError("plot: " + path + ": an empty timing diagram");
    write_whole(path, [&](const std::string& tmp) { draw_timing(d, tmp); });
}

namespace {
#if ALP85_PLOT_CAIRO
void draw(const Chart& c, const std::string& path) {
    double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
    for (const auto& s : c.series)
        for (const auto& p : s.points) {
            if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
            x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
        }
    if (!(x1 >= x0)) throw PlotError("plot: no data for " + path);

    Surface surf(path, c.width, c.height);
    cairo_t* cr = surf.cr();
    const double left = 78, right = 18, top = 44, bottom = 56;
    double pw = c.width - left - right;
    double ph = c.height - top - bottom;
    Range xr{}, yr{};
    auto scale = [&] {  // the data's ranges for a plot area pw wide
        xr = padded(x0, x1), yr = padded(y0, y1);
        if (c.equal_scale) {
            const double ux = (xr.hi - xr.lo) / pw, uy = (yr.hi - yr.lo) / ph, u = std::max(ux, uy);
            const double cx = (xr.lo + xr.hi) / 2, cy = (yr.lo + yr.hi) / 2;
            xr = {cx - u * pw / 2, cx + u * pw / 2};
            yr = {cy - u * ph / 2, cy + u * ph / 2};
        }
    };
    scale();
    auto X = [&](double x) { return left + (x - xr.lo) / (xr.hi - xr.lo) * pw; };
    auto Y = [&](double y) { return top + ph - (y - yr.lo) / (yr.hi - yr.lo) * ph; };

    // The legend's place: the corner asked for if no line or marker passes under it, else the
    // first free corner, else outside the plot area: beside it, which then narrows (as
    // Legend::Right always is), or, for a legend wider than a third of the area (long labels,
    // which would squeeze the data into a strip), below the axis label, the area then shorter.
    // A legend never covers the data.
    std::vector<const Series*> named;
    for (const auto& s : c.series)
        if (!s.label.empty()) named.push_back(&s);
    Box legend{};
    if (!named.empty()) {
        cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
        cairo_set_font_size(cr, 11);
        double wmax = 0;
        for (const Series* s : named) {
            cairo_text_extents_t e;
            cairo_text_extents(cr, s->label.c_str(), &e);
            wmax = std::max(wmax, e.x_advance);
        }
        legend.w = wmax + 42;
        legend.h = 16.0 * static_cast<double>(named.size()) + 8;
        using L = Chart::Legend;
        auto corner = [&](L where) {
            const bool at_left = where == L::TopLeft || where == L::BottomLeft;
            const bool at_bottom = where == L::BottomRight || where == L::BottomLeft;
            return Box{at_left ? left + 8 : left + pw - legend.w - 8, at_bottom ? top + ph - legend.h - 8 : top + 8,
                       legend.w, legend.h};
        };
        // Free: no segment and no marker within reach of the box (half a line, a marker's radius,
        // and a pixel of antialiasing).
        auto clear_of_data = [&](const Box& b) {
            const Box reach{b.x - 4, b.y - 4, b.w + 8, b.h + 8};
            for (const auto& s : c.series) {
                const Point* prev = nullptr;
                for (const auto& p : s.points) {
                    if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
                        prev = nullptr;
                        continue;
                    }
                    const double px = X(p.x), py = Y(p.y);
                    if (meets(reach, prev ? X(prev->x) : px, prev ? Y(prev->y) : py, px, py)) return false;
                    prev = &p;
                }
            }
            return true;
        };
        bool placed = false;
        if (c.legend != L::Right) {
            for (const L where : {c.legend, L::TopRight, L::TopLeft, L::BottomRight, L::BottomLeft}) {
                legend = corner(where);
                if (clear_of_data(legend)) {
                    placed = true;
                    break;
                }
            }
        }
        if (!placed && (c.legend == L::Right || legend.w <= pw / 3)) {
            pw -= legend.w + 10;
            scale();
            legend.x = left + pw + 10;
            legend.y = c.legend == L::Right ? top + (ph - legend.h) / 2 : top;
        } else if (!placed) {
            ph -= legend.h + 8;
            scale();
            legend.x = std::max(8.0, left + (pw - legend.w) / 2);
            legend.y = top + ph + bottom;
        }
    }

    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);

    // Grid, ticks and their labels.
    cairo_set_line_width(cr, 1.0);
    const double xs = nice_step(xr.hi - xr.lo, 7), ys = nice_step(yr.hi - yr.lo, 6);
    for (double v : ticks(xr.lo, xr.hi, 7)) {
        cairo_set_source_rgb(cr, 0.9, 0.9, 0.9);
        cairo_move_to(cr, X(v), top);
        cairo_line_to(cr, X(v), top + ph);
        cairo_stroke(cr);
        cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
        cairo_move_to(cr, X(v), top + ph);
        cairo_line_to(cr, X(v), top + ph + 5);
        cairo_stroke(cr);
        text(cr, label(v, xs), X(v), top + ph + 8, 0.5, 0.0, 11);
    }
    for (double v : ticks(yr.lo, yr.hi, 6)) {
        cairo_set_source_rgb(cr, 0.9, 0.9, 0.9);
        cairo_move_to(cr, left, Y(v));
        cairo_line_to(cr, left + pw, Y(v));
        cairo_stroke(cr);
        cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
        cairo_move_to(cr, left - 5, Y(v));
        cairo_line_to(cr, left, Y(v));
        cairo_stroke(cr);
        text(cr, label(v, ys), left - 8, Y(v), 1.0, 0.5, 11);
    }
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    cairo_rectangle(cr, left, top, pw, ph);
    cairo_stroke(cr);
    text(cr, c.title, c.width / 2.0, 12, 0.5, 0.0, 15, true);
    text(cr, c.x_label, left + pw / 2, top + ph + bottom - 8, 0.5, 1.0, 12);  // under the ticks, above a legend below
    text(cr, c.y_label, 14, top + ph / 2, 0.5, 0.0, 12, false, -std::numbers::pi / 2);

    // Data, clipped to the plot area.
    cairo_save(cr);
    cairo_rectangle(cr, left, top, pw, ph);
    cairo_clip(cr);
    for (std::size_t i = 0; i < c.series.size(); ++i) {
        const Series& s = c.series[i];
        const Rgb col = kPalette[i % std::size(kPalette)];
        cairo_set_source_rgb(cr, col.r, col.g, col.b);
        cairo_set_line_width(cr, 1.6);
        // Round joins and caps: a motor's ringing turns the path back and forth by a step; mitred,
        // each turn would be drawn as a spike several line widths long.
        cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
        cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
        const double dash[] = {6.0, 4.0};
        cairo_set_dash(cr, dash, s.dashed ? 2 : 0, 0);
        bool pen = false;
        for (const auto& p : s.points) {
            if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
                pen = false;
                continue;
            }
            if (pen) cairo_line_to(cr, X(p.x), Y(p.y));
            else cairo_move_to(cr, X(p.x), Y(p.y));
            pen = true;
        }
        cairo_stroke(cr);
        cairo_set_dash(cr, nullptr, 0, 0);
        if (s.markers)
            for (const auto& p : s.points) {
                if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
                cairo_arc(cr, X(p.x), Y(p.y), 2.6, 0, 2 * std::numbers::pi);
                cairo_fill(cr);
            }
    }
    cairo_restore(cr);

    // The legend, where it was placed above.
    if (!named.empty()) {
        const double lh = 16, bx = legend.x, by = legend.y, bw = legend.w, bh = legend.h;
        cairo_set_source_rgba(cr, 1, 1, 1, 0.9);
        cairo_rectangle(cr, bx, by, bw, bh);
        cairo_fill_preserve(cr);
        cairo_set_source_rgb(cr, 0.6, 0.6, 0.6);
        cairo_set_line_width(cr, 0.8);
        cairo_stroke(cr);
        for (std::size_t i = 0; i < c.series.size(); ++i) {
            const Series& s = c.series[i];
            if (s.label.empty()) continue;
            const std::size_t row = static_cast<std::size_t>(std::find(named.begin(), named.end(), &s) - named.begin());
            const Rgb col = kPalette[i % std::size(kPalette)];
            const double yy = by + 4 + lh * (row + 0.5);
            cairo_set_source_rgb(cr, col.r, col.g, col.b);
            cairo_set_line_width(cr, 2.0);
            const double dash[] = {6.0, 4.0};
            cairo_set_dash(cr, dash, s.dashed ? 2 : 0, 0);
            cairo_move_to(cr, bx + 6, yy);
            cairo_line_to(cr, bx + 30, yy);
            cairo_stroke(cr);
            cairo_set_dash(cr, nullptr, 0, 0);
            cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
            text(cr, s.label, bx + 36, yy, 0.0, 0.5, 11);
        }
    }
    const bool svg = surf.svg();
    surf.finish();
    if (svg) add_svg_title(path, c.title);
}

// Rows of waveforms under a row of cycle names and one of T-state names, in the manner of Intel's
// data sheet figures: a wire high, low, floating (a line midway) or unspecified (hatched); a bus
// as a band that crosses where its value changes, the value written inside.
void draw_timing(const TimingDiagram& d, const std::string& path) {
    constexpr double kLeft = 90, kRight = 20, kTop = 64, kRow = 30, kHigh = 18, kBottom = 18;
    const double unit = std::clamp(900.0 / d.length, 14.0, 60.0);
    const int w = static_cast<int>(kLeft + d.length * unit + kRight);
    const int h = static_cast<int>(kTop + kRow * static_cast<double>(d.waves.size()) + kBottom);
    Surface surf(path, w, h);
    cairo_t* cr = surf.cr();
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    auto x_of = [&](double t) { return kLeft + t * unit; };
    cairo_set_source_rgb(cr, 0, 0, 0);
    text(cr, d.title, 8, 6, 0, 0, 13, true);
    // machine cycles and T-states, with a faint line at every T-state boundary
    for (const TimingDiagram::Span& s : d.spans) {
        cairo_set_source_rgb(cr, 0, 0, 0);
        text(cr, s.label, (x_of(s.from) + x_of(s.to)) / 2, 28, 0.5, 0.5, 11, true);
        cairo_set_source_rgb(cr, 0.35, 0.35, 0.35);
        cairo_set_line_width(cr, 1.2);
        cairo_move_to(cr, x_of(s.from), 20);
        cairo_line_to(cr, x_of(s.from), h - kBottom);
        cairo_stroke(cr);
    }
    for (const TimingDiagram::Tick& t : d.ticks) {
        cairo_set_source_rgb(cr, 0, 0, 0);
        text(cr, t.label, x_of(t.at + 0.5), 48, 0.5, 0.5, 10);
        cairo_set_source_rgb(cr, 0.85, 0.85, 0.85);
        cairo_set_line_width(cr, 0.6);
        cairo_move_to(cr, x_of(t.at), kTop - 6);
        cairo_line_to(cr, x_of(t.at), h - kBottom);
        cairo_stroke(cr);
    }
    for (std::size_t i = 0; i < d.waves.size(); ++i) {
        const TimingDiagram::Wave& wv = d.waves[i];
        const double top = kTop + kRow * static_cast<double>(i) + (kRow - kHigh) / 2, bottom = top + kHigh, mid = (top + bottom) / 2;
        cairo_set_source_rgb(cr, 0, 0, 0);
        text(cr, wv.name, 8, mid, 0, 0.5, 11);
        for (const TimingDiagram::Segment& s : wv.segments) {
            const double x0 = x_of(s.from), x1 = x_of(s.to), slant = std::min(3.0, (x1 - x0) / 4);
            cairo_set_line_width(cr, 1.4);
            cairo_set_source_rgb(cr, 0.05, 0.2, 0.6);
            if (s.level == 'x') {  // unspecified: hatched
                cairo_save(cr);
                cairo_rectangle(cr, x0, top, x1 - x0, kHigh);
                cairo_clip(cr);
                cairo_set_line_width(cr, 0.6);
                for (double x = x0 - kHigh; x < x1; x += 5) {
                    cairo_move_to(cr, x, bottom);
                    cairo_line_to(cr, x + kHigh, top);
                }
                cairo_stroke(cr);
                cairo_restore(cr);
                continue;
            }
            if (s.level == 'z') {  // floating
                cairo_move_to(cr, x0, mid);
                cairo_line_to(cr, x1, mid);
                cairo_stroke(cr);
                continue;
            }
            if (wv.bus) {  // a valid value: a band crossing at both ends
                cairo_move_to(cr, x0, mid);
                cairo_line_to(cr, x0 + slant, top);
                cairo_line_to(cr, x1 - slant, top);
                cairo_line_to(cr, x1, mid);
                cairo_line_to(cr, x1 - slant, bottom);
                cairo_line_to(cr, x0 + slant, bottom);
                cairo_close_path(cr);
                cairo_stroke(cr);
                cairo_set_source_rgb(cr, 0, 0, 0);
                text(cr, s.text, (x0 + x1) / 2, mid, 0.5, 0.5, 10);
                continue;
            }
            const double y = s.level == '1' ? top : bottom;
            cairo_move_to(cr, x0, y);
            cairo_line_to(cr, x1, y);
            cairo_stroke(cr);
        }
        // edges between wire segments
        if (!wv.bus)
            for (std::size_t k = 1; k < wv.segments.size(); ++k) {
                const char a = wv.segments[k - 1].level, b = wv.segments[k].level;
                if (a == b || a == 'x' || b == 'x') continue;
                const double x = x_of(wv.segments[k].from);
                auto y_of = [&](char l) { return l == '1' ? top : l == '0' ? bottom : mid; };
                cairo_move_to(cr, x, y_of(a));
                cairo_line_to(cr, x, y_of(b));
                cairo_stroke(cr);
            }
    }
    const bool svg = surf.svg();
    surf.finish();
    if (svg) add_svg_title(path, d.title);
}
#else
void draw(const Chart&, const std::string&) {}
void draw_timing(const TimingDiagram&, const std::string&) {}
#endif
}  // namespace

void write_toolpath(const std::string& path, const std::string& title, const std::vector<Series>& paths,
                    std::optional<std::pair<Point, Point>> ideal) {
    Chart c;
    c.title = title;
    c.x_label = "X (mm)";
    c.y_label = "Y (mm)";
    c.equal_scale = true;
    c.series = paths;
    if (ideal) c.series.push_back({"ideal", {ideal->first, ideal->second}, false, true});
    write(c, path);
}

void write_time_series(const std::string& path, const std::string& title, const std::vector<Series>& series,
                       const std::string& y_label, const std::string& t_label, Chart::Legend legend) {
    Chart c;
    c.legend = legend;
    c.title = title;
    c.x_label = t_label;
    c.y_label = y_label;
    c.series = series;
    write(c, path);
}

}  // namespace alp85::plot
