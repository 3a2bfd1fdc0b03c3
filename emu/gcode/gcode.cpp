#include "emu/gcode/gcode.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <numbers>

#include <fmt/format.h>

namespace alp85::gcode {

double eps_a(int cr, double radius) { return std::ldexp(radius, -2 * cr - 4); }

int choose_cr(double radius_steps) {
    int cr = 1;
    while (eps_a(cr, radius_steps) > 1.0) ++cr;
    return cr;
}

namespace {

struct Word {
    char letter = 0;
    double value = 0;
    int column = 0;
    std::int64_t e10 = 0;  // the value times 10^10, exactly (decimals past the tenth rounded)
};

constexpr const char* kAxisNames = "XYZ";
constexpr double kMaxWord = 100000;

// Lengths are kept exactly, in units of 10^-11 mm: a word with up to ten decimals, in mm (x 10)
// or in inches (x 254, 25.4 mm), is a whole number of them, so that G91's increments add up with
// no error and a position is rounded to a step once, as a G90 word is.
constexpr std::int64_t kUnitsPerStep = 5'000'000'000;  // 0.05 mm

// A number's digits (an optional sign, digits, at most one point) times 10^10.
std::int64_t times_e10(std::string_view num) {
    std::size_t i = 0;
    const bool negative = !num.empty() && num[0] == '-';
    if (!num.empty() && (num[0] == '+' || num[0] == '-')) ++i;
    std::int64_t v = 0;
    int decimals = -1;  // -1: before the point
    bool round_up = false;
    for (; i < num.size(); ++i) {
        if (num[i] == '.') {
            decimals = 0;
            continue;
        }
        const int d = num[i] - '0';
        if (decimals < 0) {
            v = v * 10 + d;  // below 100000: checked before
        } else if (decimals < 10) {
            v = v * 10 + d;
            ++decimals;
        } else if (decimals == 10) {
            round_up = d >= 5;
            ++decimals;
        }
    }
    for (decimals = std::max(decimals, 0); decimals < 10; ++decimals) v *= 10;
    if (round_up) ++v;
    return negative ? -v : v;
}

// To the nearest step, a half step away from zero.
long to_steps(std::int64_t units) {
    const std::int64_t half = kUnitsPerStep / 2;
    return static_cast<long>(units >= 0 ? (units + half) / kUnitsPerStep : -((half - units) / kUnitsPerStep));
}

class Parser {
public:
    Parsed run(std::string_view text) {
        int line_no = 0;
        std::size_t pos = 0;
        while (pos <= text.size() && !out_.error) {
            const std::size_t nl = text.find('\n', pos);
            std::string_view line = text.substr(pos, nl == std::string_view::npos ? std::string_view::npos : nl - pos);
            if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
            line_ = ++line_no;
            block(line);
            if (nl == std::string_view::npos) break;
            pos = nl + 1;
        }
        return std::move(out_);
    }

private:
    bool fail(int column, std::string message) {
        if (!out_.error) out_.error = Error{line_, column, std::move(message)};
        return false;
    }

    // Splits a line into words; false (with the error) on anything outside the subset's syntax.
    bool words(std::string_view s, std::vector<Word>& ws) {
        std::size_t i = 0;
        const auto trimmed_is = [&](char c) {
            const auto a = s.find_first_not_of(" \t");
            return a != std::string_view::npos && s[a] == c && s.find_first_not_of(" \t", a + 1) == std::string_view::npos;
        };
        if (trimmed_is('%')) return true;  // program start/end marker
        while (i < s.size()) {
            const char c = s[i];
            const int col = static_cast<int>(i) + 1;
            if (c == ' ' || c == '\t') {
                ++i;
            } else if (c == ';') {
                break;
            } else if (c == '(') {
                const auto close = s.find(')', i);
                if (close == std::string_view::npos) return fail(col, "comment not closed: '(' without ')'");
                if (!directive(s.substr(i + 1, close - i - 1), col)) return false;
                i = close + 1;
            } else if (std::isalpha(static_cast<unsigned char>(c))) {
                Word w{static_cast<char>(std::toupper(static_cast<unsigned char>(c))), 0, col};
                std::size_t j = i + 1;
                while (j < s.size() && (s[j] == ' ' || s[j] == '\t')) ++j;
                const std::size_t start = j;
                if (j < s.size() && (s[j] == '+' || s[j] == '-')) ++j;
                bool digits = false;
                while (j < s.size() && (std::isdigit(static_cast<unsigned char>(s[j])) || s[j] == '.')) {
                    digits = digits || s[j] != '.';
                    ++j;
                }
                if (!digits) return fail(col, fmt::format("'{}' needs a number", c));
                const std::string num(s.substr(start, j - start));
                if (std::count(num.begin(), num.end(), '.') > 1) return fail(col, fmt::format("bad number '{}'", num));
                w.value = std::strtod(num.c_str(), nullptr);
                // Five digits before the point, as NC controls read words: anything larger is
                // no length, feed or G number of this machine (and would overflow the steps).
                if (!(std::fabs(w.value) < kMaxWord))
                    return fail(col, fmt::format("{}{} is out of range (a word is below 100000)", w.letter,
                                                 num.size() > 24 ? num.substr(0, 20) + "..." : num));
                w.e10 = times_e10(num);
                ws.push_back(w);
                i = j;
            } else {
                return fail(col, fmt::format("unexpected character '{}'", c));
            }
        }
        return true;
    }

