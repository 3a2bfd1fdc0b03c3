#define GL_GLEXT_PROTOTYPES 1
#include "emu/gui/canvas.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include <SDL_opengl.h>
#include <backends/imgui_impl_opengl3.h>

namespace alp85::gui {
namespace {

std::uint64_t fnv(std::uint64_t h, const void* data, std::size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    // 8 bytes at a time (FNV-1a over words): the vertex buffers are tens of kilobytes a frame.
    std::size_t i = 0;
    for (; i + 8 <= n; i += 8) {
        std::uint64_t w;
        std::memcpy(&w, p + i, 8);
        h = (h ^ w) * 0x100000001B3ull;
    }
    for (; i < n; ++i) h = (h ^ p[i]) * 0x100000001B3ull;
    return h;
}

bool same(const Backdrop::Fill& a, const Backdrop::Fill& b) {
    return a.r.x == b.r.x && a.r.y == b.r.y && a.r.w == b.r.w && a.r.h == b.r.h && a.c.r == b.c.r && a.c.g == b.c.g &&
           a.c.b == b.c.b;
}

Rect rect_of(const ImVec4& c) { return {c.x, c.y, c.z - c.x, c.w - c.y}; }

bool overlap(const Rect& a, const Rect& b) {
    const Rect i = intersect(a, b);
    return i.w > 0 && i.h > 0;
}

}  // namespace

Canvas::~Canvas() {
    if (fbo_) glDeleteFramebuffers(1, &fbo_);
    if (rbo_) glDeleteRenderbuffers(1, &rbo_);
}

bool Canvas::init(int w, int h) {
    w_ = w, h_ = h;
    glGenRenderbuffers(1, &rbo_);
    glBindRenderbuffer(GL_RENDERBUFFER, rbo_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, w, h);
    glGenFramebuffers(1, &fbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rbo_);
    const bool ok = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    full_ = true;
    present_full_ = true;
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    renderer_ = renderer ? renderer : "";
    const std::string& r = renderer_;
    software_ = r.find("llvmpipe") != std::string::npos || r.find("softpipe") != std::string::npos ||
                r.find("swrast") != std::string::npos;
    return ok;
}

bool Canvas::render(ImDrawData* dd, const Backdrop& bd, Rgb background) {
    std::vector<Rect> damage;
    const Rect all{0, 0, static_cast<float>(w_), static_cast<float>(h_)};
    // The draw lists: a changed one damages where it was and where it is.
    for (auto& [name, st] : lists_) st.seen = false;
    for (int i = 0; i < dd->CmdListsCount; ++i) {
        const ImDrawList* l = dd->CmdLists[i];
        std::uint64_t h = 0xCBF29CE484222325ull;
        h = fnv(h, l->VtxBuffer.Data, static_cast<std::size_t>(l->VtxBuffer.Size) * sizeof(ImDrawVert));
        h = fnv(h, l->IdxBuffer.Data, static_cast<std::size_t>(l->IdxBuffer.Size) * sizeof(ImDrawIdx));
        Rect clips{};
        for (const ImDrawCmd& c : l->CmdBuffer) {
            h = fnv(h, &c.ClipRect, sizeof c.ClipRect);
            h = fnv(h, &c.TextureId, sizeof c.TextureId);
            if (c.ElemCount) clips = unite(clips, rect_of(c.ClipRect));
        }
        // Where the list draws: its vertices' bounding box, inside its clip rectangles.
        float x0 = 1e9f, y0 = 1e9f, x1 = -1e9f, y1 = -1e9f;
        for (const ImDrawVert& v : l->VtxBuffer)
            x0 = std::min(x0, v.pos.x), y0 = std::min(y0, v.pos.y), x1 = std::max(x1, v.pos.x), y1 = std::max(y1, v.pos.y);
        const Rect extent = x1 >= x0 ? intersect(intersect(Rect{x0, y0, x1 - x0, y1 - y0}, clips), all) : Rect{};
        const std::string name = l->_OwnerName ? l->_OwnerName : std::to_string(i);
        auto [it, added] = lists_.try_emplace(name);
        ListState& st = it->second;
        if (added || st.hash != h) damage.push_back(unite(st.extent, extent));
        st.hash = h, st.extent = extent, st.seen = true;
    }
    for (auto it = lists_.begin(); it != lists_.end();) {  // a window gone (a closed combo box)
        if (!it->second.seen) {
            damage.push_back(it->second.extent);
            it = lists_.erase(it);
        } else {
            ++it;
        }
    }
    // The backdrop: rectangles that changed damage their old and new places.
    const auto& now = bd.fills();
    for (std::size_t i = 0; i < std::max(now.size(), backdrop_.size()); ++i) {
        const bool a = i < now.size(), b = i < backdrop_.size();
        if (a && b && same(now[i], backdrop_[i])) continue;
        if (a) damage.push_back(now[i].r);
        if (b) damage.push_back(backdrop_[i].r);
    }
    backdrop_ = now;
    if (full_) damage = {all}, full_ = false;
    // Overlapping damage is merged (whole pixels, inside the window), and so are two rectangles
    // that one draw command crosses: then each command is drawn into one rectangle at most.
    std::vector<Rect> merged;
    const auto add = [&merged](Rect d) {
        for (bool again = true; again;) {
            again = false;
            for (auto it = merged.begin(); it != merged.end(); ++it)
                if (overlap(*it, d)) {
                    d = unite(*it, d);
                    merged.erase(it);
                    again = true;
                    break;
                }
        }
        merged.push_back(d);
    };
    for (Rect d : damage) {
        d = intersect(Rect{std::floor(d.x) - 1, std::floor(d.y) - 1, std::ceil(d.w) + 3, std::ceil(d.h) + 3}, all);
        if (d.w > 0 && d.h > 0) add(d);
    }
    if (merged.empty()) return false;
    for (bool again = true; again;) {
        again = false;
        for (int i = 0; i < dd->CmdListsCount && !again; ++i)
            for (const ImDrawCmd& c : dd->CmdLists[i]->CmdBuffer) {
                Rect hit{};
                int hits = 0;
                for (const Rect& d : merged)
                    if (overlap(d, rect_of(c.ClipRect))) hit = unite(hit, d), ++hits;
                if (hits > 1) {
                    add(hit);
                    again = true;
                    break;
                }
            }
    }
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glViewport(0, 0, w_, h_);
    for (const Rect& d : merged) {
        bd.paint(background, h_, d);
        painted_ += static_cast<std::uint64_t>(d.w * d.h);
    }
    paint(dd, merged);
    previous_damage_ = std::move(damage_);
    damage_ = merged;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return true;
}

// One pass of the renderer over the lists that draw into the damage, each command clipped to the
// damage rectangle it meets (the renderer skips the commands left empty); then restored.
void Canvas::paint(ImDrawData* dd, const std::vector<Rect>& damage) {
    std::vector<ImVec4> saved;
    std::vector<ImDrawList*> lists;
    int vtx = 0, idx = 0;
    for (int i = 0; i < dd->CmdListsCount; ++i) {
        ImDrawList* l = dd->CmdLists[i];
        bool used = false;
        for (ImDrawCmd& c : l->CmdBuffer) {
            saved.push_back(c.ClipRect);
            Rect r{};
            for (const Rect& d : damage)
                if (overlap(d, rect_of(c.ClipRect))) r = intersect(rect_of(c.ClipRect), d);
            const bool draws = r.w > 0 && r.h > 0 && c.ElemCount > 0;
            c.ClipRect = draws ? ImVec4{r.x, r.y, r.x + r.w, r.y + r.h} : ImVec4{0, 0, 0, 0};
            used = used || draws;
        }
        if (used) lists.push_back(l), vtx += l->VtxBuffer.Size, idx += l->IdxBuffer.Size;
    }
    ImDrawData part = *dd;  // only the lists that draw: the others' buffers are not uploaded
    part.CmdLists = lists.data();
    part.CmdListsCount = static_cast<int>(lists.size());
    part.TotalVtxCount = vtx;
    part.TotalIdxCount = idx;
    if (!lists.empty()) ImGui_ImplOpenGL3_RenderDrawData(&part);
    std::size_t k = 0;
    for (int i = 0; i < dd->CmdListsCount; ++i)
        for (ImDrawCmd& c : dd->CmdLists[i]->CmdBuffer) c.ClipRect = saved[k++];
}

void Canvas::present(int dw, int dh, const Fit& fit, bool full) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    const bool moved = dw != shown_w_ || dh != shown_h_ || fit.scale != shown_fit_.scale || fit.ox != shown_fit_.ox ||
                       fit.oy != shown_fit_.oy;
    shown_w_ = dw, shown_h_ = dh, shown_fit_ = fit;
    if (full || moved || !software_) present_full_ = true;  // a GPU's back buffer is undefined after a swap
    if (dw != w_ || dh != h_ || !fit.identity()) {
        const int x0 = static_cast<int>(fit.ox), x1 = static_cast<int>(std::lround(fit.ox + static_cast<float>(w_) * fit.scale));
        const int y1 = dh - static_cast<int>(fit.oy), y0 = dh - static_cast<int>(std::lround(fit.oy + static_cast<float>(h_) * fit.scale));
        const GLenum filter = fit.scale == std::floor(fit.scale) ? GL_NEAREST : GL_LINEAR;
        if (present_full_) {
            glViewport(0, 0, dw, dh);
            glDisable(GL_SCISSOR_TEST);
            glClearColor(0, 0, 0, 1);
            glClear(GL_COLOR_BUFFER_BIT);
            glBlitFramebuffer(0, 0, w_, h_, x0, y0, x1, y1, GL_COLOR_BUFFER_BIT, filter);
            present_full_ = false;
        } else {
            // The whole picture mapped as above, but only where it changed: the scissor keeps the
            // copy to each damaged rectangle's place in the window (a pixel wider on each side, the
            // filter's reach), and every pixel comes out as the whole copy would make it.
            glEnable(GL_SCISSOR_TEST);
            for (const auto* list : {&damage_, &previous_damage_})
                for (const Rect& d : *list) {
                    const Vec2 a = to_window(fit, d.x, d.y), b = to_window(fit, d.x + d.w, d.y + d.h);
                    const int sx0 = static_cast<int>(std::floor(a.x)) - 1, sx1 = static_cast<int>(std::ceil(b.x)) + 1;
                    const int sy0 = dh - static_cast<int>(std::ceil(b.y)) - 1, sy1 = dh - static_cast<int>(std::floor(a.y)) + 1;
                    glScissor(sx0, sy0, sx1 - sx0, sy1 - sy0);
                    glBlitFramebuffer(0, 0, w_, h_, x0, y0, x1, y1, GL_COLOR_BUFFER_BIT, filter);
                }
            glDisable(GL_SCISSOR_TEST);
        }
    } else if (present_full_) {
        glBlitFramebuffer(0, 0, w_, h_, 0, 0, w_, h_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        present_full_ = false;
    } else {
        for (const auto* list : {&damage_, &previous_damage_})
            for (const Rect& d : *list) {
                const int x0 = static_cast<int>(d.x), x1 = static_cast<int>(std::ceil(d.x + d.w));
                const int y0 = h_ - static_cast<int>(std::ceil(d.y + d.h)), y1 = h_ - static_cast<int>(d.y);
                glBlitFramebuffer(x0, y0, x1, y1, x0, y0, x1, y1, GL_COLOR_BUFFER_BIT, GL_NEAREST);
            }
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void Canvas::unbind() { glBindFramebuffer(GL_FRAMEBUFFER, 0); }

void Canvas::bind_window_for_read() {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
}

void Canvas::bind_for_read() {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
}

}  // namespace alp85::gui
