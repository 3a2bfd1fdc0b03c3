// `alp85 gui --debug` with a toy part attached in one line (tests/board/led_latch.h): its tab in
// the chip pane is brought forward and the window saved, for gui_pixels to check that the pane
// draws the toy's description and nothing of another part's.
//   gui_part_shot gui --screenshot SHOT.png      (the arguments run_gui_test.cmake passes)
#include <cstdio>
#include <string>

#include "emu/gui/app.h"
#include "emu/script/session.h"
#include "tests/board/led_latch.h"

int main(int argc, char** argv) {
    alp85::test::LedLatch leds;
    alp85::gui::GuiOptions o;
    for (int i = 1; i + 1 < argc; ++i)
        if (std::string(argv[i]) == "--screenshot") o.screenshot = argv[i + 1];
    if (o.screenshot.empty()) {
        std::fprintf(stderr, "usage: gui_part_shot gui --screenshot SHOT.png\n");
        return 2;
    }
    o.debug = true;
    o.parts = [&](alp85::script::Session& s) { s.attach(leds, &leds, 0x00, 0x00); };
    o.show_part = "leds";
    return alp85::gui::run(o);
}