    // (METHOD SAMPLING), (METHOD THESIS), (RAMP ON), (RAMP OFF); other comments are free text.
    bool directive(std::string_view body, int col) {
        std::string t;
        for (char ch : body) t += static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
        const auto a = t.find_first_not_of(" \t");
        if (a == std::string::npos) return true;
        t = t.substr(a, t.find_last_not_of(" \t") - a + 1);
        if (t.rfind("METHOD", 0) == 0) {
            if (t == "METHOD SAMPLING") out_.method = Method::Sampling;
            else if (t == "METHOD THESIS") out_.method = Method::Thesis;
            else return fail(col, "(METHOD ...) takes SAMPLING or THESIS");
        } else if (t.rfind("RAMP", 0) == 0) {
            if (t == "RAMP ON") out_.ramp = true;
            else if (t == "RAMP OFF") out_.ramp = false;
            else return fail(col, "(RAMP ...) takes ON or OFF");
        }
        return true;
    }

    // A length word in the block's units, exactly (units of 10^-11 mm).
    std::int64_t length(const Word& w) const { return w.e10 * (inch_ ? 254 : 10); }

    bool in_travel(int axis, long v, int column) {
        if (v >= 0 && v <= kTravel[axis]) return true;
        return fail(column, fmt::format("{} {:.3f} mm is outside the table's travel (0 to {:.0f} mm)", kAxisNames[axis],
                                        v * kMmPerStep, kTravel[axis] * kMmPerStep));
    }

