// What the table view draws beside the live axes: the toolpath so far (X-Y table positions in mm,
// from samples on the machine's sampling clock) and the ideal line of the thesis firmware's move.
//
// The ideal line: the thesis firmware keeps X1, Y1, X2, Y2 as 16-bit little-endian step counts at
// 1B00H, 1B03H, 1B06H, 1B09H (symbols X1, Y1, X2, Y2); a move takes the table by (X2-X1, Y2-Y1)
// steps from where it stood. A move is taken to start when the commanded X or Y steps change after
// at least kIdle of simulated time without a change; the line then runs from the commanded
// position before that change. Before any move the line is drawn from where the table stands.
// After clear() (a boot, a reset, a new workpiece) the table stands still: the first change seen
// starts a move. (Without this, a move begun less than kIdle after a reset had no start, and its
// line followed the table.)
// After restored() (a snapshot) the table may stand where a move ended or be in the middle of one:
// no line is drawn until a move is seen to begin, a change after kIdle standing; the workpiece is
// drawn as if the table stood where the last move (X2, Y2) ended, which holds at every prompt.
// A move begun less than kIdle after a restore therefore draws no line.
// Not done: a feed so slow that one step takes longer than kIdle re-anchors the line at each step.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "emu/debug/tool_record.h"
#include "emu/script/session.h"

namespace alp85::front {

// A part of the table in mm (x0 > x1: none).
struct Bounds {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // mm
    void add(double x, double y);
    bool empty() const { return x1 < x0; }
    static Bounds none() { return {1, 1, 0, 0}; }
};

struct PointMm {
    double x = 0, y = 0;
};

class Toolpath {
public:
    static constexpr std::uint64_t kIdle = board::tstates_from_ms(250);
    static constexpr std::size_t kMaxPoints = 100000;
    static constexpr double kWorkpieceW = 40, kWorkpieceH = 30;  // mm, from the thesis's origin

    // Where X1 lives (the rest follow 3 bytes apart); nullopt: no thesis variables, no line.
    void set_variables(std::optional<std::uint16_t> x1) { vars_at_ = x1; }
    void observe(const debug::ToolSample& sample, const script::Session& s);
    void clear();
    void restored();  // clear(), and the table's past is unknown

    const std::vector<PointMm>& points() const { return points_; }
    struct Line {
        PointMm from, to;
        PointMm origin;  // the thesis's coordinate origin on the table (X1,Y1 before `from`)
        bool started = false;
    };
    // The ideal line in table mm (with the commanded position `now_cmd` when no move has started).
    std::optional<Line> ideal(const script::Session& s) const;
    // The workpiece outline: kWorkpieceW x kWorkpieceH mm from the thesis's origin (the power-on
    // position when there is no line).
    Bounds workpiece(const script::Session& s) const;

private:
    std::optional<std::array<std::int32_t, 4>> read_vars(const script::Session& s) const;

    std::optional<std::uint16_t> vars_at_;
    std::vector<PointMm> points_;
    std::array<std::int64_t, 2> last_cmd_{};
    std::uint64_t last_change_ = 0;
    bool have_cmd_ = false;
    bool cleared_ = true;  // no change seen since clear(): the first one starts a move
    bool past_unknown_ = false;  // restored: no line until a move is seen to begin
    std::optional<std::array<std::int64_t, 2>> anchor_;  // commanded steps at the move's start
    std::array<std::int32_t, 4> anchor_vars_{};
};

}  // namespace alp85::front
