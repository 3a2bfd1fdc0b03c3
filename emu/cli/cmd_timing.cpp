// alp85 timing "MVI A,32H" [--at ADDR] [--interrupt rst7.5] [--svg F] [--png F] [--vcd F]: the
// machine cycles of one instruction (or of an interrupt acknowledge) as the 8085 data sheet draws
// them, as text, and as a timing diagram (emu/plot) or a VCD (emu/debug/bus_cycles.h).
#include <array>
#include <iostream>
#include <memory>

#include <fmt/format.h>

#include "asm/asm85.h"
#include "emu/cli/commands.h"
#include "emu/debug/bus_cycles.h"
#include "emu/plot/plot.h"
#include "emu/script/parser.h"

namespace alp85::cli {

namespace {

struct TimingArgs {
    std::string instruction, at = "0800H", interrupt, svg, png, vcd;
};

// The timing diagram of `cycles`, in T-states, from their waveforms.
plot::TimingDiagram diagram(const std::vector<debug::BusCycle>& cycles, const std::string& title) {
    const debug::Waveforms w = debug::waveforms(cycles);
    plot::TimingDiagram d;
    d.title = title;
    d.length = w.half_tstates / 2.0;
    double at = 0;
    int n = 0;
    for (const debug::BusCycle& c : cycles) {
        d.spans.push_back({at, at + c.tstates, fmt::format("M{} {}", ++n, debug::cycle_name(c.type))});
        for (int t = 0; t < c.tstates; ++t) d.ticks.push_back({at + t, fmt::format("T{}", t + 1)});
        at += c.tstates;
    }
    auto add_wire = [&](const std::string& name, const std::string& levels) {
        plot::TimingDiagram::Wave wave{name, false, {}};
        for (std::size_t h = 0; h < levels.size(); ++h) {
            if (!wave.segments.empty() && wave.segments.back().level == levels[h]) wave.segments.back().to = (h + 1) / 2.0;
            else wave.segments.push_back({h / 2.0, (h + 1) / 2.0, levels[h], {}});
        }
        d.waves.push_back(std::move(wave));
    };
    auto add_bus = [&](const std::string& name, const std::vector<int>& bytes) {
        plot::TimingDiagram::Wave wave{name, true, {}};
        int last = -3;
        for (std::size_t h = 0; h < bytes.size(); ++h) {
            const int b = bytes[h];
            if (b == last && !wave.segments.empty()) {
                wave.segments.back().to = (h + 1) / 2.0;
                continue;
            }
            last = b;
            wave.segments.push_back({h / 2.0, (h + 1) / 2.0, b == -1 ? 'z' : b == -2 ? 'x' : 'v', b >= 0 ? fmt::format("{:02X}H", b) : ""});
        }
        d.waves.push_back(std::move(wave));
    };
    for (std::size_t i = 0; i < w.names.size(); ++i) {
        const std::string& name = w.names[i];
        add_wire(name == "RD" || name == "WR" || name == "INTA" ? "/" + name : name, w.levels[i]);
    }
    add_bus("A15-A8", w.bus_high);
    add_bus("AD7-AD0", w.bus_low);
    return d;
}

int run_timing(const TimingArgs& a) {
    std::string why;
    int col = 1;
    const auto at = script::parse_value(a.at, "an address", true, why, col);
    if (!at || at->expression || at->number < 0 || at->number > 0xFFFF) {
        std::cerr << cli::argument_error("alp85 timing", a.at,
                                    why.empty() ? fmt::format("'{}' is not an address (0000H-0FFFFH)", a.at) : why);
        return kUsageError;
    }
    if (a.instruction.empty() == a.interrupt.empty()) {
        std::cerr << "alp85 timing: give one instruction (e.g. \"MVI A,32H\") or --interrupt\n";
        return kUsageError;
    }
    Registers r;  // every register 0 (the flags too: Jcc/Ccc/Rcc as their flag says), PC at --at
    r.pc = static_cast<std::uint16_t>(at->number);
    std::array<std::uint8_t, 0x10000> memory;
    memory.fill(0xFF);
    std::vector<debug::BusCycle> cycles;
    std::string title;
    if (!a.instruction.empty()) {
        asm85::Options opt;
        opt.cpu = asm85::Cpu::i8085u;
        const std::string source = fmt::format("\tORG {:04X}H\n\t{}\n", r.pc, a.instruction);
        const asm85::Result res = asm85::assemble_string(source, opt, "instruction");
        for (const asm85::Diagnostic& d : res.diagnostics)
            if (d.severity == asm85::Severity::Error) {
                std::cerr << cli::argument_error("alp85 timing", a.instruction, d.message);
                return kUsageError;
            }
        if (res.image.empty() || res.image.lowest() != r.pc) {
            std::cerr << cli::argument_error("alp85 timing", a.instruction, "not an instruction (it assembles to no code)");
            return kUsageError;
        }
        for (const asm85::Segment& s : res.image.segments())
            for (std::size_t i = 0; i < s.bytes.size(); ++i) memory[static_cast<std::uint16_t>(s.start + i)] = s.bytes[i];
        cycles = debug::instruction_cycles(r, [&](std::uint16_t addr) { return memory[addr]; });
        title = fmt::format("{} at {:04X}H", a.instruction, r.pc);
    } else {
        if (a.interrupt != "rst7.5" && a.interrupt != "rst6.5" && a.interrupt != "rst5.5" && a.interrupt != "trap") {
            std::cerr << cli::argument_error("alp85 timing", a.interrupt, "--interrupt takes rst7.5, rst6.5, rst5.5 or trap");
            return kUsageError;
        }
        cycles = debug::restart_ack_cycles(r);
        title = fmt::format("{} acknowledged before the instruction at {:04X}H", a.interrupt == "trap" ? "TRAP" : "RST " + a.interrupt.substr(3), r.pc);
    }
    std::cout << title << '\n' << debug::cycles_text(cycles);
    // A file that cannot be written throws: on_run reports it (status 1).
    if (!a.svg.empty()) plot::write_timing(diagram(cycles, title), a.svg);
    if (!a.png.empty()) plot::write_timing(diagram(cycles, title), a.png);
    if (!a.vcd.empty()) debug::write_cycles_vcd(cycles, a.vcd, title);
    return 0;
}

}  // namespace

void add_timing_command(CLI::App& app, int& status) {
    Subcommand<TimingArgs> cmd(app, "timing", "The machine cycles of an instruction as the 8085 data sheet draws them");
    cmd->add_option("instruction", cmd.args->instruction, "One instruction in asm85's syntax, e.g. \"MVI A,32H\" or \"STA 2050H\"");
    cmd->add_option("--at", cmd.args->at, "Its address (default 0800H)");
    cmd->add_option("--interrupt", cmd.args->interrupt, "Draw the acknowledge of rst7.5, rst6.5, rst5.5 or trap instead");
    cmd.output("--svg", cmd.args->svg, "Draw the timing diagram to an SVG file");
    cmd.output("--png", cmd.args->png, "Draw the timing diagram to a PNG file");
    cmd.output("--vcd", cmd.args->vcd, "Write the waveforms as a VCD file (GTKWave, PulseView)");
    cmd->footer(
        "Each machine cycle with IO/M, S1 S0, its strobes and A15-A8, AD7-AD0; the diagrams show CLK, ALE,\n"
        "IO/M, S1, S0, /RD, /WR, /INTA and the buses T-state by T-state (T1...T6). The registers are 0 (SP too:\n"
        "a push writes FFFFH and FFFEH); the debugger's `timing` uses the machine's. docs/signals.md.\n"
        "Examples:\n"
        "  alp85 timing \"MVI A,32H\"\n"
        "  alp85 timing \"STA 2050H\" --svg sta.svg\n"
        "  alp85 timing --interrupt rst7.5 --vcd ack.vcd\n"
        "Exit status: 0 success, 1 a file could not be written, 2 a usage error or an instruction that does not\n"
        "assemble.");
    cmd.run(status, [](const TimingArgs& a) {
        // Two drawings on one file; the options not given are empty and not compared.
        const bool clash = refuse_output_clash("timing", {}, {{a.svg, "--svg"}, {a.png, "--png"}, {a.vcd, "--vcd"}});
        return clash ? kUsageError : run_timing(a);
    });
}

}  // namespace alp85::cli
