// A part added in one line shows up in every debugger front end from its description alone:
// the console's `info PART` and `watch PART NAME`, and DAP's scopes and variables (the functions
// the adapter's scopes/variables requests answer with). The toy (tests/board/led_latch.h) is
// known to none of them.
#include <gtest/gtest.h>

#include <algorithm>

#include "emu/dap/machine_view.h"
#include "emu/debug/console.h"
#include "tests/board/led_latch.h"

namespace alp85::test {
namespace {

// MVI A,55H (7 T) / OUT 00H (10 T) / MVI A,0FH / OUT 00H / JMP $ : the latch goes 00H, 55H, 0FH.
const std::vector<std::uint8_t> kProgram = {0x3E, 0x55, 0xD3, 0x00, 0x3E, 0x0F, 0xD3, 0x00, 0xC3, 0x08, 0x08};

struct Board {
    Machine m;
    LedLatch leds;
    debug::Debugger d{m};
    debug::Console console{d};
    Board() {
        m.attach(leds, &leds, 0x00, 0x00);  // the one line that adds the part
        m.load(0x0800, kProgram);
        m.cpu().regs().pc = 0x0800;
    }
};

TEST(PartViews, TheConsoleShowsAToyPartsRegisters) {
    Board b;
    b.m.run_until(5'000);
    const std::string info = b.console.info("leds");
    EXPECT_NE(info.find("LED latch (a toy part)"), std::string::npos) << info;
    EXPECT_NE(info.find("latch       0FH: 4 lit"), std::string::npos) << info;  // 0FH: LEDs 0-3
    EXPECT_NE(info.find("heartbeats  5"), std::string::npos) << info;         // 5000 T / 1000
    EXPECT_NE(b.console.execute("info nothing").find("leds"), std::string::npos);  // the parts it knows
}

TEST(PartViews, TheConsoleWatchesAToyPartsRegister) {
    Board b;
    EXPECT_EQ(b.console.execute("watch leds latch"), "Watchpoint 1: leds latch\n");
    const std::string out = b.console.execute("continue");
    // the first OUT 00H writes 55H: its write cycle is in the instruction at 0802H
    EXPECT_NE(out.find("Watchpoint 1: leds latch\nOld value = 00H (0)\nNew value = 55H (85)"), std::string::npos) << out;
    EXPECT_EQ(b.m.cpu().regs().pc, 0x0804);
    EXPECT_NE(b.console.execute("watch leds nothing").find("expected: watch leds latch|beats"), std::string::npos);
}

TEST(PartViews, DapShowsAToyPartAsAScope) {
    Board b;
    b.m.run_until(5'000);
    const auto scopes = dap::scope_list(b.d);
    const auto s = std::find_if(scopes.begin(), scopes.end(), [](const dap::ScopeInfo& x) { return x.name == "Leds"; });
    ASSERT_NE(s, scopes.end());
    const auto vars = dap::list_variables(b.d, s->ref);
    ASSERT_EQ(vars.size(), 2u);
    EXPECT_EQ(vars[0].name, "latch");
    EXPECT_EQ(vars[0].value, "0FH: 4 lit");
    EXPECT_TRUE(vars[0].read_only);
    EXPECT_EQ(vars[1].name, "heartbeats");
    EXPECT_EQ(vars[1].value, "5");
    // the board's own parts are scopes the same way
    for (const char* name : {"8155", "8279", "Machine tool"})
        EXPECT_TRUE(std::any_of(scopes.begin(), scopes.end(), [&](const dap::ScopeInfo& x) { return x.name == name; })) << name;
}

}  // namespace
}  // namespace alp85::test