    void block(std::string_view s) {
        std::vector<Word> ws;
        if (!words(s, ws) || ws.empty()) return;
        std::array<const Word*, 26> seen{};
        std::optional<int> motion;
        const Word* motion_word = nullptr;
        for (std::size_t k = 0; k < ws.size(); ++k) {
            const Word& w = ws[k];
            if (w.letter == 'G') {
                const double g = w.value;
                const int gi = static_cast<int>(g);
                if (g != gi || (gi != 0 && gi != 1 && gi != 2 && gi != 3 && gi != 20 && gi != 21 && gi != 90 && gi != 91)) {
                    fail(w.column, fmt::format("G{} is not in the subset (G00 G01 G02 G03 G20 G21 G90 G91)", g));
                    return;
                }
                if (gi <= 3) {
                    if (motion_word) {
                        fail(w.column, "two motion words (G00-G03) in one block");
                        return;
                    }
                    motion = gi;
                    motion_word = &w;
                } else if (gi == 20 || gi == 21) {
                    inch_ = gi == 20;
                } else {
                    incremental_ = gi == 91;
                }
                continue;
            }
            if (w.letter == 'N') {
                if (k != 0) {
                    fail(w.column, "a line number (N) must open the block");
                    return;
                }
                continue;
            }
            if (std::string_view("XYZIJRF").find(w.letter) == std::string_view::npos) {
                fail(w.column, fmt::format("'{}' is not in the subset (G N X Y Z I J R F)", w.letter));
                return;
            }
            if (seen[w.letter - 'A']) {
                fail(w.column, fmt::format("'{}' twice in one block", w.letter));
                return;
            }
            seen[w.letter - 'A'] = &w;
        }
        if (const Word* f = seen['F' - 'A']) {
            // The table holds whole mm/min, and the firmware takes 6 to 1500 of them (SPEED, DLYK =
            // 1500 / F in a byte): the word is rounded first, then checked, so that the number in
            // a refusal is the one that is out of range.
            const double mm_min = f->value * (inch_ ? 25.4 : 1.0);
            const long whole = std::lround(mm_min);
            if (whole < 6 || whole > 1500) {
                fail(f->column, mm_min == static_cast<double>(whole)
                                    ? fmt::format("feedrate {} mm/min is outside the firmware's 6 to 1500 mm/min", whole)
                                    : fmt::format("feedrate {:g} mm/min, {} to the whole mm/min, is outside the firmware's "
                                                  "6 to 1500 mm/min", mm_min, whole));
                return;
            }
            feed_ = static_cast<std::uint16_t>(whole);
        }
        if (motion) mode_ = motion;
        const Word* ax[3] = {seen['X' - 'A'], seen['Y' - 'A'], seen['Z' - 'A']};
        const Word* wi = seen['I' - 'A'];
        const Word* wj = seen['J' - 'A'];
        const Word* wr = seen['R' - 'A'];
        if (!ax[0] && !ax[1] && !ax[2] && !wi && !wj && !wr) return;  // modes or F only
        const Word* first = ax[0] ? ax[0] : ax[1] ? ax[1] : ax[2] ? ax[2] : wi ? wi : wj ? wj : wr;
        if (!mode_) {
            fail(first->column, "a move with no motion mode (G00, G01, G02 or G03) yet");
            return;
        }
        const bool arc = *mode_ >= 2;
        if (!arc && (wi || wj || wr)) {
            fail((wi ? wi : wj ? wj : wr)->column, "I, J and R belong to arcs (G02, G03)");
            return;
        }
        // The programmed point exactly (G91: the last one plus the words), then rounded once.
        std::int64_t target[3] = {at_[0], at_[1], at_[2]};
        long end[3] = {pos_[0], pos_[1], pos_[2]};
        for (int a = 0; a < 3; ++a) {
            if (!ax[a]) continue;
            target[a] = (incremental_ ? at_[a] : 0) + length(*ax[a]);
            end[a] = to_steps(target[a]);
            if (!in_travel(a, end[a], ax[a]->column)) return;
        }
        const bool xy = end[0] != pos_[0] || end[1] != pos_[1];
        if (end[2] != pos_[2] && (xy || arc)) {
            fail(ax[2]->column, "Z moves on its own on this machine (the thesis sets Z apart): put it in a block of its own");
            return;
        }
        Entry e;
        e.feed = *mode_ == 0 ? 1500 : feed_;
        if (*mode_ != 0 && feed_ == 0) {
            fail((motion_word ? motion_word : first)->column, "no feedrate (F) for this move");
            return;
        }
        e.x = static_cast<std::uint16_t>(end[0]);
        e.y = static_cast<std::uint16_t>(end[1]);
        e.z = static_cast<std::uint16_t>(end[2]);
        if (!arc) {
            if (!xy && end[2] == pos_[2]) {  // no step: nothing to draw, but the point counts
                for (int a = 0; a < 3; ++a) at_[a] = target[a];
                return;
            }
            e.kind = *mode_ == 0 ? Kind::Rapid : Kind::Line;
        } else if (!plan_arc(e, end, wi, wj, wr, first)) {
            return;
        }
        out_.entries.push_back(e);
        for (int a = 0; a < 3; ++a) pos_[a] = end[a], at_[a] = target[a];
    }

