// The block-format tape: words, modal values, geometry checks, the reader's words.
#include "emu/pisa/tape.h"

#include <array>
#include <cctype>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

namespace alp85::pisa {
namespace {

struct Spec {
    char letter;
    LetterCode code;
    int digits;   // on tape
    bool signed_; // a sign character on tape
    bool length;  // µm or mm with a point
};

constexpr std::array<Spec, 7> kSpecs{{
    {'N', kN, 3, false, false}, {'G', kG, 2, false, false}, {'X', kX, 6, true, true},
    {'Y', kY, 6, true, true},   {'I', kI, 6, true, true},   {'J', kJ, 6, true, true},
    {'F', kF, 4, false, false},
}};

const Spec* spec_of(char c) {
    for (const auto& s : kSpecs)
        if (s.letter == c) return &s;
    return nullptr;
}

struct Parser {
    const TapeLimits& lim;
    ParsedTape out;
    int line = 0;

    // Modal state: the end point of the last move, the mode, the feedrate.
    std::int64_t x = 0, y = 0;
    int g = -1, f = 0;

    bool fail(int col, std::string msg) {
        out.error = TapeError{line, col, std::move(msg)};
        return false;
    }

    bool within_travel(double xmm, double ymm) const {
        double tx = lim.start_x_mm + xmm, ty = lim.start_y_mm + ymm;
        return tx >= -1e-9 && tx <= lim.travel_x_mm + 1e-9 && ty >= -1e-9 && ty <= lim.travel_y_mm + 1e-9;
    }

