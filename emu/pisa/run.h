// A run of the Pisa interpolator on a tape: the computer, its tape reader and the two servo axes
// of the machine tool's X and Y tables, sampled at every pair of converter writes (the program's
// 6 ms outputs). `alp85 pisa`, the tests and the docs' figures use it.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "emu/pisa/interpolator.h"
#include "emu/pisa/servo.h"
#include "emu/pisa/tape.h"

namespace alp85::pisa {

inline constexpr double kDigitStepSeconds = 100e-9;  // docs/pisa.md "Timing: digit steps"

struct RunParams {
    ServoAxis::Params x, y;              // default: the machine tool's X and Y tables, program zero
    TapeReader::Params reader{};         // at TapeLimits' start position
    // The guard against a program that never ends (a ROM of one's own, --rom): the run stops after
    // this many digit steps; 0 sizes it from the tape (guard_steps).
    std::uint64_t max_steps = 0;
    double settle_s = 0.3;               // the tables' record goes on this long after END
    std::uint16_t idle_first = 1, idle_last = 0;  // the program's waiting loop (none by default)
    RunParams();
};

struct Sample {
    std::uint64_t t = 0;                 // digit steps (100 ns)
    std::int64_t cmd_x_um = 0, cmd_y_um = 0;  // the converters after the write
    double x_mm = 0, y_mm = 0;           // the tables, from program zero
    std::uint64_t idle = 0;              // the program's waiting-loop steps so far
};

struct RunResult {
    Stop stop;
    std::vector<Sample> samples;         // one per Y write (X is written just before), then settling
    std::size_t output_samples = 0;      // samples before the settling ones
    std::uint64_t instructions = 0;
    std::uint64_t steps = 0;             // digit steps until END
    std::uint64_t max_steps = 0;         // the guard the run had
    std::uint64_t idle_steps = 0;        // of which in the waiting loop
    std::array<bool, kIndicators> indicators{};
    std::uint64_t last_word_read = 0;    // digit step the reader filled its last word
};

// The tape's own time, in digit steps: every element at its feedrate (rapids at TapeLimits::rapid)
// and every character read at the reader's speed, one after the other.
std::uint64_t tape_steps(const Tape& tape, const RunParams& p = RunParams());
// The default guard: twice the tape's own time and a minute. The program moves at the feedrate to
// within a 6 ms period an element and reads the next block while one runs, so a program that
// ends does so well inside it; a 700 mm line at F10 (70 minutes) gets 2 h 21 min.
std::uint64_t guard_steps(const Tape& tape, const RunParams& p = RunParams());

RunResult run_tape(const std::vector<std::uint32_t>& rom, const Tape& tape, const RunParams& p = RunParams());

// "t_ms,x_cmd_mm,y_cmd_mm,x_mm,y_mm", one row per sample.
std::string samples_csv(const RunResult& r);

}  // namespace alp85::pisa