    bool plan_arc(Entry& e, const long end[3], const Word* wi, const Word* wj, const Word* wr, const Word* first) {
        const bool ccw = *mode_ == 3;
        e.kind = ccw ? Kind::ArcCcw : Kind::ArcCw;
        const double sx = static_cast<double>(pos_[0]), sy = static_cast<double>(pos_[1]);
        const double ex = static_cast<double>(end[0]), ey = static_cast<double>(end[1]);
        double cx = 0, cy = 0;
        if (wr && (wi || wj)) return fail(wr->column, "an arc takes I and J or R, not both");
        if (wr) {
            const auto r = static_cast<double>(to_steps(length(*wr)));
            const double dx = ex - sx, dy = ey - sy, d = std::hypot(dx, dy);
            if (d == 0) return fail(wr->column, "R cannot give a full circle: use I and J");
            if (r == 0 || d > 2 * std::abs(r) + 1e-9)
                return fail(wr->column, fmt::format("no arc of radius {:.3f} mm joins the two points", r * kMmPerStep));
            const double h = std::sqrt(std::max(0.0, r * r - d * d / 4));
            // The centre is left of the chord for a short CCW arc, right for a short CW one.
            const double side = (ccw ? 1.0 : -1.0) * (r > 0 ? 1.0 : -1.0);
            cx = std::round((sx + ex) / 2 - side * h * dy / d);
            cy = std::round((sy + ey) / 2 + side * h * dx / d);
        } else if (wi || wj) {
            // I and J from the programmed start, rounded once as the end points are.
            cx = static_cast<double>(to_steps(at_[0] + (wi ? length(*wi) : 0)));
            cy = static_cast<double>(to_steps(at_[1] + (wj ? length(*wj) : 0)));
        } else {
            return fail(first->column, "an arc needs its centre (I, J) or its radius (R)");
        }
        const Word* where = wr ? wr : wi ? wi : wj;
        const double r0 = std::hypot(sx - cx, sy - cy), r1 = std::hypot(ex - cx, ey - cy);
        if (r0 < 1) return fail(where->column, "an arc of radius zero");
        if (std::abs(r0 - r1) > 1.0)
            return fail(where->column, fmt::format("the end point is not on the arc (radius {:.3f} mm at the start, {:.3f} mm at the end)",
                                                   r0 * kMmPerStep, r1 * kMmPerStep));
        if (cx < 0 || cy < 0 || cx > 65535 || cy > 65535) return fail(where->column, "the arc's centre is outside the table's travel");
        const double two_pi = 2 * std::numbers::pi;
        double theta = std::atan2(ey - cy, ex - cx) - std::atan2(sy - cy, sx - cx);
        if (!ccw) theta = -theta;
        theta = std::fmod(theta + 2 * two_pi, two_pi);
        if (theta < 1e-9) theta = two_pi;  // end = start: the whole circle
        const int cr = choose_cr(r0);
        const double dphi = std::ldexp(1.0, -cr);
        // Whole segments before the last one, which is (0, 2^-C_R] rad long and ends exactly at the end.
        const long n = static_cast<long>(std::ceil(theta / dphi - 1e-9)) - 1;
        // The arc, pushed out by eps_A (the first-point correction) and a step, must stay on the table.
        const double reach = r0 + eps_a(cr, r0) + 1;
        const double a0 = std::atan2(sy - cy, sx - cx);
        for (int k = 0; k <= 720; ++k) {
            const double a = a0 + (ccw ? 1 : -1) * theta * k / 720;
            const double p[2] = {cx + reach * std::cos(a), cy + reach * std::sin(a)};
            for (int ax = 0; ax < 2; ++ax)
                if (p[ax] < -0.5 || p[ax] > kTravel[ax] + 0.5)
                    return fail(where->column, fmt::format("the arc leaves the table's travel on {} (0 to {:.0f} mm)",
                                                           kAxisNames[ax], kTravel[ax] * kMmPerStep));
        }
        e.cr = static_cast<std::uint8_t>(cr);
        e.cx = static_cast<std::uint16_t>(cx);
        e.cy = static_cast<std::uint16_t>(cy);
        e.n = static_cast<std::uint16_t>(n);
        e.radius = r0;
        return true;
    }

