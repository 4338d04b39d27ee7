#include "renderer/params/transfer_function.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb/stb_image.h>

#include "core/parse_number.hpp"

namespace tlab::render {

namespace {

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::istringstream in(text);
  std::string part;
  while (std::getline(in, part, separator)) parts.push_back(part);
  return parts;
}

double number(const std::string& text, const std::string& spec) {
  const auto v = core::parseFiniteNumber(text);
  if (!v) throw std::invalid_argument("transfer function '" + spec + "': '" + text + "' is not a number");
  return *v;
}

void requireUnit(double v, const std::string& spec) {
  if (v < 0.0 || v > 1.0) throw std::invalid_argument("transfer function '" + spec + "': values must lie in [0, 1]");
}

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

struct Png {
  int width = 0, height = 0;
  std::vector<unsigned char> rgba;
  glm::vec3 at(int x, int y) const {
    const unsigned char* p = &rgba[(std::size_t(y) * width + x) * 4];
    return glm::vec3(p[0], p[1], p[2]) / 255.0f;
  }
};

Png loadPng(const std::string& path) {
  Png png;
  int channels = 0;
  unsigned char* pixels = stbi_load(path.c_str(), &png.width, &png.height, &channels, 4);
  if (!pixels)
    throw std::invalid_argument("transfer function '" + path + "' is neither a built-in (" +
                                "fig6a, fig6b, fig7a, fig7b), inline points nor a readable PNG file");
  png.rgba.assign(pixels, pixels + std::size_t(png.width) * png.height * 4);
  stbi_image_free(pixels);
  return png;
}

// Piecewise-linear interpolation through (x, v) points sorted by x.
template <typename V>
V piecewiseLinear(const std::vector<std::pair<double, V>>& points, double x) {
  if (x <= points.front().first) return points.front().second;
  for (std::size_t i = 1; i < points.size(); ++i)
    if (x <= points[i].first) {
      const double t = (x - points[i - 1].first) / (points[i].first - points[i - 1].first);
      return points[i - 1].second + V(float(t)) * (points[i].second - points[i - 1].second);
    }
  return points.back().second;
}

// seed 002, Fig. 6 (read off the pictures): (a) convex bright, concave dark; (b) curved bright, flat dark.
const char* kFig6a = "points:-1=1,0=0.5,1=0";
const char* kFig6b = "points:-1=0.9,-0.3=0.45,0=0.25,0.3=0.45,1=0.9";
// seed 002, Fig. 7 (read off the pictures; rows near → far, columns |κ| = 0, 1/3, 2/3, 1): (a)
// transparent when flat and near, opacity growing quickly with curvature and with distance;
// (b) less focus in front, shape shown over a wider range of depth.
const char* kFig7a = "grid:0.05,0.5,0.85,0.95/0.3,0.7,0.95,1/0.7,0.9,1,1/0.9,1,1,1";
const char* kFig7b = "grid:0.05,0.3,0.55,0.75/0.1,0.35,0.6,0.8/0.15,0.45,0.7,0.85/0.25,0.55,0.75,0.9";

glm::vec3 bilinearRow(const std::vector<glm::vec3>& s, float u) {
  const float x = std::clamp(u, 0.0f, 1.0f) * float(s.size() - 1);
  const auto i = std::min<std::size_t>(std::size_t(x), s.size() - 2);
  return glm::mix(s[i], s[i + 1], x - float(i));
}

}  // namespace

