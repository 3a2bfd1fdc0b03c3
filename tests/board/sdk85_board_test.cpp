// The project's SDK-85 test program (firmware/sdk85/sdk85test.asm, docs/sdk85.md) on the Machine
// built from the SDK-85's description (--board sdk85): its 8355 ROM at 0000H, the memory-mapped
// 8279, the 8155's timer on TRAP, SID/SOD on a serial terminal. Expected values: the step records
// against the assembler's labels (the address of each instruction in the order it runs), the
// display against the digits the program's documentation says it shows, the keys' FIFO codes from
// the 8279 data sheet (CNTL, SHIFT, SL2-0, RL2-0; CNTL and SHIFT tied high on the kit), the echo
// against the characters sent.
#include <gtest/gtest.h>

#include <string>

#include "emu/board/board_map.h"
#include "emu/board/machine.h"
#include "emu/program/rom_image.h"
#include "tests/board/sdk85_test_rom.h"
#include "peripherals/serial_terminal.h"

namespace alp85::test {
namespace {

using periph::Key;


periph::UartFormat baud2400() {
    periph::UartFormat f;
    f.baud = 2400;  // 8N1, as the program's serial line
    return f;
}

// The board with the program in its 8355 and a terminal on its TTY line: the program listens to
// SID between keys, and a line with nothing on it (SID low, a break) would keep it waiting for mark.
struct Sdk85Board {
    Sdk85Board() : term(board::kCpuHz, baud2400(), 10 * 1280), m([] {
          Machine::Options o;
          o.board = &board::kSdk85;
          return o;
      }()) {
        m.connect_serial(term);
        m.load(0x0000, sdk85_test_rom().bytes);
        m.reset();
    }
    std::uint16_t word(std::uint16_t a) const { return static_cast<std::uint16_t>(m.peek(a) | m.peek(a + 1) << 8); }
    void key(Key k) {
        m.key_at(k, true, m.now());
        m.key_at(k, false, m.now() + Machine::tstates_from_ms(30));  // past the 8279's debounce
        m.run_for(Machine::tstates_from_ms(60));
    }
    periph::SerialTerminal term;  // outlives the machine it is connected to
    Machine m;
};

// Every step of the stepped program stops after exactly one instruction: 28 instructions of every
// length and timing, 4 to 18 T-states (the program's source lists them), each record the address
// of the instruction that comes next. The display then reads "001C 1C": 28 steps, 28 right.
TEST(Sdk85Board, SingleStepStopsAfterEachInstructionOfEveryLength) {
    Sdk85Board b;
    b.m.run_for(Machine::tstates_from_ms(20));
    const char* order[] = {"S01", "S02", "S03", "S04", "S05", "S06", "S07", "S08", "S09", "S10",
                           "USUB", "S12", "S13", "S14", "S15", "S16", "S17", "USUBZ", "S19", "S20",
                           "S21", "S22", "R1VEC", "S24", "S25", "S26", "S27", "UEND"};
    ASSERT_EQ(b.m.peek(sdk85_label("STEPN")), std::size(order));
    const std::uint16_t steppc = sdk85_label("STEPPC");
    for (std::size_t i = 0; i < std::size(order); ++i)
        EXPECT_EQ(b.word(static_cast<std::uint16_t>(steppc + 2 * i)), sdk85_label(order[i])) << "step " << i + 1;
    EXPECT_EQ(b.m.peek(sdk85_label("STEPOK")), std::size(order));
    EXPECT_EQ(b.m.display_text(), "001C1C");
}

// Keys in through the memory-mapped 8279, digits out: the count of keys and the FIFO byte. With
// CNTL and SHIFT high: 7 = 11 000 111 = C7H, A = 11 001 010 = CAH, SINGLE STEP = 11 010 101 = D5H.
TEST(Sdk85Board, KeysInDigitsOut) {
    Sdk85Board b;
    b.m.run_for(Machine::tstates_from_ms(20));
    b.key(Key::K7);
    EXPECT_EQ(b.m.display_text(), "0001C7");
    b.key(Key::KA);
    EXPECT_EQ(b.m.display_text(), "0002CA");
    b.key(Key::Step);
    EXPECT_EQ(b.m.display_text(), "0003d5");
    EXPECT_EQ(b.m.peek(sdk85_label("LASTKY")), 0xD5);
}

// VECT INTR (RST 7.5, 003CH) runs the step test again: after a key, the display is back at 001C 1C.
TEST(Sdk85Board, VectIntrRunsTheStepTestAgain) {
    Sdk85Board b;
    b.m.run_for(Machine::tstates_from_ms(20));
    b.key(Key::K5);
    EXPECT_EQ(b.m.display_text(), "0001C5");
    b.m.vect_intr_at(true, b.m.now());
    b.m.vect_intr_at(false, b.m.now() + Machine::tstates_from_ms(1));
    b.m.run_for(Machine::tstates_from_ms(20));
    EXPECT_EQ(b.m.display_text(), "001C1C");
}

// SID/SOD echo through the serial terminal at 2400 baud 8N1, on the SDK-85's TTY line (SOD
// inverted by its driver): what comes back is what was sent.
TEST(Sdk85Board, EchoesCharactersOverSidAndSod) {
    Sdk85Board b;
    b.m.run_for(Machine::tstates_from_ms(20));
    const std::string text = "SDK-85\x01\xFF";
    for (char c : text) {
        b.m.serial_at(static_cast<std::uint8_t>(c), b.m.now());
        b.m.run_for(3 * 10 * 1280);  // its frame in, its echo out, a character's gap
    }
    const auto& got = b.term.text();
    EXPECT_EQ(std::string(got.begin(), got.end()), text);
    EXPECT_EQ(b.term.errors(), 0u);
    EXPECT_EQ(b.word(sdk85_label("RXCNT")), text.size());
}

}  // namespace
}  // namespace alp85::test
