// The board benchmark: one firmware-like workload (emu/bench/bench_board.asm, assembled at build time)
// on the bare core with a flat 64 KiB RAM, and on the ALP 85 board with its 8155 and 8279 idle.
// The ratio is what the board's scheduler costs. Used by `alp85 bench board` and tests/bench/board.
#pragma once

#include <cstdint>
#include <vector>

#include "emu/bench/bench_cpu.h"
#include "emu/board/machine.h"

namespace alp85 {

class BoardBench {
public:
    BoardBench();
    // Each runs its machine on for about `tstates` T-states; returns the T-states actually run.
    std::uint64_t run_bare(std::uint64_t tstates);
    std::uint64_t run_board(std::uint64_t tstates);
    const Machine& board() const { return board_; }

private:
    BareCore bare_;
    Machine board_;
};

}  // namespace alp85