CurvatureShadingFunction CurvatureShadingFunction::parse(const std::string& specIn) {
  const std::string spec = specIn == "fig6a" ? kFig6a : specIn == "fig6b" ? kFig6b : specIn;
  CurvatureShadingFunction f;
  f.samples_.resize(kSamples);
  if (startsWith(spec, "points:")) {
    std::vector<std::pair<double, glm::vec3>> points;
    for (const auto& p : split(spec.substr(7), ',')) {
      const auto eq = p.find('=');
      if (eq == std::string::npos)
        throw std::invalid_argument("transfer function '" + specIn + "': expected κ=value, got '" + p + "'");
      const double k = number(p.substr(0, eq), specIn), v = number(p.substr(eq + 1), specIn);
      if (k < -1.0 || k > 1.0) throw std::invalid_argument("transfer function '" + specIn + "': κ must lie in [-1, 1]");
      requireUnit(v, specIn);
      if (!points.empty() && k <= points.back().first)
        throw std::invalid_argument("transfer function '" + specIn + "': κ must be strictly ascending");
      points.emplace_back(k, glm::vec3(float(v)));
    }
    if (points.empty()) throw std::invalid_argument("transfer function '" + specIn + "' has no points");
    for (int i = 0; i < kSamples; ++i) f.samples_[i] = piecewiseLinear(points, -1.0 + 2.0 * i / (kSamples - 1));
  } else {
    const Png png = loadPng(spec);
    std::vector<glm::vec3> row(std::size_t(std::max(png.width, 2)));
    for (int x = 0; x < int(row.size()); ++x) row[x] = png.at(std::min(x, png.width - 1), png.height / 2);
    for (int i = 0; i < kSamples; ++i) f.samples_[i] = bilinearRow(row, float(i) / (kSamples - 1));
  }
  return f;
}

glm::vec3 CurvatureShadingFunction::at(float kappa) const {
  return bilinearRow(samples_, (std::clamp(kappa, -1.0f, 1.0f) + 1.0f) * 0.5f);
}

CurvatureOpacityFunction CurvatureOpacityFunction::parse(const std::string& specIn) {
  const std::string spec = specIn == "fig7a" ? kFig7a : specIn == "fig7b" ? kFig7b : specIn;
  // The control values as a grid g[row = depth][column = |κ|] sampled bilinearly.
  std::vector<std::vector<float>> grid;
  if (startsWith(spec, "grid:")) {
    for (const auto& row : split(spec.substr(5), '/')) {
      std::vector<float> values;
      for (const auto& v : split(row, ',')) {
        const double x = number(v, specIn);
        requireUnit(x, specIn);
        values.push_back(float(x));
      }
      if (!grid.empty() && values.size() != grid.front().size())
        throw std::invalid_argument("transfer function '" + specIn + "': every row needs the same number of values");
      grid.push_back(std::move(values));
    }
    if (grid.size() < 2 || grid.front().size() < 2)
      throw std::invalid_argument("transfer function '" + specIn + "': a grid needs at least 2x2 values");
  } else {
    const Png png = loadPng(spec);
    for (int y = png.height - 1; y >= 0; --y) {  // bottom row = near
      std::vector<float> values;
      for (int x = 0; x < png.width; ++x) values.push_back(png.at(x, y).r);
      if (values.size() == 1) values.push_back(values.front());
      grid.push_back(std::move(values));
    }
    if (grid.size() == 1) grid.push_back(grid.front());
  }
  CurvatureOpacityFunction f;
  f.samples_.resize(std::size_t(kSamples) * kSamples);
  const auto rows = grid.size(), cols = grid.front().size();
  for (int r = 0; r < kSamples; ++r)
    for (int c = 0; c < kSamples; ++c) {
      const float y = float(r) / (kSamples - 1) * float(rows - 1), x = float(c) / (kSamples - 1) * float(cols - 1);
      const auto i = std::min<std::size_t>(std::size_t(y), rows - 2), j = std::min<std::size_t>(std::size_t(x), cols - 2);
      const float ty = y - float(i), tx = x - float(j);
      const float top = glm::mix(grid[i][j], grid[i][j + 1], tx), bottom = glm::mix(grid[i + 1][j], grid[i + 1][j + 1], tx);
      f.samples_[std::size_t(r) * kSamples + c] = glm::mix(top, bottom, ty);
    }
  return f;
}

float CurvatureOpacityFunction::at(float absKappa, float depth) const {
  const float y = std::clamp(depth, 0.0f, 1.0f) * (kSamples - 1), x = std::clamp(absKappa, 0.0f, 1.0f) * (kSamples - 1);
  const int i = std::min(int(y), kSamples - 2), j = std::min(int(x), kSamples - 2);
  const float ty = y - float(i), tx = x - float(j);
  const auto s = [&](int r, int c) { return samples_[std::size_t(r) * kSamples + c]; };
  return glm::mix(glm::mix(s(i, j), s(i, j + 1), tx), glm::mix(s(i + 1, j), s(i + 1, j + 1), tx), ty);
}

}  // namespace tlab::render
