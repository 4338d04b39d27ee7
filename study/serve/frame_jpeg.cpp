#include "study/serve/frame_jpeg.hpp"

// jpeglib.h needs FILE and size_t declared before it.
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include <jpeglib.h>

namespace tlab::study {

namespace {

[[noreturn]] void fail(j_common_ptr info) {
  char message[JMSG_LENGTH_MAX];
  (*info->err->format_message)(info, message);
  throw std::runtime_error(std::string("JPEG of a live frame: ") + message);
}

// libjpeg's compressor and its output buffer, freed whatever happens.
struct JpegWriter {
  jpeg_compress_struct info{};
  jpeg_error_mgr errors{};
  unsigned char* bytes = nullptr;
  unsigned long size = 0;
  JpegWriter() {
    info.err = jpeg_std_error(&errors);
    errors.error_exit = fail;
    jpeg_create_compress(&info);
    jpeg_mem_dest(&info, &bytes, &size);
  }
  ~JpegWriter() {
    jpeg_destroy_compress(&info);
    std::free(bytes);
  }
  JpegWriter(const JpegWriter&) = delete;
  JpegWriter& operator=(const JpegWriter&) = delete;
};

}  // namespace

std::string encodeFrameJpeg(const Canvas& frame, int quality) {
  if (quality < 1 || quality > 100) throw std::invalid_argument("JPEG of a live frame: quality must be between 1 and 100");
  JpegWriter w;
  w.info.image_width = JDIMENSION(frame.width());
  w.info.image_height = JDIMENSION(frame.height());
  w.info.input_components = 4;
  w.info.in_color_space = JCS_EXT_RGBA;  // libjpeg-turbo reads the canvas's RGBA rows as they are (alpha ignored)
  jpeg_set_defaults(&w.info);
  jpeg_set_quality(&w.info, quality, TRUE);
  jpeg_start_compress(&w.info, TRUE);
  const std::size_t stride = std::size_t(frame.width()) * 4;
  auto* pixels = const_cast<JSAMPLE*>(frame.rgba().data());  // libjpeg only reads the rows
  while (w.info.next_scanline < w.info.image_height) {
    JSAMPROW row = pixels + std::size_t(w.info.next_scanline) * stride;
    jpeg_write_scanlines(&w.info, &row, 1);
  }
  jpeg_finish_compress(&w.info);
  return std::string(reinterpret_cast<const char*>(w.bytes), w.size);
}

}  // namespace tlab::study
