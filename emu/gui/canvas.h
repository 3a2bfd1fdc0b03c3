// The window's picture kept in an offscreen framebuffer, redrawn only where it changed.
//
// Each frame ImGui produces draw lists (one per window: every view is its own window). A list
// whose vertices, indices or clip rectangles differ from the last frame's damages its area (its
// old and its new extent); so does a backdrop rectangle that moved. Only the damaged rectangles
// are painted again - every list, clipped to them - and the framebuffer is copied to the window
// only when something was. With software OpenGL (Mesa under Xvfb) drawing is the process's main
// cost, so a window showing a still display costs almost nothing, and a moving table only its
// own panels.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <imgui.h>

#include "emu/gui/backdrop.h"
#include "emu/gui/layout.h"

namespace alp85::gui {

class Canvas {
public:
    Canvas() = default;
    Canvas(const Canvas&) = delete;
    Canvas& operator=(const Canvas&) = delete;
    ~Canvas();

    // Creates the offscreen framebuffer (w x h); false when OpenGL cannot.
    bool init(int w, int h);
    // Paints what changed; returns true when anything was painted.
    bool render(ImDrawData* dd, const Backdrop& bd, Rgb background);
    // Copies the picture into the window's back buffer (then swap): with software OpenGL only what
    // this frame and the one before repainted (Mesa's software back buffer keeps its pixels across
    // a swap, and a pair of exchanged buffers would be one frame behind); with a GPU, all of it.
    // The window's drawable is dw x dh and the picture lies in it at `fit` (layout.h), scaled
    // (pixel-doubled at whole multiples, filtered otherwise): the whole picture with the letterbox
    // cleared when the size or fit changed, else the same mapping scissored to the changed places.
    // `full`: copy everything (the window was exposed or resized).
    void present(int dw, int dh, const Fit& fit, bool full);
    bool software() const { return software_; }
    const std::string& renderer() const { return renderer_; }  // OpenGL's GL_RENDERER
    // Makes the picture the source of glReadPixels (screenshots).
    void bind_for_read();
    void unbind();
    // Makes the window's back buffer (after present) the source of glReadPixels.
    void bind_window_for_read();
    // The window lost its pixels (exposed): the next present copies everything.
    void expose() { present_full_ = true; }
    std::uint64_t painted_pixels() const { return painted_; }

private:
    struct ListState {
        std::uint64_t hash = 0;
        Rect extent;
        bool seen = false;
    };
    void paint(ImDrawData* dd, const std::vector<Rect>& damage);

    unsigned fbo_ = 0, rbo_ = 0;
    int w_ = 0, h_ = 0;
    bool full_ = true;
    std::map<std::string, ListState> lists_;
    std::vector<Backdrop::Fill> backdrop_;
    std::vector<Rect> damage_, previous_damage_;
    bool software_ = false;
    std::string renderer_;
    bool present_full_ = true;
    int shown_w_ = 0, shown_h_ = 0;  // the window's drawable and the picture's place in it, last present
    Fit shown_fit_;
    std::uint64_t painted_ = 0;
};

}  // namespace alp85::gui
