// A recording of the machine tool against simulated time: per axis the commanded steps (the
// sequencer's count), the table's position, the transducer's count, the lost steps and the phase
// pattern, sampled every `period` T-states on the machine's sampling clock. For `record FILE.csv`,
// the plots, and any front end that draws the tables.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "emu/board/machine.h"

namespace alp85::debug {

struct AxisSample {
    std::int64_t commanded = 0;
    double mm = 0;
    std::int64_t count = 0;
    std::int64_t lost = 0;
    std::uint8_t phases = 0;  // sequencer bits: 8 A, 4 /A, 2 B, 1 /B
};

struct ToolSample {
    std::uint64_t t = 0;  // T-state
    std::array<AxisSample, 3> axes{};
};

ToolSample sample_tool(const periph::MachineTool& tool, std::uint64_t t);

class ToolRecorder {
public:
    // The most samples a recording keeps (128 bytes each: 128 MB; 1000 s of machine time at one
    // sample a millisecond). `record every 1t` would otherwise take ~400 MB per simulated second
    // until memory ran out and the recording was lost; the samples beyond are dropped and full()
    // says so.
    static constexpr std::size_t kMaxSamples = 1'000'000;

    // Starts sampling `machine` (the first sample is now); stop() ends it. One recorder per machine.
    void start(Machine& machine, std::uint64_t period);
    void stop();
    bool recording() const { return machine_ != nullptr; }
    const std::vector<ToolSample>& samples() const { return samples_; }
    // The recording reached kMaxSamples: the samples after the first kMaxSamples were dropped.
    bool full() const { return full_; }

    // "t_ms,x_cmd,x_mm,x_count,x_lost,x_phases,y_cmd,..." one row per sample, written row by row
    // (a full recording is ~90 MB of text: never built as one string).
    void write_csv(std::ostream& out) const;

private:
    Machine* machine_ = nullptr;
    std::vector<ToolSample> samples_;
    bool full_ = false;
};

}  // namespace alp85::debug
