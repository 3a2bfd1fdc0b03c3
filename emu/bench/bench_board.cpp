#include "emu/bench/bench_board.h"

#include "board_bench_program_embed.h"

namespace alp85 {

BoardBench::BoardBench()
    : bare_(Variant::I8085, std::span(bench::kBoardBenchProgram, bench::kBoardBenchProgram_size),
            bench::kBoardBenchProgram_origin) {
    const auto origin = bench::kBoardBenchProgram_origin;
    // ROM where the board has its monitor: the bare core then runs the same page-table loop as the
    // board (all 64 KiB of RAM would take the core's flat-RAM loop, which a board never runs), so
    // the comparison is of the peripherals alone. The workload does not write below 0800H.
    bare_.bus.map_rom(0, 0x0800, bare_.ram.data());
    bare_.cpu.reset();
    bare_.cpu.regs().pc = origin;

    board_.load(origin, std::span(bench::kBoardBenchProgram, bench::kBoardBenchProgram_size));
    board_.reset();
    board_.cpu().regs().pc = origin;
    // The board's overhead is measured on the interpreter alone: every DL iteration executed.
    board_.cpu().set_fast_loops(false);
}

std::uint64_t BoardBench::run_bare(std::uint64_t tstates) { return bare_.run(tstates); }

std::uint64_t BoardBench::run_board(std::uint64_t tstates) {
    const std::uint64_t before = board_.now();
    board_.run_for(tstates);
    return board_.now() - before;
}

}  // namespace alp85
