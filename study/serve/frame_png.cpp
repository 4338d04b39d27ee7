#include "study/serve/frame_png.hpp"

#include <png.h>
#include <zlib.h>

#include <stdexcept>
#include <vector>

namespace tlab::study {

namespace {

void append(png_structp png, png_bytep data, png_size_t size) {
  auto* out = static_cast<std::string*>(png_get_io_ptr(png));
  out->append(reinterpret_cast<const char*>(data), size);
}

void flush(png_structp) {}

[[noreturn]] void fail(png_structp, png_const_charp message) { throw std::runtime_error(std::string("PNG of a live frame: ") + message); }

void warn(png_structp, png_const_charp) {}

// libpng's write struct and info, freed whatever happens.
struct PngWriter {
  png_structp png = nullptr;
  png_infop info = nullptr;
  PngWriter() {
    png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, fail, warn);
    if (!png) throw std::runtime_error("PNG of a live frame: libpng could not start");
    info = png_create_info_struct(png);
  }
  ~PngWriter() { png_destroy_write_struct(&png, &info); }
  PngWriter(const PngWriter&) = delete;
  PngWriter& operator=(const PngWriter&) = delete;
};

}  // namespace

std::string encodeFramePng(const Canvas& frame) {
  std::string out;
  out.reserve(frame.rgba().size() / 4);
  PngWriter w;
  if (!w.info) throw std::runtime_error("PNG of a live frame: libpng could not start");
  png_set_write_fn(w.png, &out, append, flush);
  png_set_IHDR(w.png, w.info, png_uint_32(frame.width()), png_uint_32(frame.height()), 8, PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_filter(w.png, PNG_FILTER_TYPE_BASE, PNG_FILTER_UP);
  png_set_compression_level(w.png, 1);
  png_set_compression_strategy(w.png, Z_RLE);
  std::vector<png_bytep> rows(std::size_t(frame.height()));
  auto* pixels = const_cast<png_bytep>(frame.rgba().data());  // libpng only reads the rows
  for (std::size_t y = 0; y < rows.size(); ++y) rows[y] = pixels + y * std::size_t(frame.width()) * 4;
  png_set_rows(w.png, w.info, rows.data());
  png_write_png(w.png, w.info, PNG_TRANSFORM_IDENTITY, nullptr);
  return out;
}

}  // namespace tlab::study
