// The Terminal pane's text (emu/gui/terminal_pane.h): what a program sent on SOD, as the pane
// shows it.
#include <gtest/gtest.h>

#include <string_view>

#include "emu/gui/terminal_pane.h"

namespace alp85::gui {
namespace {

// `bytes` sent on SOD at 9600 8N1, back to back, into a terminal.
std::string shown(std::string_view bytes) {
    const periph::UartFormat f;  // 9600,8N1
    constexpr std::uint64_t board_clock = 3'072'000;  // the ALP 85's, board::kCpuHz
    periph::SerialTerminal term(board_clock, f, 0);
    periph::UartTransmitter line(board_clock, f, 0);
    for (const char c : bytes) line.send(static_cast<std::uint8_t>(c), 0);
    const std::uint64_t end = bytes.size() * f.frame_tstates(board_clock) + 1;
    line.advance(end, [&](bool level, std::uint64_t t) { term.sod(level, t); });
    term.advance(end);
    return terminal_text(term);
}

TEST(TerminalPane, EndsLinesAtCrLfLfOrCr) {
    EXPECT_EQ(shown("one\r\ntwo\nthree\rfour"), "one\ntwo\nthree\nfour");
    EXPECT_EQ(shown("a\r\n\r\nb"), "a\n\nb");  // an empty line between
}

TEST(TerminalPane, ShowsControlCharactersAsDots) {
    EXPECT_EQ(shown(std::string_view("\x07tab\there\x1b[\x80\xff", 13)), ".tab\there.[..");
}

}  // namespace
}  // namespace alp85::gui
