#pragma once
// A live frame as a JPEG ([online] frames = "jpeg"): lossy, chosen by the experimenter and logged
// with every frame (LiveFrame::encoding); the frame's SHA-256 stays that of the rendered pixels, so
// `tlab replay` checks the frames exactly whatever was sent. libjpeg-turbo, 4:2:0 chroma at the
// given quality; on 512² frames about ten times faster to write than the PNG and under half its size.
#include <string>

#include "study/run/canvas.hpp"

namespace tlab::study {

// The JPEG file's bytes at `quality` (1..100); throws std::runtime_error when libjpeg fails.
std::string encodeFrameJpeg(const Canvas& frame, int quality);

}  // namespace tlab::study
