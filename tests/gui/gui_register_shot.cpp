// `alp85 gui --debug --screenshot SHOT.png` linked with a toy register added to the CPU's
// description in one line (tests/debug/toy_register.cpp, in place of the library's): the window is
// the library's, unchanged, and gui_pixels checks that the Registers pane drew the toy's row.
//   gui_register_shot gui --screenshot SHOT.png      (the arguments run_gui_test.cmake passes)
#include <cstdio>
#include <string>

#include "emu/gui/app.h"

int main(int argc, char** argv) {
    alp85::gui::GuiOptions o;
    for (int i = 1; i + 1 < argc; ++i)
        if (std::string(argv[i]) == "--screenshot") o.screenshot = argv[i + 1];
    if (o.screenshot.empty()) {
        std::fprintf(stderr, "usage: gui_register_shot gui --screenshot SHOT.png\n");
        return 2;
    }
    o.debug = true;
    return alp85::gui::run(o);
}
