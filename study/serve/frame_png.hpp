#pragma once
// A live frame as a PNG, fast: lossless RGBA (the participant sees exactly the rendered pixels),
// written by libpng with the Sub filter and zlib's fastest level — a live frame is sent once and
// must not wait for compression (the stimuli's PNGs keep core::encodePng, byte for byte).
#include <string>

#include "study/run/canvas.hpp"

namespace tlab::study {

// The PNG file's bytes; throws std::runtime_error when libpng fails.
std::string encodeFramePng(const Canvas& frame);

}  // namespace tlab::study
