// The Pisa multi-purpose interpolator (CNR-IEI, 1969): a decimal three-address computer whose ROM
// program makes it an interpolator. Paper: ../shared/seeds/004_... ; reconstruction: docs/pisa.md.
//
// Pins and parts as modelled:
//   - RWM: 64 words of 8 excess-three cells (512 cells, §4), cleared to +0 at reset (choice: the
//     console's reset; real TTL arrays power up at random).
//   - ROM: up to 4096 words of 22 bits, fitted in packages of 64 (§4). Fetching outside the fitted
//     packages stops the machine with a fault.
//   - indicators (six-bit addresses, §2.3): 0 CLK the 6 ms time base (§4), 1 RDR the tape reader's
//     buffer-full flag, 2 RUN the reader's start, 3 EOT end of tape, 4 OVF arithmetic overflow,
//     5 END the program's end lamp (the run stops), 6..63 flip-flops for the program.
//   - input channel 0: the tape reader (tape_reader.h); output channels 1 and 2: the X and Y
//     converters (servo.h). Other channels read zeros and drop writes.
//   - time: digit steps (pisa_isa.h `steps`), 100 ns each.
//
// Not emulated: the micro-order ROM itself (instructions are executed whole with the step counts
// of the micro-program structure), the console beyond RESET/START and the END lamp, other devices.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "asm/pisa_isa.h"
#include "emu/pisa/tape_reader.h"
#include "emu/pisa/word.h"

namespace alp85::pisa {

enum Indicator : std::uint8_t { kClk = 0, kRdr = 1, kRun = 2, kEot = 3, kOvf = 4, kEnd = 5 };

inline constexpr std::uint64_t kClockSteps = 60'000;  // 6 ms at 100 ns a step

enum class StopReason : std::uint8_t { End, StepLimit, Fault };

struct Stop {
    StopReason reason = StopReason::End;
    std::string message;  // for a fault
};

class Interpolator {
public:
    // Output channel writes: channel, the whole converter register after the write, digit step.
    using OutputFn = std::function<void(int channel, const Word& value, std::uint64_t t)>;

    explicit Interpolator(std::vector<std::uint32_t> rom = {});
    void load_rom(std::vector<std::uint32_t> rom);
    void reset();  // PC 0, RWM +0, indicators 0, time 0, the reader rewound

    void step();                            // one instruction
    // Until END, a fault or max_steps digit steps. A two-instruction loop waiting on CLK or RDR
    // is turned through at once (the same times and counts as step by step).
    Stop run(std::uint64_t max_steps);

    std::uint64_t now() const { return now_; }
    std::uint16_t pc() const { return pc_; }
    std::uint64_t instructions() const { return executed_; }

    const Word& rwm(int address) const { return rwm_[static_cast<std::size_t>(address & 63)]; }
    bool indicator(int s) const;
    void set_indicator(int s, bool v);  // as SET/RST would
    TapeReader& reader() { return reader_; }
    const Word& output(int channel) const { return out_[static_cast<std::size_t>(channel & 63)]; }
    void on_output(OutputFn f) { on_output_ = std::move(f); }
    // Input channels other than the reader: a fixed word in external BCD digits (console switches).
    void set_input(int channel, const std::array<std::uint8_t, 8>& bcd) {
        in_[static_cast<std::size_t>(channel & 63)] = bcd;
    }
    // Digit steps spent in instructions fetched from [first, last]: a program's waiting loop, so
    // that the rest is its computing time.
    void count_idle(std::uint16_t first, std::uint16_t last) { idle_first_ = first, idle_last_ = last; }
    std::uint64_t idle_steps() const { return idle_; }

private:
    void sync();  // the clock and the reader up to now_
    bool skip_wait(std::uint64_t limit);  // a waiting loop's turns at once
    void exec(std::uint32_t word);

    std::vector<std::uint32_t> rom_;
    std::array<Word, kRwmWords> rwm_{};
    std::array<bool, kIndicators> ind_{};
    std::array<Word, kChannels> out_{};
    std::array<std::array<std::uint8_t, 8>, kChannels> in_{};
    TapeReader reader_;
    OutputFn on_output_;
    std::uint16_t pc_ = 0;
    std::uint64_t now_ = 0;
    std::uint64_t executed_ = 0;
    std::uint64_t next_tick_ = ~std::uint64_t{0};  // the time base stopped until SET CLK
    std::optional<std::string> fault_;
    std::uint16_t idle_first_ = 1, idle_last_ = 0;  // empty
    std::uint64_t idle_ = 0;
};

}  // namespace alp85::pisa
