// The SDK-85 test program (firmware/sdk85/sdk85test.asm) on the SDK-85's chips, wired here by
// hand as the SDK-85 user's manual maps them: the 8355's ROM at 0000H, the 8279 memory-mapped
// (1800H data, 1900H command/status: A8), the 8155 at I/O 20H-25H with its RAM at 2000H, TIMER
// OUT on TRAP, 8279 IRQ on RST 5.5, SID/SOD to a serial terminal (SOD through the kit's inverting
// TTY driver, docs/board.md), 3.072 MHz. Expected values:
// the step records against the assembler's own labels (the address of each instruction in the
// order it runs), the display against the hex digits' segments on the SDK-85's wiring (a lit
// segment is a 0 bit; a-d on bits 4-7, e-g on bits 0-2, dp on bit 3), the echo against the
// characters sent.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <utility>

#include "emu/core/bus.h"
#include "emu/core/i8085.h"
#include "emu/program/rom_image.h"
#include "tests/board/sdk85_test_rom.h"
#include "peripherals/i8155.h"
#include "peripherals/i8279.h"
#include "peripherals/i8355.h"
#include "peripherals/keypad.h"
#include "peripherals/serial_terminal.h"

namespace alp85::test {
namespace {

using periph::I8155;
using periph::I8279;
using periph::I8355;
using periph::Key;

constexpr std::uint64_t kHz = 3'072'000;
constexpr std::uint64_t kMs = kHz / 1000;

class Sdk85 {
public:
    explicit Sdk85(const RomImage& image) : tty_(kHz, format(), 10 * 1280) {
        rom_.load_rom(std::span<const std::uint8_t, I8355::kRomSize>(image.bytes.data(), I8355::kRomSize));
        bus_.map_rom(0x0000, I8355::kRomSize, rom_.rom().data());
        bus_.map_ram(0x2000, 0x100, rio_.ram().data());
        kdc_ports_.board = this;
        bus_.map_device(0x1800, 0x200, kdc_ports_);
        rio_ports_.on_in = [this](std::uint8_t port, std::uint64_t t) { return rio_.read(port - 0x20, t); };
        rio_ports_.on_out = [this](std::uint8_t port, std::uint8_t v, std::uint64_t t) {
            rio_.write(port - 0x20, v, t);
            cpu_.stop_at(t);  // a new count: the scheduler looks again
        };
        bus_.map_io(0x20, 0x25, rio_ports_);
        rio_.on_timer_out([this](bool level, std::uint64_t) { cpu_.set_trap(level); });
        kdc_.on_irq([this](bool level, std::uint64_t) { cpu_.set_rst55(level); });
        kdc_.set_return_lines_source([this](std::uint8_t sl) { return keypad_.return_lines(sl); });
        kdc_.set_shift(false, 0);
        kdc_.set_cntl_stb(false, 0);
        tty_.on_txd([this](bool level, std::uint64_t) { cpu_.set_sid(level); });
        cpu_.on_sod = [this](bool level) { tty_.sod(!level, cpu_.tstates()); };  // the inverting driver
        cpu_.reset();
        tty_.set_sod_level(!cpu_.sod());
        cpu_.set_sid(tty_.txd());
        for (periph::Part* p : parts()) p->reset(0);
    }

    // Runs to `until` the way the board's scheduler does: no batch past a part's next event.
    void run_until(std::uint64_t until) {
        for (;;) {
            const std::uint64_t t = cpu_.tstates();
            for (periph::Part* p : parts()) p->advance(std::max(t, p->now()));
            if (t >= until) return;
            std::uint64_t next = until;
            for (periph::Part* p : parts()) next = std::min(next, p->next_event());
            if (next <= t) next = t + 1;
            cpu_.run(next);
        }
    }
    void run_for(std::uint64_t tstates) { run_until(cpu_.tstates() + tstates); }
    void key(Key k) {
        const std::uint64_t t = cpu_.tstates();
        kdc_.advance(t);
        keypad_.press(k);
        kdc_.inputs_changed(t);
        run_for(30 * kMs);  // held past the 8279's debounce (two scans, ~10 ms)
        kdc_.advance(cpu_.tstates());
        keypad_.release(k);
        kdc_.inputs_changed(cpu_.tstates());
        run_for(30 * kMs);
    }
    void vect_intr() {
        cpu_.set_rst75(true);
        run_for(1 * kMs);
        cpu_.set_rst75(false);
    }
    void send(char c) { tty_.type(static_cast<std::uint8_t>(c), cpu_.tstates()); }

