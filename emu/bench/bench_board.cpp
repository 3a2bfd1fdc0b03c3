#include "emu/bench/bench_board.h"

#include <algorithm>

#include "board_bench_program_embed.h"

namespace alp85 {

BoardBench::BoardBench() : ram_(0x10000, 0), bare_cpu_(bus_) {
    const auto* program = bench::kBoardBenchProgram;
    const auto size = bench::kBoardBenchProgram_size;
    const auto origin = bench::kBoardBenchProgram_origin;
    std::copy_n(program, size, ram_.begin() + origin);
    // ROM where the board has its monitor: the bare core then runs the same page-table loop as the
    // board (all 64 KiB of RAM would take the core's flat-RAM loop, which a board never runs), so
    // the comparison is of the peripherals alone. The workload does not write below 0800H.
    bus_.map_ram(0, 0x10000, ram_.data());
    bus_.map_rom(0, 0x0800, ram_.data());
    bare_cpu_.reset();
    bare_cpu_.regs().pc = origin;

    board_.load(origin, std::span(program, size));
    board_.reset();
    board_.cpu().regs().pc = origin;
    // The board's overhead is measured on the interpreter alone: every DL iteration executed.
    bare_cpu_.set_fast_loops(false);
    board_.cpu().set_fast_loops(false);
}

std::uint64_t BoardBench::run_bare(std::uint64_t tstates) { return bare_cpu_.run(bare_cpu_.tstates() + tstates); }

std::uint64_t BoardBench::run_board(std::uint64_t tstates) {
    const std::uint64_t before = board_.now();
    board_.run_for(tstates);
    return board_.now() - before;
}

}  // namespace alp85
