// Board descriptions (emu/board/board_description.h): the SDK-85's tables against the numbers of
// its user's manual (Intel 9800451, the memory and I/O address assignment), the SDK-85 Machine
// driving its memory-mapped 8279 and its 8155 from a few bytes of code, the ALP 85's matrix against
// the keypad's, and a changed description changing the Machine and `info board` with no front end.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "emu/board/board_map.h"
#include "emu/board/machine.h"
#include "emu/board/snapshot_file.h"
#include "peripherals/serial_terminal.h"

namespace alp85::test {
namespace {

using board::kSdk85;
using periph::Key;

const board::MemoryRegion* region(const board::Board& b, board::Memory id) {
    for (const board::MemoryRegion& r : b.memory)
        if (r.id == id) return &r;
    return nullptr;
}

// The SDK-85's map as the user's manual gives it (numbers typed from the manual's address
// assignment, not from the description): ROM 0000H-07FFH (8355), expansion ROM 0800H-0FFFH
// (8755A), 8279 data 1800H and command/status 1900H, 8155 RAM 2000H-20FFH and ports 20H-25H, the
// second 8155's RAM 2800H-28FFH and ports 28H-2DH; a 6.144 MHz crystal.
TEST(Sdk85Description, MemoryAndIoMapAsTheManualGives) {
    EXPECT_EQ(kSdk85.clock.crystal_hz, 6'144'000u);
    EXPECT_EQ(kSdk85.clock.cpu_hz(), 3'072'000u);
    const auto* rom = region(kSdk85, board::Memory::Rom8355);
    ASSERT_TRUE(rom);
    EXPECT_EQ(rom->base, 0x0000);
    EXPECT_EQ(rom->size, 0x0800);
    EXPECT_EQ(rom->kind, board::MemoryKind::Rom);
    const auto* exp = region(kSdk85, board::Memory::ExpansionRom);
    ASSERT_TRUE(exp);
    EXPECT_EQ(exp->base, 0x0800);
    EXPECT_EQ(exp->size, 0x0800);
    const auto* ram = region(kSdk85, board::Memory::Ram8155);
    ASSERT_TRUE(ram);
    EXPECT_EQ(ram->base, 0x2000);
    EXPECT_EQ(ram->size, 0x0100);
    EXPECT_TRUE(ram->option.empty());
    const auto* ram2 = region(kSdk85, board::Memory::Ram8155Expansion);
    ASSERT_TRUE(ram2);
    EXPECT_EQ(ram2->base, 0x2800);
    EXPECT_EQ(ram2->option, "ram2");

    ASSERT_EQ(kSdk85.devices.size(), 4u);
    const board::DeviceRegion& kdc = kSdk85.devices[0];
    EXPECT_EQ(kdc.device, board::Device::Kdc8279);
    EXPECT_EQ(kdc.space, board::Space::Memory);
    EXPECT_EQ(kdc.offset(0x1800), 0);  // A0 = 0: data
    EXPECT_EQ(kdc.offset(0x1900), 1);  // A0 = 1: command/status
    EXPECT_TRUE(kdc.first <= 0x1800 && 0x1900 <= kdc.last);
    const board::DeviceRegion& rio = kSdk85.devices[1];
    EXPECT_EQ(rio.space, board::Space::Io);
    EXPECT_EQ(rio.first, 0x20);
    EXPECT_EQ(rio.last, 0x25);
    EXPECT_EQ(rio.offset(0x24), 4);  // timer low (8155 data sheet: AD2-AD0 = 100)
    const board::DeviceRegion& rio2 = kSdk85.devices[2];
    EXPECT_EQ(rio2.first, 0x28);
    EXPECT_EQ(rio2.last, 0x2D);
    EXPECT_EQ(rio2.unit, 1);
    EXPECT_EQ(rio2.option, "ram2");
    // The 8355's ports: 00H port A, 01H port B, 02H and 03H their direction registers (AD1-AD0).
    const board::DeviceRegion& rom_io = kSdk85.devices[3];
    EXPECT_EQ(rom_io.device, board::Device::Rom8355);
    EXPECT_EQ(rom_io.space, board::Space::Io);
    EXPECT_EQ(rom_io.first, 0x00);
    EXPECT_EQ(rom_io.last, 0x03);
    EXPECT_EQ(rom_io.offset(0x02), 2);

    // TIMER OUT -> TRAP, VECT INTR -> RST 7.5, RESET -> RESET IN.
    const auto pin = [](board::Source s) {
        for (const board::Wire& w : kSdk85.wiring)
            if (w.source == s) return w.pin;
        return board::CpuPin::Rst55;
    };
    EXPECT_EQ(pin(board::Source::TimerOut8155), board::CpuPin::Trap);
    EXPECT_EQ(pin(board::Source::VectIntrKey), board::CpuPin::Rst75);
    EXPECT_EQ(pin(board::Source::ResetKey), board::CpuPin::ResetIn);

    // 24 keys: 22 in the matrix, RESET and VECT INTR to the CPU; six digits.
    EXPECT_EQ(kSdk85.keys.size(), 24u);
    EXPECT_EQ(std::count_if(kSdk85.keys.begin(), kSdk85.keys.end(),
                            [](const board::BoardKey& k) { return k.wire == board::KeyWire::Matrix; }),
              22);
    EXPECT_EQ(kSdk85.display.digits, 6);
    EXPECT_TRUE(kSdk85.tool.empty());
}

// The ALP 85's matrix in its description is the keypad's own (docs/peripherals.md): each key on
// the scan line and return line Keypad::info gives, 24 keys in the matrix and RESET, VECT beside.
TEST(Alp85Description, KeypadMatrixIsTheKeypadsLayout) {
    int matrix = 0;
    for (const board::BoardKey& k : board::kAlp85.keys) {
        if (k.wire != board::KeyWire::Matrix) continue;
        ++matrix;
        EXPECT_EQ(periph::Keypad::info(k.key).row, k.scan) << k.name;
        EXPECT_EQ(periph::Keypad::info(k.key).column, k.ret) << k.name;
        EXPECT_EQ(periph::Keypad::info(k.key).name, k.name);
    }
    EXPECT_EQ(matrix, 24);
    EXPECT_EQ(board::kAlp85.keys.size(), 26u);
}

Machine::Options sdk85_options() {
    Machine::Options o;
    o.board = &kSdk85;
    return o;
}

// A program in the SDK-85's 8155 RAM (2000H), started by a JMP at 0000H.
void boot_sdk85(Machine& m, const std::vector<std::uint8_t>& code) {
    m.load(0x0000, std::vector<std::uint8_t>{0xC3, 0x00, 0x20});  // JMP 2000H
    m.load(0x2000, code);
    m.reset();
}

// Digits through the memory-mapped 8279: command 90H (8279 data sheet: 100 AI=1 AAAA=0000, write
// display RAM from 0 with auto-increment) to 1900H, then six bytes to 1800H, the last through the
// mirror 1A00H (A8 = 0: data). Segment codes worked out by hand with the SDK-85's wiring (a-d on
// RAM bits 4-7, e f g dp on bits 0-3, lit at 0): 0 = abcdef lit = bits 4-7, 0, 1 clear = 0CH,
// 1 = bc = ~60H = 9FH, 2 = abdeg = ~B5H = 4AH, 3 = abcdg = ~F4H = 0BH, 4 = bcfg = ~66H = 99H,
// 5 = acdfg = ~D6H = 29H. The status read at 1B00H (a mirror of 1900H)
// with an empty FIFO and no clear running is 00H (data sheet: FIFO status word).
TEST(Sdk85Machine, DigitsThroughTheMemoryMapped8279) {
    Machine m(sdk85_options());
    boot_sdk85(m, {
                      0x3E, 0x90, 0x32, 0x00, 0x19,  // MVI A,90H ; STA 1900H
                      0x3E, 0x0C, 0x32, 0x00, 0x18,  // MVI A,0CH ; STA 1800H
                      0x3E, 0x9F, 0x32, 0x00, 0x18,  // 9FH
                      0x3E, 0x4A, 0x32, 0x00, 0x18,  // 4AH
                      0x3E, 0x0B, 0x32, 0x00, 0x18,  // 0BH
                      0x3E, 0x99, 0x32, 0x00, 0x18,  // 99H
                      0x3E, 0x29, 0x32, 0x00, 0x1A,  // 29H to the mirror 1A00H
                      0x3A, 0x00, 0x1B,              // LDA 1B00H (status, mirror of 1900H)
                      0x32, 0xF0, 0x20,              // STA 20F0H
                      0x76,                          // HLT
                  });
    m.run_for(Machine::tstates_from_ms(5), [&] { return m.cpu().halted(); });
    ASSERT_TRUE(m.cpu().halted());
    EXPECT_EQ(m.display_text(), "012345");
    EXPECT_EQ(m.display_digits(), 6u);
    EXPECT_EQ(m.peek(0x20F0), 0x00);
}

// A key through the matrix and the memory-mapped FIFO: GO is on scan line 2, return line 2, and
// SHIFT and CNTL are tied high, so its FIFO code is 11 010 010 = D2H (8279 data sheet: CNTL,
// SHIFT, SL2-0, RL2-0). The program polls the status at 1900H until the FIFO holds a character,
// sends 40H (read FIFO) and reads the data at 1800H.
TEST(Sdk85Machine, KeyThroughTheMemoryMapped8279) {
    Machine m(sdk85_options());
    boot_sdk85(m, {
                      0x3A, 0x00, 0x19,  // 2000: LDA 1900H
                      0xE6, 0x0F,        //       ANI 0FH (characters in the FIFO)
                      0xCA, 0x00, 0x20,  //       JZ 2000H
                      0x3E, 0x40,        //       MVI A,40H
                      0x32, 0x00, 0x19,  //       STA 1900H
                      0x3A, 0x00, 0x18,  //       LDA 1800H
                      0x32, 0xF1, 0x20,  //       STA 20F1H
                      0x76,              //       HLT
                  });
    m.key_at(Key::Go, true, Machine::tstates_from_ms(1));
    m.key_at(Key::Go, false, Machine::tstates_from_ms(40));
    m.run_for(Machine::tstates_from_ms(100), [&] { return m.cpu().halted(); });
    ASSERT_TRUE(m.cpu().halted());
    EXPECT_EQ(m.peek(0x20F1), 0xD2);
}

// The 8155 at ports 20H-25H and its RAM at 2000H (mirrored through 27FFH, A8-A10 not decoded):
// command 01H (port A output) to 20H, 5AH to port A (21H); port B read at 22H with nothing driving
// it is FFH; a byte stored at 2080H reads back at 2480H. Then the timer: 100 (64H) at 24H, mode
// 10 (single pulse, 80H) at 25H, command C1H (start, port A still output) at 20H; TIMER OUT is
// wired to TRAP, which vectors to 0024H, where the ROM stores 77H at 20F3H and halts.
TEST(Sdk85Machine, The8155PortsRamAndTimerToTrap) {
    Machine m(sdk85_options());
    m.load(0x0024, std::vector<std::uint8_t>{0x3E, 0x77, 0x32, 0xF3, 0x20, 0x76});  // MVI A,77H ; STA 20F3H ; HLT
    boot_sdk85(m, {
                      0x31, 0xF0, 0x20,  // LXI SP,20F0H
                      0x3E, 0x01, 0xD3, 0x20,  // MVI A,01H ; OUT 20H
                      0x3E, 0x5A, 0xD3, 0x21,  // MVI A,5AH ; OUT 21H
                      0xDB, 0x22,              // IN 22H
                      0x32, 0xF1, 0x20,        // STA 20F1H
                      0x3E, 0xA5, 0x32, 0x80, 0x20,  // MVI A,A5H ; STA 2080H
                      0x3A, 0x80, 0x24,        // LDA 2480H
                      0x32, 0xF2, 0x20,        // STA 20F2H
                      0x3E, 0x64, 0xD3, 0x24,  // MVI A,64H ; OUT 24H
                      0x3E, 0x80, 0xD3, 0x25,  // MVI A,80H ; OUT 25H
                      0x3E, 0xC1, 0xD3, 0x20,  // MVI A,C1H ; OUT 20H
                      0xC3, 0x27, 0x20,        // 2027: JMP 2027H
                  });
    m.run_for(Machine::tstates_from_ms(5), [&] { return m.cpu().halted(); });
    ASSERT_TRUE(m.cpu().halted());
    EXPECT_EQ(m.rio().port_output(periph::I8155::Port::A), 0x5A);
    EXPECT_EQ(m.peek(0x20F1), 0xFF);
    EXPECT_EQ(m.peek(0x20F2), 0xA5);
    EXPECT_EQ(m.peek(0x20F3), 0x77);
    // The second 8155 is an option, out on the kit as sold: its RAM and ports are not there.
    EXPECT_EQ(m.peek(0x2800), 0xFF);
    EXPECT_TRUE(m.set_option("ram2", true));
    EXPECT_TRUE(m.poke(0x2800, 0x42));
    EXPECT_EQ(m.peek(0x2F00), 0x42);  // mirrored through 2FFFH
    EXPECT_FALSE(m.set_option("expansion", true));  // the ALP 85's option, not the SDK-85's
}

// An SDK-85 snapshot restores onto another SDK-85 (its ROM, its second 8155, the 8279's digits),
// and a machine of the other board refuses it and the other way round: the SDK-85 has an
// expansion ROM section (EXPR) and a second 8155 (RIO2) the ALP 85 lacks, the ALP 85 a 4 KB RAM.
TEST(Sdk85Machine, SnapshotsStayOnTheirBoard) {
    Machine m(sdk85_options());
    // Clear the display RAM to FFH (8279 command 110 1 11 0 0 = DCH: clear display, CD = 11 all
    // ones, dark at lit-at-0), wait while the status's DU bit (bit 7) says the clear runs, then 1
    // (9FH) in digit 0.
    boot_sdk85(m, {
                      0x3E, 0xDC, 0x32, 0x00, 0x19,  // 2000: MVI A,0DCH ; STA 1900H
                      0x3A, 0x00, 0x19,              // 2005: LDA 1900H
                      0xE6, 0x80,                    //       ANI 80H
                      0xC2, 0x05, 0x20,              //       JNZ 2005H
                      0x3E, 0x90, 0x32, 0x00, 0x19,  //       MVI A,90H ; STA 1900H
                      0x3E, 0x9F, 0x32, 0x00, 0x18,  //       MVI A,9FH ; STA 1800H
                      0x76,
                  });
    m.run_for(Machine::tstates_from_ms(1), [&] { return m.cpu().halted(); });
    ASSERT_EQ(m.display_text(), "1     ");
    const std::vector<std::uint8_t> bytes = m.snapshot_bytes();
    Machine copy(sdk85_options());
    copy.restore_bytes(bytes);
    EXPECT_EQ(copy.display_text(), "1     ");
    EXPECT_EQ(copy.peek(0x0000), 0xC3);
    EXPECT_EQ(copy.now(), m.now());
    Machine alp;
    EXPECT_THROW(alp.restore_bytes(bytes), SnapshotError);
    EXPECT_THROW(copy.restore_bytes(alp.snapshot_bytes()), SnapshotError);
    EXPECT_EQ(copy.display_text(), "1     ");  // a refused file changes nothing
}

// The SDK-85's TTY driver inverts SOD (docs/board.md): SOD low after RESET holds the line at mark,
// where a terminal receives nothing; SOD set high (SIM with C0H: SOD enable and SOD = 1) holds it
// at space, which the terminal takes as a character with a framing error (a break) one frame
// later. The ALP 85 wires SOD straight: there SOD high is the idle line.
TEST(Sdk85Machine, SodIsInvertedOnTheTtyLine) {
    periph::UartFormat f;
    f.baud = 9600;
    for (const bool sod_high : {false, true}) {
        Machine m(sdk85_options());
        periph::SerialTerminal term(board::kCpuHz, f, 0);
        m.connect_serial(term);
        boot_sdk85(m, {0x3E, static_cast<std::uint8_t>(sod_high ? 0xC0 : 0x40), 0x30, 0x76});  // MVI A,xx ; SIM ; HLT
        m.run_for(Machine::tstates_from_ms(5));  // 5 ms: about 5 frames at 9600 baud
        EXPECT_EQ(term.received() > 0, sod_high) << "SOD " << sod_high;
        EXPECT_EQ(term.errors() > 0, sod_high) << "SOD " << sod_high;
    }
    Machine alp;
    periph::SerialTerminal term(board::kCpuHz, f, 0);
    alp.connect_serial(term);
    alp.load(0x0000, std::vector<std::uint8_t>{0x3E, 0xC0, 0x30, 0x76});
    alp.reset();
    alp.run_for(Machine::tstates_from_ms(5));
    EXPECT_EQ(term.received(), 0u);
}

// One description changed in one place -- the ALP 85 with its 8279 on ports 10H/11H and GO moved
// to the return line of R -- changes the Machine's decoding, its keys and `info board`; nothing
// else is touched.
TEST(BoardDescription, AChangedDescriptionChangesTheMachineAndInfo) {
    static constexpr std::array<board::DeviceRegion, 2> kDevices{{
        {board::Device::Kdc8279, 0, board::Space::Io, 0x10, 0x11, 0x0001, "8279", "moved to 10H/11H"},
        board::alp85::kDevices[1],
    }};
    static const std::vector<board::BoardKey> keys = [] {
        std::vector<board::BoardKey> k(board::kAlp85.keys.begin(), board::kAlp85.keys.end());
        for (board::BoardKey& key : k)
            if (key.key == Key::Go && key.wire == board::KeyWire::Matrix) key.ret = 7;  // where R was
            else if (key.key == Key::R && key.wire == board::KeyWire::Matrix) key.ret = 2;
        return k;
    }();
    board::Board moved = board::kAlp85;
    moved.devices = kDevices;
    moved.keys = keys;
    Machine::Options o;
    o.board = &moved;
    o.machine_tool = false;
    Machine m(o);
    // Display via the new ports: 90H to 11H, 76H (H on the ALP 85's wiring) to 10H; a write to
    // E1H/E0H reaches nothing now.
    m.load(0x0800, std::vector<std::uint8_t>{
                       0x3E, 0x90, 0xD3, 0x11,  // MVI A,90H ; OUT 11H
                       0x3E, 0x76, 0xD3, 0x10,  // MVI A,76H ; OUT 10H
                       0x3E, 0x91, 0xD3, 0xE1,  // MVI A,91H ; OUT E1H (nothing there now)
                       0x3E, 0x76, 0xD3, 0xE0,  // MVI A,76H ; OUT E0H
                       0x76,
                   });
    m.reset();
    m.cpu().regs().pc = 0x0800;
    m.run_for(Machine::tstates_from_ms(5), [&] { return m.cpu().halted(); });
    ASSERT_TRUE(m.cpu().halted());
    EXPECT_EQ(m.display_text(), "H       ");
    // GO now closes RL7 on scan line 2: the return lines read 0111 1111 there.
    m.key_at(Key::Go, true, m.now());
    m.run_for(10);
    EXPECT_EQ(m.keypad().return_lines(2), 0x7F);
    const std::string info = m.describe_board();
    EXPECT_NE(info.find("10H-11H"), std::string::npos) << info;
    EXPECT_EQ(info.find("E0H-E1H"), std::string::npos) << info;
    EXPECT_NE(info.find("GO    SL2 RL7"), std::string::npos) << info;
    // The board as built says E0H-E1H.
    EXPECT_NE(Machine().describe_board().find("E0H-E1H"), std::string::npos);
}

}  // namespace
}  // namespace alp85::test
