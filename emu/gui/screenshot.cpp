#include "emu/gui/screenshot.h"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <SDL_opengl.h>
#include <cairo.h>

#include "asm/files/atomic_file.h"

namespace alp85::gui {

void save_screenshot(const std::string& path, int width, int height) {
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    // cairo's ARGB32: native-endian 32-bit words, rows top first (GL's are bottom first).
    cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height);
    cairo_surface_flush(s);
    std::uint8_t* data = cairo_image_surface_get_data(s);
    const int stride = cairo_image_surface_get_stride(s);
    for (int y = 0; y < height; ++y) {
        const std::uint8_t* src = rgba.data() + static_cast<std::size_t>(height - 1 - y) * static_cast<std::size_t>(width) * 4;
        auto* dst = reinterpret_cast<std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
        for (int x = 0; x < width; ++x, src += 4)
            dst[x] = 0xFF000000u | std::uint32_t{src[0]} << 16 | std::uint32_t{src[1]} << 8 | src[2];
    }
    cairo_surface_mark_dirty(s);
    // Encoded in memory, then written whole or not at all (a killed run leaves no half a PNG).
    std::string png;
    const cairo_status_t st = cairo_surface_write_to_png_stream(
        s,
        [](void* out, const unsigned char* bytes, unsigned int n) {
            static_cast<std::string*>(out)->append(reinterpret_cast<const char*>(bytes), n);
            return CAIRO_STATUS_SUCCESS;
        },
        &png);
    cairo_surface_destroy(s);
    if (st != CAIRO_STATUS_SUCCESS)
        throw std::runtime_error("screenshot " + path + ": " + cairo_status_to_string(st));
    write_atomic(path, png);
}

}  // namespace alp85::gui
