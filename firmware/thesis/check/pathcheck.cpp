// Verification harness (not part of the build): the thesis firmware on the emulated board with a
// minimal transducer model -- a rising edge of the X (Y) pulse on port A moves the axis one step
// in the direction its port A direction bit gives, toggles port B bit 1 (bit 0) and sets port B
// bit 2 (bit 3) to that direction. Types the Appendix C session, runs to HLT, prints the result.
//   g++ -std=c++20 -O2 -I. -Ibuild -Ibuild/firmware/monitor firmware/thesis/check/pathcheck.cpp \
//     -o /tmp/h/h build/emu/libalp85_script.a build/emu/libalp85_board.a \
//     build/emu/libalp85_atomic_file.a build/emu/libalp85_emu.a \
//     build/firmware/monitor/libmonitor_embed.a build/peripherals/libalp85_peripherals.a \
//     build/asm/libalp85_asm.a $(find build -name libalp85_isa.a) -lfmt
//   /tmp/h/h build/firmware/thesis/thesis-fixed.hex Z X1 Y1 X2 Y2 FEED [max_ms]   (4 digits each)
// PATHLOG=1 prints every step.
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include "emu/machine.h"
#include "emu/firmware.h"
#include "emu/ihex.h"
#include "peripherals/keypad.h"
using namespace alp85;
int main(int argc, char** argv) {
    // args: hexfile Z X1 Y1 X2 Y2 F [maxms]
    Machine m;
    auto mon = firmware::monitor();
    m.load(mon.segments);
    std::ifstream f(argv[1]); std::stringstream ss; ss << f.rdbuf();
    std::string err = load_intel_hex(ss.str(), [&](std::uint16_t a, std::uint8_t b) { m.poke(a, b); });
    if (!err.empty()) { std::printf("hex: %s\n", err.c_str()); return 1; }
    double maxms = argc > 8 ? std::atof(argv[8]) : 20000;
    std::uint8_t pb = 0; int xpos = std::atoi(argv[3]), ypos = std::atoi(argv[4]); std::uint8_t lastA = 0;
    long xs = 0, ys = 0; std::uint64_t lastedge = 0, sumper = 0; long nper = 0;
    bool trace_path = std::getenv("PATHLOG") != nullptr;
    m.set_port_b_source([&](std::uint64_t) { return pb; });
    m.set_trace([&](const I8085&) {
        std::uint8_t a = m.rio().port_output(periph::I8155::Port::A);
        std::uint8_t rise = a & ~lastA;
        if (rise & 0x01) { int d = (a & 0x02) ? 1 : -1; xpos += d; xs++; pb ^= 0x02; pb = (pb & ~0x04) | ((a & 0x02) ? 0x04 : 0);
            if (trace_path) std::printf("X %d %d\n", xpos, ypos); }
        if (rise & 0x04) { int d = (a & 0x08) ? 1 : -1; ypos += d; ys++; pb ^= 0x01; pb = (pb & ~0x08) | ((a & 0x08) ? 0x08 : 0);
            if (trace_path) std::printf("Y %d %d\n", xpos, ypos); }
        if (rise & 0x05) { if (lastedge) { sumper += m.now() - lastedge; nper++; } lastedge = m.now(); }
        lastA = a;
    });
    m.reset();
    std::uint64_t t = m.now() + Machine::tstates_from_ms(50);
    auto press = [&](const char* k) {
        auto key = *periph::Keypad::find(k);
        m.key_at(key, true, t); t += Machine::tstates_from_ms(30);
        m.key_at(key, false, t); t += Machine::tstates_from_ms(30);
    };
    auto typenum = [&](const char* s) { for (const char* p = s; *p; ++p) { char k[2] = {*p, 0}; press(k); } };
    press("R"); press("7"); press("0"); press("8"); press("0"); press("0"); press("EXEC");
    typenum(argv[2]);                  // Z
    t += Machine::tstates_from_ms(500);
    typenum(argv[3]); press("EXEC");   // X1
    typenum(argv[4]); press("EXEC");
    typenum(argv[5]); press("EXEC");
    typenum(argv[6]); press("EXEC");
    typenum(argv[7]); press("EXEC");   // feed, start
    std::uint64_t start = t;
    m.run_until(t + Machine::tstates_from_ms(maxms), [&] { return m.cpu().halted(); });
    auto w = [&](int a) { return m.peek(a) | m.peek(a + 1) << 8; };
    std::printf("halted=%d ms=%.1f display='%s' pos=(%d,%d) XAC=%d YAC=%d YID=%d steps x=%ld y=%ld D=%d avg_step_T=%.0f ZAC=%d\n",
                (int)m.cpu().halted(), (m.now() - start) * 1000.0 / 3072000.0, m.display_text().c_str(), xpos, ypos,
                w(0x1B34), w(0x1B32), w(0x1B30), xs, ys, m.peek(0x1B38), nper ? double(sumper) / nper : 0.0, w(0x1B3E));
}
