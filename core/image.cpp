#include "core/image.hpp"

#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

namespace tlab::core {

std::vector<std::uint8_t> toRgba8(const Image& image) {
  std::vector<std::uint8_t> out(image.pixels.size() * 4);
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    for (int c = 0; c < 4; ++c) {
      const float v = std::clamp(image.pixels[i][c], 0.0f, 1.0f);
      out[i * 4 + c] = static_cast<std::uint8_t>(std::lround(v * 255.0f));
    }
  return out;
}

std::vector<std::uint8_t> encodePng(const Image& image) {
  const auto rgba = toRgba8(image);
  std::vector<std::uint8_t> png;
  const auto sink = [](void* context, void* data, int size) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(context);
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    out->insert(out->end(), bytes, bytes + size);
  };
  if (!stbi_write_png_to_func(sink, &png, image.width, image.height, 4, rgba.data(), image.width * 4))
    throw std::runtime_error("cannot encode a " + std::to_string(image.width) + "x" + std::to_string(image.height) + " PNG");
  return png;
}

std::vector<std::uint8_t> encodePgm16(const std::vector<std::uint16_t>& values, int width, int height) {
  const std::string header = "P5\n" + std::to_string(width) + " " + std::to_string(height) + "\n65535\n";
  std::vector<std::uint8_t> out(header.begin(), header.end());
  out.reserve(out.size() + values.size() * 2);
  for (auto v : values) {
    out.push_back(static_cast<std::uint8_t>(v >> 8));
    out.push_back(static_cast<std::uint8_t>(v & 0xFF));
  }
  return out;
}

void writeFileAtomically(const std::string& path, const std::vector<std::uint8_t>& bytes) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  const fs::path temp = target.parent_path() / (target.filename().string() + ".tmp" + std::to_string(::getpid()));
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(path + ": cannot write (does the folder exist and is it writable?)");
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out) {
      out.close();
      std::error_code ec;
      fs::remove(temp, ec);
      throw std::runtime_error(path + ": write failed (disk full?)");
    }
  }
  std::error_code ec;
  fs::rename(temp, target, ec);
  if (ec) {
    fs::remove(temp, ec);
    throw std::runtime_error(path + ": cannot be written: " + ec.message());
  }
}

void writeFilesAtomically(const std::vector<std::pair<std::string, std::vector<std::uint8_t>>>& files) {
  std::size_t written = 0;
  try {
    for (; written < files.size(); ++written) writeFileAtomically(files[written].first, files[written].second);
  } catch (...) {
    std::error_code ec;
    for (std::size_t i = 0; i < written; ++i) std::filesystem::remove(files[i].first, ec);
    throw;
  }
}

}  // namespace tlab::core