    Parsed out_;
    int line_ = 0;
    bool inch_ = false;
    bool incremental_ = false;
    std::optional<int> mode_;
    std::uint16_t feed_ = 0;
    long pos_[3] = {0, 0, 0};            // where the tool stands, steps
    std::int64_t at_[3] = {0, 0, 0};     // the programmed point it stands for, exactly (10^-11 mm)
};

}  // namespace

Parsed parse(std::string_view text) { return Parser().run(text); }

namespace {

struct Geometry {
    double length = 0;        // of the polygon the sampling follows, steps
    double start[2] = {0, 0}; // unit tangents at the start and the end (0, 0: no X-Y motion)
    double end[2] = {0, 0};
};

// An entry's polygon (eqs. 8-11: the start, the vertices at R + eps_A every 2^-C_R rad, the end)
// and its tangents.
Geometry geometry(const Entry& e, double sx, double sy) {
    Geometry g;
    const double ex = e.x, ey = e.y;
    if (e.kind != Kind::ArcCw && e.kind != Kind::ArcCcw) {
        const double d = std::hypot(ex - sx, ey - sy);
        g.length = d;
        if (d > 0) g.start[0] = g.end[0] = (ex - sx) / d, g.start[1] = g.end[1] = (ey - sy) / d;
        return g;
    }
    const double s = e.kind == Kind::ArcCcw ? 1.0 : -1.0;
    const double r = std::hypot(sx - e.cx, sy - e.cy), rv = r * (1 + std::ldexp(1.0, -2 * e.cr - 4));
    const double a0 = std::atan2(sy - e.cy, sx - e.cx), dphi = std::ldexp(1.0, -e.cr);
    double px = sx, py = sy;
    for (int k = 1; k <= e.n; ++k) {
        const double a = a0 + s * dphi * k;
        const double vx = e.cx + rv * std::cos(a), vy = e.cy + rv * std::sin(a);
        g.length += std::hypot(vx - px, vy - py);
        px = vx, py = vy;
    }
    g.length += std::hypot(ex - px, ey - py);
    const double a1 = std::atan2(ey - e.cy, ex - e.cx);
    g.start[0] = -s * std::sin(a0), g.start[1] = s * std::cos(a0);
    g.end[0] = -s * std::sin(a1), g.end[1] = s * std::cos(a1);
    return g;
}

// F mm/min as steps a 2 ms sample, 0.16: 1500 mm/min is one step (65536, kept to FFFFH).
std::uint16_t feed_per_sample(std::uint16_t mm_min) {
    return static_cast<std::uint16_t>(std::min(65535L, std::lround(mm_min * 65536.0 / 1500.0)));
}

}  // namespace

std::vector<Entry> sampling_path(const std::vector<Entry>& path, bool ramp) {
    std::vector<Entry> out;
    std::size_t header = 0;
    double length = 0;
    const auto close = [&] {
        // The margin (1/32 of the length and 4 steps) covers C_x's table (16 entries: the feed up
        // to 1.6 % fast, the master's code space) and the chord lengths' rounding: the
        // deceleration ends early and the tool creeps in at F_MIN.
        const double l = std::clamp(length - length / 32 - 4, 0.0, 32767.0);
        const auto fixed = static_cast<std::uint32_t>(std::lround(l * 65536));
        out[header].x = static_cast<std::uint16_t>(fixed & 0xFFFF);
        out[header].y = static_cast<std::uint16_t>(fixed >> 16);
    };
    double x = 0, y = 0, z = 0, tangent[2] = {0, 0};
    std::uint16_t feed = 0;
    bool rapid = false;
    for (const Entry& e : path) {
        const Geometry g = geometry(e, x, y);
        const bool has_xy = g.length > 0;
        const bool z_move = e.z != z;
        const std::uint16_t f = feed_per_sample(e.feed);
        const bool corner = has_xy && (tangent[0] != 0 || tangent[1] != 0) &&
                            std::acos(std::clamp(tangent[0] * g.start[0] + tangent[1] * g.start[1], -1.0, 1.0)) > kCornerRad;
        if (out.empty() || z_move || corner || (has_xy && (f != feed || (e.kind == Kind::Rapid) != rapid))) {
            if (!out.empty()) close();
            Entry h;
            h.kind = Kind::Sample;
            h.cr = ramp ? 1 : 0;
            h.feed = f;
            header = out.size();
            out.push_back(h);
            length = 0;
            feed = f;
            rapid = e.kind == Kind::Rapid;
            if (z_move) tangent[0] = tangent[1] = 0;
        }
        out.push_back(e);
        length += g.length;
        if (has_xy) tangent[0] = g.end[0], tangent[1] = g.end[1];
        x = e.x, y = e.y, z = e.z;
    }
    if (!out.empty()) close();
    return out;
}

}  // namespace alp85::gcode
