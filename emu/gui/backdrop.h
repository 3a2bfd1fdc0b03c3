// Solid rectangles under everything ImGui draws, painted with scissored glClear calls. Software
// OpenGL (Mesa's llvmpipe, as under Xvfb) fills a clear many times faster than blended triangles,
// and the large panels are most of the window's pixels: drawn as triangles they cost a frame
// about 20 ms, as clears about 1 ms.
#pragma once

#include <vector>

#include "emu/gui/layout.h"

namespace alp85::gui {

class Backdrop {
public:
    // A rectangle of colour `c`; later ones paint over earlier ones. Clipped to `clip` if given.
    void fill(Rect r, Rgb c);
    void fill_clipped(Rect r, const Rect& clip, Rgb c);
    void reset() { fills_.clear(); }
    // Paints, inside `clip` only, the background colour and then every rectangle into the current
    // GL framebuffer (`h` pixels high: GL counts rows from the bottom).
    void paint(Rgb background, int h, const Rect& clip) const;

    struct Fill {
        Rect r;
        Rgb c;
    };
    const std::vector<Fill>& fills() const { return fills_; }

private:
    std::vector<Fill> fills_;
};

}  // namespace alp85::gui
