#include "emu/debug/bus_cycles.h"

#include <stdexcept>

#include <fmt/format.h>

#include "asm/isa.h"
#include "emu/board/board_map.h"
#include "asm/files/atomic_file.h"

namespace alp85::debug {

using isa::MachineCycle;

std::string_view cycle_name(MachineCycle c) {
    switch (c) {
        case MachineCycle::Fetch4:
        case MachineCycle::Fetch6: return "opcode fetch";
        case MachineCycle::MemRead: return "memory read";
        case MachineCycle::MemWrite: return "memory write";
        case MachineCycle::IoRead: return "I/O read";
        case MachineCycle::IoWrite: return "I/O write";
        case MachineCycle::BusIdle: return "bus idle";
        case MachineCycle::Halt: return "halt";
        case MachineCycle::IntAck: return "interrupt acknowledge";
        case MachineCycle::AckIdle: return "bus idle (RST/TRAP acknowledge)";
    }
    return "?";
}

// The data sheet's machine cycle chart (IO/M, S1, S0 and the control lines).
BusStatus bus_status(MachineCycle c) {
    switch (c) {
        case MachineCycle::Fetch4:
        case MachineCycle::Fetch6: return {'0', '1', '1', true, false, false, true};
        case MachineCycle::MemRead: return {'0', '1', '0', true, false, false, true};
        case MachineCycle::MemWrite: return {'0', '0', '1', false, true, false, true};
        case MachineCycle::IoRead: return {'1', '1', '0', true, false, false, true};
        case MachineCycle::IoWrite: return {'1', '0', '1', false, true, false, true};
        case MachineCycle::IntAck: return {'1', '1', '1', false, false, true, true};
        case MachineCycle::BusIdle: return {'0', '1', '0', false, false, false, false};   // DAD
        case MachineCycle::AckIdle: return {'1', '1', '1', false, false, false, false};   // ACK. of RST, TRAP
        case MachineCycle::Halt: return {'z', '0', '0', false, false, false, false};
    }
    return {'x', 'x', 'x', false, false, false, false};
}

bool condition_taken(std::uint8_t opcode, std::uint8_t f) {
    const isa::OpInfo& info = isa::kOpcodes[opcode];
    switch (info.flow) {
        case isa::Flow::JumpIf:
        case isa::Flow::CallIf:
        case isa::Flow::ReturnIf: break;
        case isa::Flow::RestartIf: return (f & isa::F_V) != 0;  // RSTV
        default: return true;
    }
    if (opcode == 0xDD) return (f & isa::F_K) == 0;  // JNK
    if (opcode == 0xFD) return (f & isa::F_K) != 0;  // JK
    static constexpr std::uint8_t kFlag[4] = {isa::F_Z, isa::F_CY, isa::F_P, isa::F_S};  // NZ/Z, NC/C, PO/PE, P/M
    const int cc = (opcode >> 3) & 7;
    return ((f & kFlag[cc >> 1]) != 0) == ((cc & 1) != 0);
}

namespace {

std::uint8_t reg_value(const Registers& r, int code) {
    switch (code) {
        case 0: return r.b;
        case 1: return r.c;
        case 2: return r.d;
        case 3: return r.e;
        case 4: return r.h;
        case 5: return r.l;
        default: return r.a;  // 7 (6 is M: not asked here)
    }
}

std::uint16_t pair_value(const Registers& r, int code) {  // B, D, H, SP (PSW is PUSH's own)
    switch (code) {
        case 0: return r.bc();
        case 1: return r.de();
        case 2: return r.hl();
        default: return r.sp;
    }
}

// The accesses after the opcode fetch, in order: what the data sheet's cycles carry.
struct Access {
    std::uint16_t address;
    bool has_data;
    std::uint8_t data;
    std::string what;
};

std::vector<Access> accesses(const Registers& r, const Peek& peek, std::uint8_t op, bool taken) {
    const std::uint16_t pc = r.pc;
    auto at = [](int v) { return static_cast<std::uint16_t>(v); };
    auto read = [&](std::uint16_t a, std::string what) { return Access{a, true, peek(a), std::move(what)}; };
    auto write = [](std::uint16_t a, std::uint8_t v, std::string what) { return Access{a, true, v, std::move(what)}; };
    const std::uint16_t a16 = static_cast<std::uint16_t>(peek(at(pc + 2)) << 8 | peek(at(pc + 1)));
    const std::uint8_t b1 = peek(at(pc + 1));
    const std::uint16_t sp = r.sp, hl = r.hl();
    auto push = [&](std::uint16_t v, const char* hi, const char* lo) {
        return std::vector<Access>{write(at(sp - 1), static_cast<std::uint8_t>(v >> 8), hi),
                                   write(at(sp - 2), static_cast<std::uint8_t>(v), lo)};
    };
    auto operands = [&](int n) {
        std::vector<Access> v;
        if (n >= 1) v.push_back(read(at(pc + 1), n == 1 ? "operand" : "operand, low byte"));
        if (n >= 2) v.push_back(read(at(pc + 2), "operand, high byte"));
        return v;
    };
    auto join = [](std::vector<Access> a, const std::vector<Access>& b) {
        a.insert(a.end(), b.begin(), b.end());
        return a;
    };
    const int dst = (op >> 3) & 7, src = op & 7, rp = (op >> 4) & 3;
    const isa::OpInfo& info = isa::kOpcodes[op];
    const std::string_view m = info.mnemonic;
    if (m == "MOV") {
        if (src == 6) return {read(hl, "from M (HL)")};
        if (dst == 6) return {write(hl, reg_value(r, src), "to M (HL)")};
        return {};
    }
    if (m == "MVI") return dst == 6 ? std::vector<Access>{read(at(pc + 1), "operand"), write(hl, b1, "to M (HL)")} : operands(1);
    if (m == "INR" || m == "DCR") {
        if (dst != 6) return {};
        const std::uint8_t v = peek(hl);
        return {read(hl, "M (HL)"), write(hl, static_cast<std::uint8_t>(m == "INR" ? v + 1 : v - 1), "M (HL), changed")};
    }
    if (info.operands == "M") return {read(hl, "M (HL)")};  // ADD M ... CMP M
    if (m == "LXI" || m == "JMP" || m == "LDHI" || m == "LDSI") return operands(m == "LXI" || m == "JMP" ? 2 : 1);
    if (m == "STAX") return {write(pair_value(r, rp), r.a, "A")};
    if (m == "LDAX") return {read(pair_value(r, rp), "to A")};
    if (m == "STA") return join(operands(2), {write(a16, r.a, "A")});
    if (m == "LDA") return join(operands(2), {read(a16, "to A")});
    if (m == "SHLD") return join(operands(2), {write(a16, r.l, "L"), write(at(a16 + 1), r.h, "H")});
    if (m == "LHLD") return join(operands(2), {read(a16, "to L"), read(at(a16 + 1), "to H")});
    if (m == "SHLX") return {write(r.de(), r.l, "L"), write(at(r.de() + 1), r.h, "H")};
    if (m == "LHLX") return {read(r.de(), "to L"), read(at(r.de() + 1), "to H")};
    if (m == "PUSH")
        return rp == 3 ? push(static_cast<std::uint16_t>(r.a << 8 | r.f), "A", "flags") : push(pair_value(r, rp), "high byte", "low byte");
    if (m == "POP" || m == "RET" || (info.flow == isa::Flow::ReturnIf && taken))
        return {read(sp, m == "POP" ? "low byte" : "return address, low"), read(at(sp + 1), m == "POP" ? "high byte" : "return address, high")};
    if (m == "XTHL")
        return {read(sp, "to L"), read(at(sp + 1), "to H"), write(at(sp + 1), r.h, "H"), write(sp, r.l, "L")};
    if (m == "CALL" || (info.flow == isa::Flow::CallIf && taken))
        return join(operands(2), push(at(pc + 3), "return address, high", "return address, low"));
    if (info.flow == isa::Flow::CallIf || info.flow == isa::Flow::JumpIf) return operands(taken ? 2 : 1);
    if (m == "RST" || (m == "RSTV" && taken)) return push(at(pc + 1), "return address, high", "return address, low");
    if (m == "OUT") return {read(at(pc + 1), "port"), Access{static_cast<std::uint16_t>(b1 << 8 | b1), true, r.a, "A"}};
    if (m == "IN") return {read(at(pc + 1), "port"), Access{static_cast<std::uint16_t>(b1 << 8 | b1), false, 0, "to A"}};
    if (info.length > 1) return operands(info.length - 1);  // ADI ... CPI
    return {};
}

}  // namespace

std::vector<BusCycle> instruction_cycles(const Registers& r, const Peek& peek) {
    const std::uint8_t op = peek(r.pc);
    const bool taken = condition_taken(op, r.f);
    const isa::CycleList list = isa::cycles_of(op, taken);
    const std::vector<Access> acc = accesses(r, peek, op, taken);
    std::vector<BusCycle> out;
    std::size_t next = 0;
    const isa::OpInfo& info = isa::kOpcodes[op];
    for (int i = 0; i < list.count; ++i) {
        BusCycle c;
        c.type = list.cycles[static_cast<std::size_t>(i)];
        c.tstates = isa::tstates_of(c.type);
        switch (c.type) {
            case MachineCycle::Fetch4:
            case MachineCycle::Fetch6:
                c.has_address = c.has_data = true;
                c.address = r.pc;
                c.data = op;
                c.what = fmt::format("opcode {:02X}H: {}{}{}", op, info.mnemonic, info.operands.empty() ? "" : " ", info.operands);
                break;
            case MachineCycle::MemRead:
            case MachineCycle::MemWrite:
            case MachineCycle::IoRead:
            case MachineCycle::IoWrite:
                if (next < acc.size()) {
                    const Access& a = acc[next++];
                    c.has_address = true;
                    c.address = a.address;
                    c.has_data = a.has_data;
                    c.data = a.data;
                    c.what = a.what;
                }
                break;
            default: break;
        }
        out.push_back(std::move(c));
    }
    if (next != acc.size())
        throw std::logic_error(fmt::format("bus cycles of {:02X}H: {} accesses for its cycles", op, acc.size()));
    return out;
}

std::vector<BusCycle> restart_ack_cycles(const Registers& r) {
    std::vector<BusCycle> out;
    const isa::CycleList list = isa::parse_cycles(isa::kAckRst);
    const std::uint16_t sp = r.sp;
    for (int i = 0; i < list.count; ++i) {
        BusCycle c;
        c.type = list.cycles[static_cast<std::size_t>(i)];
        c.tstates = isa::tstates_of(c.type);
        if (i == 0) c.what = "no INTA: the restart is internal";
        if (i > 0) {
            c.has_address = c.has_data = true;
            c.address = static_cast<std::uint16_t>(sp - i);
            c.data = static_cast<std::uint8_t>(i == 1 ? r.pc >> 8 : r.pc);
            c.what = i == 1 ? "return address, high" : "return address, low";
        }
        out.push_back(std::move(c));
    }
    return out;
}

std::string cycles_text(const std::vector<BusCycle>& cycles) {
    std::string out;
    int n = 0, total = 0;
    for (const BusCycle& c : cycles) {
        const BusStatus s = bus_status(c.type);
        std::string strobes;
        if (s.rd) strobes += "RD";
        if (s.wr) strobes += "WR";
        if (s.inta) strobes += "INTA";
        out += fmt::format("M{}  {:<32} T1-T{}  IO/M={} S1,S0={},{}  {:<4}", ++n, cycle_name(c.type), c.tstates, s.io_m, s.s1,
                           s.s0, strobes);
        if (c.has_address) out += fmt::format("  A15-A8={:02X}H AD7-AD0={:02X}H,", c.address >> 8, c.address & 0xFF);
        if (c.has_address) out += c.has_data ? fmt::format("{:02X}H", c.data) : std::string("??");
        if (!c.what.empty()) out += fmt::format("  ({})", c.what);
        out += '\n';
        total += c.tstates;
    }
    out += fmt::format("{} machine cycle{}, {} T-states\n", cycles.size(), cycles.size() == 1 ? "" : "s", total);
    return out;
}

Waveforms waveforms(const std::vector<BusCycle>& cycles) {
    Waveforms w;
    w.names = {"CLK", "ALE", "IO/M", "S1", "S0", "RD", "WR", "INTA"};
    w.levels.assign(w.names.size(), "");
    for (const BusCycle& c : cycles) {
        const BusStatus s = bus_status(c.type);
        const bool fetch = c.type == MachineCycle::Fetch4 || c.type == MachineCycle::Fetch6;
        const bool halt = c.type == MachineCycle::Halt;
        for (int h = 0; h < 2 * c.tstates; ++h) {
            const int t = h / 2;                   // 0 = T1
            const bool strobe = t == 1 || t == 2;  // RD, WR, INTA low through T2 and T3
            w.levels[0] += h % 2 == 0 ? '1' : '0';
            w.levels[1] += s.ale && h == 0 ? '1' : '0';
            w.levels[2] += s.io_m;
            w.levels[3] += s.s1;
            w.levels[4] += s.s0;
            w.levels[5] += halt ? 'z' : s.rd && strobe ? '0' : '1';
            w.levels[6] += halt ? 'z' : s.wr && strobe ? '0' : '1';
            w.levels[7] += s.inta && strobe ? '0' : '1';
            int high = -2, low = -2;
            if (halt) {
                high = low = -1;
            } else if (c.has_address && t <= 2) {
                high = c.address >> 8;
                if (t == 0) low = c.address & 0xFF;
                else if (s.wr) low = c.data;
                else low = h == 2 || !c.has_data ? (h == 2 ? -1 : -2) : c.data;  // a read: floating, then the data
            } else if (fetch || c.type == MachineCycle::IntAck) {
                low = -1;  // T4-T6: AD7-AD0 float, A15-A8 unspecified
            }
            w.bus_high.push_back(high);
            w.bus_low.push_back(low);
        }
        w.half_tstates += 2 * c.tstates;
    }
    return w;
}

void write_cycles_vcd(const std::vector<BusCycle>& cycles, const std::string& path, const std::string& title) {
    const Waveforms w = waveforms(cycles);
    AtomicOutput file(path);
    std::ostream& o = file.stream();
    o << "$version ALP85 (alp85 timing) $end\n";
    o << "$comment\n  " << title << "\n"
      << fmt::format("  The 8085's machine cycles as its data sheet draws them, half a T-state at a time: one T-state is\n"
                     "  1e9/{} ns; T-state n (from 0) starts at #round(n * 1e9 / {}). RD, WR and INTA are the pins\n"
                     "  (active low). A15-A8 and AD7-AD0 are one variable a bit (sigrok-cli reads 1-bit variables).\n",
                     board::kCpuHz, board::kCpuHz)
      << "$end\n$timescale 1 ns $end\n$scope module i8085 $end\n";
    std::vector<std::string> names;
    for (const std::string& n : w.names) names.push_back(n == "IO/M" ? "IO_M" : n);
    for (int b = 15; b >= 8; --b) names.push_back(fmt::format("A{}", b));
    for (int b = 7; b >= 0; --b) names.push_back(fmt::format("AD{}", b));
    auto id = [](std::size_t i) { return std::string(1, static_cast<char>('!' + i)); };
    for (std::size_t i = 0; i < names.size(); ++i) o << "$var wire 1 " << id(i) << ' ' << names[i] << " $end\n";
    o << "$upscope $end\n$enddefinitions $end\n";
    auto bit = [](int byte, int b) { return byte == -1 ? 'z' : byte == -2 ? 'x' : ((byte >> b) & 1) ? '1' : '0'; };
    std::vector<char> last(names.size(), '?');
    for (int h = 0; h <= w.half_tstates; ++h) {
        const std::uint64_t ns = (static_cast<std::uint64_t>(h) * 1'000'000'000ull + board::kCpuHz) / (2ull * board::kCpuHz);
        if (h == w.half_tstates) {  // the end, so that viewers draw the last half T-state
            o << '#' << ns << '\n';
            break;
        }
        std::string changes;
        for (std::size_t i = 0; i < names.size(); ++i) {
            char v;
            if (i < w.names.size()) v = w.levels[i][static_cast<std::size_t>(h)];
            else if (i < w.names.size() + 8) v = bit(w.bus_high[static_cast<std::size_t>(h)], 15 - static_cast<int>(i - w.names.size()));
            else v = bit(w.bus_low[static_cast<std::size_t>(h)], 7 - static_cast<int>(i - w.names.size() - 8));
            if (v == last[i]) continue;
            last[i] = v;
            changes += v + id(i) + '\n';
        }
        if (!changes.empty()) o << '#' << ns << '\n' << (h == 0 ? "$dumpvars\n" + changes + "$end\n" : changes);
    }
    file.commit();
}

}  // namespace alp85::debug