    bool block(std::string_view text);
    bool arc_checks(const Element& e, int col);
};

bool Parser::arc_checks(const Element& e, int col) {
    double i = static_cast<double>(e.cx - e.x0), j = static_cast<double>(e.cy - e.y0);
    double r = std::hypot(i, j);
    auto r_um = static_cast<std::int64_t>(std::floor(r));
    std::int64_t nl = near_limit_um(e.feed);
    if (r_um < lim.min_radius_um || r_um < 2 * nl)
        return fail(col, fmt::format("arc radius {:.3f} mm is below the smallest the program follows at F{} "
                                     "({:.3f} mm)", r / 1000, e.feed,
                                     static_cast<double>(std::max(lim.min_radius_um, 2 * nl)) / 1000));
    double re = std::hypot(static_cast<double>(e.x1 - e.cx), static_cast<double>(e.y1 - e.cy));
    if (std::abs(re - r) > 1.0)
        return fail(col, fmt::format("the arc's end point is {:.3f} mm from its centre, its start {:.3f} mm: "
                                     "not on one circle (1 µm allowed)", re / 1000, r / 1000));
    std::int64_t m = std::abs(e.x1 - e.x0) + std::abs(e.y1 - e.y0);
    if (m != 0 && m <= nl)
        return fail(col, fmt::format("the arc ends {} µm from its start (|dX|+|dY|): within the program's "
                                     "near-end window of {} µm at F{}; program a line or a full circle",
                                     m, nl, e.feed));
    // The arc's extent: its end points and every axis extreme it sweeps.
    double a0 = std::atan2(static_cast<double>(e.y0 - e.cy), static_cast<double>(e.x0 - e.cx));
    double a1 = std::atan2(static_cast<double>(e.y1 - e.cy), static_cast<double>(e.x1 - e.cx));
    double two_pi = 2 * std::numbers::pi;
    double sweep = e.kind == Element::Kind::Ccw ? a1 - a0 : a0 - a1;
    while (sweep <= 0) sweep += two_pi;
    if (m == 0) sweep = two_pi;
    for (int k = 0; k < 4; ++k) {
        double a = k * std::numbers::pi / 2;
        double d = e.kind == Element::Kind::Ccw ? a - a0 : a0 - a;
        while (d < 0) d += two_pi;
        while (d >= two_pi) d -= two_pi;
        if (d <= sweep) {
            double px = static_cast<double>(e.cx) + r * std::cos(a), py = static_cast<double>(e.cy) + r * std::sin(a);
            if (!within_travel(px / 1000, py / 1000))
                return fail(col, fmt::format("the arc leaves the tables' travel (it reaches X{:.3f} Y{:.3f} mm from "
                                             "program zero)", px / 1000, py / 1000));
        }
    }
    return true;
}

bool Parser::block(std::string_view text) {
    struct Got {
        bool seen = false;
        std::int64_t v = 0;
        int col = 0;
    };
    std::array<Got, 9> got{};  // by letter code
    std::vector<TapeWord> words;
    std::size_t i = 0;
    int first_col = 0;
    while (i < text.size()) {
        char c = text[i];
        if (c == ' ' || c == '\t') {
            ++i;
            continue;
        }
        int col = static_cast<int>(i) + 1;
        if (!first_col) first_col = col;
        char up = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        const Spec* s = spec_of(up);
        if (!s) {
            if (std::isalpha(static_cast<unsigned char>(c)))
                return fail(col, fmt::format("'{}' is not a word of this tape format (N G X Y I J F)", c));
            return fail(col, fmt::format("unexpected character '{}': a word starts with its address letter", c));
        }
        if (got[s->code].seen) return fail(col, fmt::format("{} given twice in one block", s->letter));
        ++i;
        bool neg = false;
        int sign_col = static_cast<int>(i) + 1;
        if (i < text.size() && (text[i] == '+' || text[i] == '-')) {
            if (!s->signed_) return fail(sign_col, fmt::format("{} takes no sign", s->letter));
            neg = text[i] == '-';
            ++i;
        }
        std::size_t d0 = i;
        std::string whole, frac;
        bool point = false;
        while (i < text.size() && (std::isdigit(static_cast<unsigned char>(text[i])) || text[i] == '.')) {
            if (text[i] == '.') {
                if (point || !s->length) return fail(static_cast<int>(i) + 1, fmt::format("unexpected '.' in {}", s->letter));
                point = true;
            } else {
                (point ? frac : whole) += text[i];
            }
            ++i;
        }
        if (whole.empty() && frac.empty())
            return fail(static_cast<int>(d0) + 1, fmt::format("{} needs a number", s->letter));
        if (i < text.size() && text[i] != ' ' && text[i] != '\t' && !std::isalpha(static_cast<unsigned char>(text[i])))
            return fail(static_cast<int>(i) + 1, fmt::format("unexpected character '{}' in {}", text[i], s->letter));
        std::int64_t v = 0;
        if (point) {
            if (frac.size() > 3) return fail(col, fmt::format("{} has more than three decimals (1 µm)", s->letter));
            while (frac.size() < 3) frac += '0';
            std::string all = whole + frac;
            std::size_t nz = all.find_first_not_of('0');
            if (nz != std::string::npos && all.size() - nz > 6)
                return fail(col, fmt::format("{} is beyond 999.999 mm (six digits on tape)", s->letter));
            v = std::stoll(all.empty() ? "0" : all);
        } else {
            std::size_t nz = whole.find_first_not_of('0');
            if (nz != std::string::npos && whole.size() - nz > static_cast<std::size_t>(s->digits))
                return fail(col, s->length ? fmt::format("{} is beyond 999999 µm (six digits on tape)", s->letter)
                                           : fmt::format("{} has more than {} digits", s->letter, s->digits));
            v = nz == std::string::npos ? 0 : std::stoll(whole.substr(nz));
        }
        got[s->code] = {true, neg ? -v : v, col};
        words.push_back({static_cast<std::uint8_t>(s->code), neg && v != 0, static_cast<std::uint32_t>(v),
                         1 + (s->signed_ ? 1 : 0) + s->digits, line});
    }
    if (words.empty()) return true;

    if (got[kG].seen) {
        if (got[kG].v > 3) return fail(got[kG].col, fmt::format("G{:02d} is not one of G00 G01 G02 G03", got[kG].v));
        g = static_cast<int>(got[kG].v);
    }
    if (got[kF].seen) {
        auto fv = got[kF].v;
        if (fv < lim.f_min || fv > std::max(lim.f_max_line, lim.f_max_arc))
            return fail(got[kF].col, fmt::format("feedrate {} mm/min is outside {}-{}", fv, lim.f_min,
                                                 std::max(lim.f_max_line, lim.f_max_arc)));
        f = static_cast<int>(fv);
    }
    bool moves = got[kX].seen || got[kY].seen || got[kI].seen || got[kJ].seen;
    if (moves) {
        if (g < 0) return fail(first_col, "a move with no G mode (G00 G01 G02 G03) given yet");
        Element e;
        e.kind = g == 0 ? Element::Kind::Rapid : g == 1 ? Element::Kind::Line : g == 2 ? Element::Kind::Cw : Element::Kind::Ccw;
        e.line = line;
        e.x0 = x, e.y0 = y;
        e.x1 = got[kX].seen ? got[kX].v : x;
        e.y1 = got[kY].seen ? got[kY].v : y;
        if (g != 0 && f == 0) return fail(first_col, "a move with no feedrate (F) given yet");
        e.feed = g == 0 ? lim.rapid : f;
        int col = got[kX].seen ? got[kX].col : got[kY].seen ? got[kY].col : first_col;
        if (!e.arc() && (got[kI].seen || got[kJ].seen))
            return fail(got[kI].seen ? got[kI].col : got[kJ].col, "I and J belong to arcs (G02, G03)");
        if (e.arc()) {
            if (!got[kI].seen && !got[kJ].seen) return fail(first_col, "an arc needs its centre (I, J)");
            if (e.feed > lim.f_max_arc)
                return fail(got[kF].seen ? got[kF].col : first_col,
                            fmt::format("feedrate {} mm/min is above {} for arcs", e.feed, lim.f_max_arc));
            e.cx = x + got[kI].v;
            e.cy = y + got[kJ].v;
            if (!arc_checks(e, got[kI].seen ? got[kI].col : got[kJ].col)) return false;
        } else if (e.feed > lim.f_max_line) {
            return fail(got[kF].seen ? got[kF].col : first_col,
                        fmt::format("feedrate {} mm/min is above {} for lines", e.feed, lim.f_max_line));
        }
        if (!within_travel(static_cast<double>(e.x1) / 1000, static_cast<double>(e.y1) / 1000))
            return fail(col, fmt::format("X{:.3f} Y{:.3f} mm is outside the tables' travel from program zero "
                                         "(X {:.0f} to {:.0f}, Y {:.0f} to {:.0f} mm)",
                                         static_cast<double>(e.x1) / 1000, static_cast<double>(e.y1) / 1000,
                                         -lim.start_x_mm, lim.travel_x_mm - lim.start_x_mm, -lim.start_y_mm,
                                         lim.travel_y_mm - lim.start_y_mm));
        out.tape.elements.push_back(e);
        x = e.x1, y = e.y1;
    }
    for (auto& w : words) out.tape.words.push_back(w);
    out.tape.words.push_back({kEob, false, 0, 1, line});
    ++out.tape.blocks;
    return true;
}

}  // namespace

std::int64_t near_limit_um(int feed) { return 2 * (feed / 10 + 1) + 4; }

std::vector<PointMm> ideal_path_mm(const Tape& tape) {
    std::vector<PointMm> out;
    for (const auto& e : tape.elements) {
        if (out.empty()) out.push_back({static_cast<double>(e.x0) / 1000, static_cast<double>(e.y0) / 1000});
        if (e.arc()) {
            double cx = static_cast<double>(e.cx), cy = static_cast<double>(e.cy);
            double a0 = std::atan2(static_cast<double>(e.y0) - cy, static_cast<double>(e.x0) - cx);
            double a1 = std::atan2(static_cast<double>(e.y1) - cy, static_cast<double>(e.x1) - cx);
            double r = std::hypot(static_cast<double>(e.x0) - cx, static_cast<double>(e.y0) - cy);
            double two_pi = 2 * std::numbers::pi;
            double sweep = e.kind == Element::Kind::Ccw ? a1 - a0 : a0 - a1;
            while (sweep <= 0) sweep += two_pi;
            if (e.x0 == e.x1 && e.y0 == e.y1) sweep = two_pi;
            int n = std::max(2, static_cast<int>(std::ceil(sweep / (two_pi / 200))));
            double dir = e.kind == Element::Kind::Ccw ? 1 : -1;
            for (int k = 1; k <= n; ++k) {
                double a = a0 + dir * sweep * k / n;
                out.push_back({(cx + r * std::cos(a)) / 1000, (cy + r * std::sin(a)) / 1000});
            }
        }
        out.push_back({static_cast<double>(e.x1) / 1000, static_cast<double>(e.y1) / 1000});
    }
    return out;
}

ParsedTape parse_tape(std::string_view text, const TapeLimits& limits) {
    Parser p{limits, {}};
    std::size_t start = 0;
    while (start <= text.size()) {
        ++p.line;
        std::size_t nl = text.find('\n', start);
        std::string_view l = text.substr(start, nl == std::string_view::npos ? std::string_view::npos : nl - start);
        if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
        // Comments: ( ... ) and from ';' on; a '%' line is the rewind stop.
        std::string clean(l);
        if (auto semi = clean.find(';'); semi != std::string::npos) clean.resize(semi);
        for (std::size_t open = clean.find('('); open != std::string::npos; open = clean.find('(')) {
            std::size_t close = clean.find(')', open);
            if (close == std::string::npos) {
                p.out.error = TapeError{p.line, static_cast<int>(open) + 1, "comment not closed by ')'"};
                return std::move(p.out);
            }
            for (std::size_t k = open; k <= close; ++k) clean[k] = ' ';
        }
        std::string_view c = clean;
        auto first = c.find_first_not_of(" \t");
        if (first != std::string_view::npos && c[first] == '%') {
            // the rewind stop (the rest of its line is not read)
        } else if (!p.block(c)) {
            return std::move(p.out);
        }
        if (nl == std::string_view::npos) break;
        start = nl + 1;
    }
    if (p.out.tape.elements.empty() && !p.out.error) p.out.error = TapeError{1, 1, "the tape holds no move"};
    return std::move(p.out);
}

}  // namespace alp85::pisa
