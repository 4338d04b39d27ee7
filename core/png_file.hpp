#pragma once
// Reads a PNG file (8 or 16 bits, grey, RGB or RGBA) into an Image, row 0 = top, channels in
// [0, 1]; images from another renderer enter tlab this way.
#include <optional>
#include <string>

#include "core/image.hpp"

namespace tlab::core {

// nullopt when the file cannot be read or is not a PNG.
std::optional<Image> readPngFile(const std::string& path);

}  // namespace tlab::core
