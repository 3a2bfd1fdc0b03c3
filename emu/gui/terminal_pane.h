// The Terminal pane of `alp85 gui --serial BAUD[,FRAME]`: the serial terminal on SID/SOD
// (peripherals/serial_terminal.h) as a window shows it. The text the program sent on SOD fills
// the pane; every character typed in its input line goes to SID at the terminal's rate (Enter
// sends a carriage return), through the Session as a key does.
#pragma once

#include <string>

#include "emu/script/session.h"

namespace alp85::gui {

struct TerminalPane {
    bool focus = false;    // put the keyboard into the input line this frame (a test hook asks)
    bool focused = false;  // the input line has the keyboard
};

// The received text as the pane shows it: CR LF, LF and a lone CR end a line; a tab is kept;
// other control characters and bytes above 7EH show as '.'.
std::string terminal_text(const periph::SerialTerminal& terminal);

// Draws the pane; returns what was typed in its input line this frame.
std::string draw_terminal_pane(const periph::SerialTerminal& terminal, TerminalPane& pane);

}  // namespace alp85::gui
