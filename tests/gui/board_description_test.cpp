// Issue 38's "one place": a board description changed in the test alone (a copy of the ALP 85's
// tables with the 8279 on other ports, GO moved to another place on the panel under another
// caption and PC key, and a display of seven digits) changes the Machine, `info board`, the
// window's keypad and display and the page's keypad model (front::keypad_view, what web/binding.cpp
// hands the page), with no front-end file touched. Expected values are the changes made here.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>

#include "emu/board/alp85.h"
#include "emu/board/machine.h"
#include "emu/front/keys.h"
#include "emu/front/views.h"
#include "emu/gui/layout.h"
#include "emu/script/session.h"

namespace alp85::gui {
namespace {

// GO's place on the ALP 85's panel (row 1, column 2: docs/peripherals.md) and where it goes here:
// row 3, column 0, a place the ALP 85's panel leaves empty.
constexpr int kGoRow = 1, kGoCol = 2, kMovedRow = 3, kMovedCol = 0;

struct ChangedAlp85 {
    std::array<board::DeviceRegion, 2> devices = board::alp85::kDevices;
    std::array<board::BoardKey, 26> keys = board::alp85::kKeys;
    board::Board board = board::kAlp85;
    ChangedAlp85() {
        for (board::DeviceRegion& d : devices)
            if (d.device == board::Device::Kdc8279) d.first = 0xC0, d.last = 0xC1;  // was E0H-E1H
        for (board::BoardKey& k : keys)
            if (k.name == "GO") {
                k.panel_row = kMovedRow, k.panel_col = kMovedCol;
                k.cap = "RUN";
                k.pc = {"U"};
                k.pc_label = "U";
            }
        board.name = "alp85-changed";
        board.devices = devices;
        board.keys = keys;
        board.display.digits = 7;  // was 8
    }
};

script::SessionOptions on(const board::Board& b) {
    script::SessionOptions o;
    o.board = &b;
    return o;
}

TEST(BoardDescription, ChangedInOnePlaceTheMachineTheWindowAndThePageFollow) {
    // The description as given is what the other tests run: the ALP 85's GO at (1, 2), 8 digits.
    const auto go = front::find_pad_key("GO");
    ASSERT_TRUE(go);
    EXPECT_EQ(go->row, kGoRow);
    EXPECT_EQ(go->col, kGoCol);

    const ChangedAlp85 changed;
    script::Session s(on(changed.board));

    // The Machine and `info board`: the 8279 on C0H-C1H.
    const auto devices = s.machine().device_map();
    const auto kdc = std::find_if(devices.begin(), devices.end(), [](const board::DeviceRegion& d) { return d.device == board::Device::Kdc8279; });
    ASSERT_NE(kdc, devices.end());
    EXPECT_EQ(kdc->first, 0xC0);
    EXPECT_EQ(kdc->last, 0xC1);
    const std::string info = s.describe_board();
    EXPECT_NE(info.find("C0H-C1H  8279"), std::string::npos) << info;
    EXPECT_EQ(info.find("E0H-E1H"), std::string::npos) << info;
    EXPECT_NE(info.find("RUN"), std::string::npos) << info;
    EXPECT_NE(info.find("display: 7 digits"), std::string::npos) << info;

    // The window: GO is hit at its new place, nothing at its old one, and it is drawn with the
    // new caption and PC key; seven digits, the display's window a digit's pitch narrower.
    const PadKey moved{Button::Matrix, periph::Key::Go, kMovedRow, kMovedCol};
    const Vec2 at = key_rect(moved).centre();
    const auto hit = key_at(at.x, at.y, s);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->key, periph::Key::Go);
    const Vec2 old = key_rect(PadKey{Button::Matrix, periph::Key::Go, kGoRow, kGoCol}).centre();
    EXPECT_FALSE(key_at(old.x, old.y, s));
    EXPECT_TRUE(key_at(old.x, old.y));  // the default board's GO is where it was
    EXPECT_EQ(cap_label(*hit, s), "RUN");
    EXPECT_EQ(pc_key_label(*hit, s), "U");
    EXPECT_EQ(pad_key_for_pc("U", s)->key, periph::Key::Go);
    EXPECT_EQ(display_digits(s), 7u);
    EXPECT_EQ(display_rect(display_digits(s)).w, kDisplayRect.w - kDigitPitch);
    EXPECT_EQ(display_rect(8).w, kDisplayRect.w);

    // The page's keypad model: 26 keys, GO among them at its new place with its new caption, and
    // the key map naming its PC key.
    const auto pad = front::keypad_view(s);
    EXPECT_EQ(pad.size(), 26u);
    const auto k = std::find_if(pad.begin(), pad.end(), [](const front::KeypadKey& x) { return x.name == "GO"; });
    ASSERT_NE(k, pad.end());
    EXPECT_EQ(k->key.row, kMovedRow);
    EXPECT_EQ(k->key.col, kMovedCol);
    EXPECT_EQ(k->cap, "RUN");
    EXPECT_EQ(k->pc, "U");
    EXPECT_TRUE(k->fn);
    const auto rows = front::key_map_rows(false, s);
    EXPECT_TRUE(std::any_of(rows.begin(), rows.end(), [](const front::KeyMapRow& r) { return r.keys == "U" && r.action == "RUN"; }));
}

// The SDK-85 as its description has it: 24 keys on four rows of six, six digits, no machine tool
// (the window and the page then show no table), its ROM at 0000H-07FFH the user's.
TEST(BoardDescription, TheSdk85sKeypadDisplayAndRomComeFromItsDescription) {
    script::Session s(on(board::kSdk85));
    const auto pad = front::keypad_view(s);
    ASSERT_EQ(pad.size(), 24u);
    int rows = 0, cols = 0;
    for (const front::KeypadKey& k : pad) rows = std::max(rows, k.key.row + 1), cols = std::max(cols, k.key.col + 1);
    EXPECT_EQ(rows, 4);
    EXPECT_EQ(cols, 6);
    // Every key is hit at its own centre and no two share a place.
    for (const front::KeypadKey& k : pad) {
        const Vec2 c = key_rect(k.key).centre();
        const auto hit = key_at(c.x, c.y, s);
        ASSERT_TRUE(hit) << k.name;
        EXPECT_EQ(front::cap_label(*hit, s), k.cap);
    }
    EXPECT_EQ(front::cap_label(*front::find_pad_key("EXEC", s), s), "EXEC\n.");
    EXPECT_FALSE(front::find_pad_key("PREV", s));
    EXPECT_EQ(display_digits(s), 6u);
    EXPECT_FALSE(has_tool(s));
    EXPECT_TRUE(has_tool(script::Session(script::SessionOptions{})));
    const auto rom = monitor_rom(s);
    ASSERT_TRUE(rom);
    EXPECT_EQ(rom->base, 0x0000);
    EXPECT_EQ(rom->size, 0x0800);
}

}  // namespace
}  // namespace alp85::gui
