#include "emu/gui/backdrop.h"

#include <algorithm>
#include <cmath>

#include <SDL_opengl.h>

namespace alp85::gui {

void Backdrop::fill(Rect r, Rgb c) { fills_.push_back({r, c}); }

void Backdrop::fill_clipped(Rect r, const Rect& clip, Rgb c) {
    const Rect i = intersect(r, clip);
    if (i.w > 0 && i.h > 0) fill(i, c);
}

void Backdrop::paint(Rgb background, int h, const Rect& clip) const {
    const auto clear = [h](const Rect& r, Rgb c) {
        const int x0 = static_cast<int>(std::lround(r.x)), y0 = static_cast<int>(std::lround(r.y));
        const int x1 = static_cast<int>(std::lround(r.x + r.w)), y1 = static_cast<int>(std::lround(r.y + r.h));
        if (x1 <= x0 || y1 <= y0) return;
        glScissor(x0, h - y1, x1 - x0, y1 - y0);
        glClearColor(c.r / 255.0f, c.g / 255.0f, c.b / 255.0f, 1);
        glClear(GL_COLOR_BUFFER_BIT);
    };
    glEnable(GL_SCISSOR_TEST);
    clear(clip, background);
    for (const Fill& f : fills_) clear(intersect(f.r, clip), f.c);
    glDisable(GL_SCISSOR_TEST);
}

}  // namespace alp85::gui