    std::uint8_t ram(std::uint16_t a) const { return rio_.read_memory(static_cast<std::uint8_t>(a - 0x2000)); }
    std::uint16_t ram_word(std::uint16_t a) const { return static_cast<std::uint16_t>(ram(a) | ram(a + 1) << 8); }
    std::uint8_t display(int position) const { return kdc_.state().display_ram[static_cast<std::size_t>(position)]; }
    const periph::SerialTerminal& tty() const { return tty_; }
    I8085& cpu() { return cpu_; }

private:
    static periph::UartFormat format() {
        periph::UartFormat f;
        f.baud = 2400;  // 8N1
        return f;
    }
    std::array<periph::Part*, 4> parts() { return {&rio_, &kdc_, &keypad_, &tty_}; }

    struct KdcPorts final : MemoryDevice {
        Sdk85* board = nullptr;
        std::uint8_t read(std::uint16_t addr, std::uint64_t t) override {
            return board->kdc_.read(static_cast<std::uint8_t>(addr >> 8 & 1), t);
        }
        void write(std::uint16_t addr, std::uint8_t v, std::uint64_t t) override {
            board->kdc_.write(static_cast<std::uint8_t>(addr >> 8 & 1), v, t);
            board->cpu_.stop_at(t);
        }
    };

    Bus bus_;
    I8085 cpu_{bus_};
    I8355 rom_;
    I8155 rio_;
    I8279 kdc_;
    periph::Keypad keypad_;
    periph::SerialTerminal tty_;
    KdcPorts kdc_ports_;
    IoFunctions rio_ports_;
};


// A hex digit on the SDK-85's display: the classic a-g patterns (a = bit 0 ... g = bit 6),
// moved to the SDK-85's wiring (a-d: bits 4-7, e-g: bits 0-2) and inverted (lit at 0).
std::uint8_t sdk85_digit(unsigned v) {
    static constexpr std::uint8_t kAbcdefg[16] = {0x3F, 0x06, 0x5B, 0x4F, 0x66, 0x6D, 0x7D, 0x07,
                                                  0x7F, 0x6F, 0x77, 0x7C, 0x39, 0x5E, 0x79, 0x71};
    static constexpr int kBit[7] = {4, 5, 6, 7, 0, 1, 2};  // a b c d e f g
    std::uint8_t out = 0;
    for (int s = 0; s < 7; ++s)
        if (kAbcdefg[v] >> s & 1) out = static_cast<std::uint8_t>(out | 1u << kBit[s]);
    return static_cast<std::uint8_t>(~out);
}
void expect_display(const Sdk85& b, const std::array<unsigned, 6>& digits) {
    for (int i = 0; i < 6; ++i)
        EXPECT_EQ(b.display(i), sdk85_digit(digits[static_cast<std::size_t>(i)])) << "digit " << i;
}

TEST(Sdk85Program, SingleStepStopsAfterEachInstructionOfEveryLength) {
    Sdk85 b(sdk85_test_rom());
    b.run_for(20 * kMs);
    // The PC after each step, in the order the stepped program runs (its source's labels).
    const char* order[] = {"S01", "S02", "S03", "S04", "S05", "S06", "S07", "S08", "S09", "S10",
                           "USUB", "S12", "S13", "S14", "S15", "S16", "S17", "USUBZ", "S19", "S20",
                           "S21", "S22", "R1VEC", "S24", "S25", "S26", "S27", "UEND"};
    const std::uint16_t steppc = sdk85_label("STEPPC");
    ASSERT_EQ(b.ram(sdk85_label("STEPN")), std::size(order));
    for (std::size_t i = 0; i < std::size(order); ++i)
        EXPECT_EQ(b.ram_word(static_cast<std::uint16_t>(steppc + 2 * i)), sdk85_label(order[i])) << "step " << i + 1;
    EXPECT_EQ(b.ram(sdk85_label("STEPOK")), std::size(order));  // the program's own check agrees
    EXPECT_EQ(sdk85_label("NSTEPS"), std::size(order));
    EXPECT_EQ(sdk85_label("R1VEC"), 0x0008);  // RST 1's vector
    expect_display(b, {0, 0, 1, 0xC, 1, 0xC});  // "001C 1C": 28 steps, 28 right
}

TEST(Sdk85Program, TimerCountIsTheArithmeticInTheSource) {
    // 68 T-states from OUT's first T-state to the user's instruction (OUT 10, POP PSW 10,
    // LHLD 16, SPHL 6, LHLD 16, RET 10); START taken 7 T-states into OUT; the TRAP edge at
    // 7 + N + 1 = 70, two T-states into the user's instruction: N = 62.
    EXPECT_EQ(sdk85_label("STEPCNT"), 62);
    // The count as the ROM loads it into the 8155: 3EH, then 80H (single pulse, count bits 13-8 0).
    const std::uint16_t resume = sdk85_label("RESUME");
    const auto& rom = sdk85_test_rom().bytes;
    std::size_t at = resume;
    while (at + 4 < rom.size() && !(rom[at] == 0x3E && rom[at + 2] == 0xD3 && rom[at + 3] == 0x24)) ++at;
    ASSERT_LT(at + 4, rom.size()) << "MVI A / OUT 24H not found after RESUME";
    EXPECT_EQ(rom[at + 1], 0x3E);
    EXPECT_EQ(rom[at + 4], 0x3E);  // MVI A, for the high byte
    EXPECT_EQ(rom[at + 5], 0x80);
}

TEST(Sdk85Program, OnlyTheCountsThatTrapInsideTheFirstInstructionStepOne) {
    // The TRAP edge at 7 + N + 1 T-states after OUT's first T-state, the user's instruction from
    // 68 to 72 (4 T-states at the least): N = 61..64 put the edge inside it, so every step is one
    // instruction; N = 60 traps before it runs (the PC never moves), N = 65 after a 4-T-state
    // instruction and into the next. The source's count, 62, is inside (asm85 -D overrides it).
    const auto run = [](int n) {
        asm85::Options o;
        o.defines.push_back({"STEPCNT", std::to_string(n)});
        Sdk85 b(read_rom_image(std::string(ALP85_SOURCE_DIR) + "/firmware/sdk85/sdk85test.asm", {}, o));
        b.run_for(30 * kMs);
        return std::pair<int, int>{b.ram(sdk85_label("STEPN")), b.ram(sdk85_label("STEPOK"))};
    };
    EXPECT_EQ(run(60), (std::pair<int, int>{32, 0}));  // STEPMAX records, none right
    EXPECT_EQ(run(61), (std::pair<int, int>{28, 28}));
    EXPECT_EQ(run(64), (std::pair<int, int>{28, 28}));
    EXPECT_EQ(run(65), (std::pair<int, int>{32, 0}));
}

TEST(Sdk85Program, VectIntrRunsTheStepTestAgain) {
    Sdk85 b(sdk85_test_rom());
    b.run_for(20 * kMs);
    b.key(Key::K5);
    expect_display(b, {0, 0, 0, 1, 0, 5});
    b.vect_intr();
    b.run_for(20 * kMs);
    EXPECT_EQ(b.ram(sdk85_label("STEPOK")), 28);
    expect_display(b, {0, 0, 1, 0xC, 1, 0xC});
}

TEST(Sdk85Program, EachKeyShowsItsCodeAndTheCountOfKeys) {
    Sdk85 b(sdk85_test_rom());
    b.run_for(20 * kMs);
    b.key(Key::K7);  // row 0, return line 7: 07H
    expect_display(b, {0, 0, 0, 1, 0, 7});
    b.key(Key::KA);  // row 1, line 2: 0AH
    expect_display(b, {0, 0, 0, 2, 0, 0xA});
    b.key(Key::Step);  // SINGLE STEP: row 2, line 5: 15H
    expect_display(b, {0, 0, 0, 3, 1, 5});
    EXPECT_EQ(b.ram(sdk85_label("LASTKY")), 0x15);
    EXPECT_EQ(b.ram_word(sdk85_label("KEYCNT")), 3);
    const std::uint16_t buf = sdk85_label("DISPBF");
    const std::array<std::uint8_t, 6> digits{0, 0, 0, 3, 1, 5};
    for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(b.ram(static_cast<std::uint16_t>(buf + i)), digits[i]);
}

TEST(Sdk85Program, EchoesCharactersAt2400Baud) {
    Sdk85 b(sdk85_test_rom());
    b.run_for(20 * kMs);
    const std::string text = "SDK-85\x01\xFF";
    for (char c : text) {
        b.send(c);
        b.run_for(3 * 10 * 1280);  // its frame in, its echo out, a character's gap
    }
    const auto& got = b.tty().text();
    EXPECT_EQ(std::string(got.begin(), got.end()), text);
    EXPECT_EQ(b.ram_word(sdk85_label("RXCNT")), text.size());
    EXPECT_EQ(b.ram(sdk85_label("LASTCH")), 0xFF);
}

}  // namespace
}  // namespace alp85::test
