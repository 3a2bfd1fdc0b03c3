// A bare 8085/8080 on 64 KiB of RAM for the unit tests: place bytes, set registers, step.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <vector>

#include "emu/core/bus.h"
#include "emu/core/i8085.h"

namespace alp85::test {

// Flag bits as the data sheets and docs/cpu.md number them.
inline constexpr std::uint8_t S = 0x80, Z = 0x40, K = 0x20, AC = 0x10, P = 0x04, V = 0x02, CY = 0x01;

struct Rig {
    std::vector<std::uint8_t> ram = std::vector<std::uint8_t>(0x10000, 0);
    Bus bus;
    I8085 cpu;

    explicit Rig(Variant v = Variant::I8085) : cpu(bus, v) {
        bus.map_ram(0, 0x10000, ram.data());
        cpu.regs().sp = 0xF000;
    }
    bool is8080() const { return cpu.variant() == Variant::I8080; }
    // The flag byte an 8080 would show for `f85`-style flags: bit 1 always reads 1 there.
    std::uint8_t flags(std::uint8_t f) const { return is8080() ? static_cast<std::uint8_t>(f | 0x02) : f; }

    void load(std::uint16_t addr, std::initializer_list<std::uint8_t> bytes) {
        for (std::uint8_t b : bytes) ram[addr++] = b;
    }
    // Places `code` at 0100H, points PC at it and runs one instruction; returns its T-states.
    std::uint64_t exec(std::initializer_list<std::uint8_t> code) {
        load(0x0100, code);
        cpu.regs().pc = 0x0100;
        return cpu.step();
    }
    Registers& r() { return cpu.regs(); }
};

}  // namespace alp85::test
