// 8355 tests. Expected values come from the Intel 8355 data sheet: AD1-AD0 select port A (00),
// port B (01), DDR A (10), DDR B (11); a DDR bit 1 makes its line an output; a port read gives
// the output latch on output lines and the pins on input lines; RESET clears both DDRs (every
// line an input); the ROM is 2048 bytes addressed by A10-A0. Facts: docs/peripherals.md.
#include "peripherals/i8355.h"

#include <gtest/gtest.h>

#include <tuple>
#include <vector>

#include "peripherals/state_io.h"

namespace {

using alp85::periph::I8355;
using Port = I8355::Port;

TEST(I8355Test, ResetLeavesEveryLineAnInputReadingThePins) {
    I8355 chip;
    chip.reset(0);
    chip.set_port_input(Port::A, 0x5A);
    chip.set_port_input(Port::B, 0xC3);
    EXPECT_EQ(chip.read(I8355::kPortA, 1), 0x5A);
    EXPECT_EQ(chip.read(I8355::kPortB, 1), 0xC3);
    EXPECT_EQ(chip.port_output_mask(Port::A), 0x00);
    EXPECT_EQ(chip.port_output_mask(Port::B), 0x00);
    EXPECT_EQ(chip.next_event(), I8355::kNever);  // no timer, nothing happens by itself
}

TEST(I8355Test, AddressBitsSelectPortsAndDirectionRegisters) {
    I8355 chip;
    chip.reset(0);
    chip.write(I8355::kDdrA, 0xFF, 1);  // 10: DDR A, all output
    chip.write(I8355::kPortA, 0x81, 2);  // 00: port A latch
    chip.write(I8355::kDdrB, 0x0F, 3);  // 11: DDR B, low nibble output
    chip.write(I8355::kPortB, 0x3C, 4);  // 01: port B latch
    EXPECT_EQ(chip.port_output_mask(Port::A), 0xFF);
    EXPECT_EQ(chip.port_output(Port::A), 0x81);
    EXPECT_EQ(chip.port_output_mask(Port::B), 0x0F);
    EXPECT_EQ(chip.port_output(Port::B), 0x0C);  // 3CH on the output lines 0-3 only
    // Only AD1-AD0 reach the selection: offset 4 is port A again, 7 is DDR B.
    chip.write(4, 0x7E, 5);
    EXPECT_EQ(chip.port_output(Port::A), 0x7E);
    chip.write(7, 0x00, 6);
    EXPECT_EQ(chip.port_output_mask(Port::B), 0x00);
}

TEST(I8355Test, ReadGivesLatchOnOutputLinesAndPinsOnInputLines) {
    I8355 chip;
    chip.reset(0);
    chip.set_port_input(Port::A, 0x00);  // every pin pulled low from outside
    chip.write(I8355::kPortA, 0xFF, 1);
    chip.write(I8355::kDdrA, 0xF0, 2);  // PA7-4 out, PA3-0 in
    // PA7-4 from the latch (1111), PA3-0 from the pins (0000).
    EXPECT_EQ(chip.read(I8355::kPortA, 3), 0xF0);
    chip.set_port_input(Port::A, 0x05);
    EXPECT_EQ(chip.read(I8355::kPortA, 4), 0xF5);
    // All outputs: the pins no longer matter, the latch is read back.
    chip.write(I8355::kDdrA, 0xFF, 5);
    chip.write(I8355::kPortA, 0xA5, 6);
    EXPECT_EQ(chip.read(I8355::kPortA, 7), 0xA5);
}

TEST(I8355Test, InputCallbackSuppliesThePinsAtTheTimeOfTheRead) {
    I8355 chip;
    chip.reset(0);
    chip.set_input_callback([](Port p, std::uint64_t now) {
        return static_cast<std::uint8_t>(p == Port::B ? now & 0xFF : 0x11);
    });
    chip.write(I8355::kDdrB, 0x80, 1);  // PB7 out (latch 0), PB6-0 in
    EXPECT_EQ(chip.read(I8355::kPortB, 0x37), 0x37);
    EXPECT_EQ(chip.read(I8355::kPortB, 0xF7), 0x77);  // PB7 is the latch's 0, not the pin's 1
    EXPECT_EQ(chip.read(I8355::kPortA, 0xF8), 0x11);
}

TEST(I8355Test, WritesAreReportedWithTheLatchAndTime) {
    I8355 chip;
    std::vector<std::tuple<Port, std::uint8_t, std::uint64_t>> writes;
    chip.on_port_write([&](Port p, std::uint8_t latch, std::uint64_t at) { writes.emplace_back(p, latch, at); });
    chip.reset(0);
    chip.write(I8355::kPortB, 0x42, 10);
    chip.write(I8355::kDdrB, 0xFF, 20);  // the lines start driving the latch: reported too
    ASSERT_EQ(writes.size(), 2u);
    EXPECT_EQ(writes[0], std::make_tuple(Port::B, std::uint8_t{0x42}, std::uint64_t{10}));
    EXPECT_EQ(writes[1], std::make_tuple(Port::B, std::uint8_t{0x42}, std::uint64_t{20}));
}

TEST(I8355Test, ResetClearsTheDirectionRegistersAndTellsTheBoard) {
    I8355 chip;
    chip.reset(0);
    chip.write(I8355::kDdrA, 0xFF, 1);
    chip.write(I8355::kPortA, 0x99, 2);
    std::vector<Port> told;
    chip.on_port_write([&](Port p, std::uint8_t, std::uint64_t) { told.push_back(p); });
    chip.set_port_input(Port::A, 0x12);
    chip.reset(3);
    EXPECT_EQ(chip.port_output_mask(Port::A), 0x00);
    EXPECT_EQ(chip.port_output(Port::A), 0x00);
    EXPECT_EQ(chip.read(I8355::kPortA, 4), 0x12);  // an input again: the pins
    ASSERT_EQ(told.size(), 1u);                     // port A stopped driving; B never did
    EXPECT_EQ(told[0], Port::A);
}

TEST(I8355Test, RomIsTwoKilobytesAddressedByA10ToA0) {
    I8355 chip;
    EXPECT_EQ(chip.read_rom(0x0000), 0xFF);  // unloaded: FFH, as an empty ROM socket reads here
    std::array<std::uint8_t, I8355::kRomSize> image{};
    for (std::size_t a = 0; a < image.size(); ++a) image[a] = static_cast<std::uint8_t>(a ^ (a >> 8));
    chip.load_rom(image);
    EXPECT_EQ(chip.read_rom(0x0000), 0x00);
    EXPECT_EQ(chip.read_rom(0x07FF), 0xFF ^ 0x07);
    EXPECT_EQ(chip.read_rom(0x0800), chip.read_rom(0x0000));  // A11 is not the chip's: it wraps
    chip.reset(1);
    EXPECT_EQ(chip.read_rom(0x0123), 0x23 ^ 0x01);  // RESET does not touch the ROM
}

TEST(I8355Test, DescribeShowsPortsAndDirectionRegisters) {
    I8355 chip;
    chip.reset(0);
    chip.write(I8355::kDdrA, 0x0F, 1);
    chip.write(I8355::kPortA, 0x33, 2);
    alp85::periph::Description d;
    chip.describe(d);
    const auto* ddr = d.find_watch("ddra");
    ASSERT_NE(ddr, nullptr);
    EXPECT_EQ(ddr->value, 0x0F);
    const auto* pa = d.find_watch("porta");
    ASSERT_NE(pa, nullptr);
    EXPECT_EQ(pa->value, 0x33);
    EXPECT_EQ(pa->text, "mixed");
    ASSERT_NE(d.find_watch("portb"), nullptr);
    EXPECT_EQ(d.find_watch("ddrb")->value, 0x00);
}

TEST(I8355Test, SnapshotRoundTripAndRefusals) {
    I8355 chip;
    chip.reset(0);
    chip.write(I8355::kDdrB, 0xF0, 5);
    chip.write(I8355::kPortB, 0xAB, 6);
    chip.set_port_input(Port::A, 0x3C);
    std::vector<std::uint8_t> blob;
    chip.save(blob);

    I8355 other;
    other.load(blob);
    EXPECT_EQ(other.state().ddr, chip.state().ddr);
    EXPECT_EQ(other.state().latch, chip.state().latch);
    EXPECT_EQ(other.read(I8355::kPortA, 7), 0x3C);
    EXPECT_EQ(other.now(), 7u);

    I8355 fresh;
    std::vector<std::uint8_t> truncated(blob.begin(), blob.end() - 1);
    EXPECT_THROW(fresh.load(truncated), alp85::SnapshotError);
    std::vector<std::uint8_t> extra = blob;
    extra.push_back(0);
    EXPECT_THROW(fresh.load(extra), alp85::SnapshotError);
    std::vector<std::uint8_t> wrong = blob;
    wrong[0] = 'X';
    EXPECT_THROW(fresh.load(wrong), alp85::SnapshotError);
    EXPECT_EQ(fresh.state().ddr[1], 0x00);  // unchanged by the refused loads
}

}  // namespace
