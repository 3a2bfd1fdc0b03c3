// The window's pixels (the OpenGL back buffer just rendered) to a PNG file, through cairo.
#pragma once

#include <string>

namespace alp85::gui {

// Reads width x height pixels of the current GL read framebuffer and writes them to `path`.
// Throws std::runtime_error when the file cannot be written.
void save_screenshot(const std::string& path, int width, int height);

}  // namespace alp85::gui
