#include "tasks/letter_patterns.hpp"

#include <cmath>
#include <complex>
#include <stdexcept>

namespace tlab::tasks {

const std::string& patternLetters() {
  static const std::string letters = "CKRXY";
  return letters;
}

const std::array<std::string, kLetterRows>& letterBitmap(char letter) {
  static const std::array<std::string, kLetterRows> c = {".###.", "#...#", "#....", "#....", "#....", "#...#", ".###."};
  static const std::array<std::string, kLetterRows> k = {"#...#", "#..#.", "#.#..", "##...", "#.#..", "#..#.", "#...#"};
  static const std::array<std::string, kLetterRows> r = {"####.", "#...#", "#...#", "####.", "#.#..", "#..#.", "#...#"};
  static const std::array<std::string, kLetterRows> x = {"#...#", "#...#", ".#.#.", "..#..", ".#.#.", "#...#", "#...#"};
  static const std::array<std::string, kLetterRows> y = {"#...#", "#...#", ".#.#.", "..#..", "..#..", "..#..", "..#.."};
  switch (letter) {
    case 'C': return c;
    case 'K': return k;
    case 'R': return r;
    case 'X': return x;
    case 'Y': return y;
  }
  throw std::invalid_argument(std::string("no pattern letter '") + letter + "' (known: C, K, R, X, Y)");
}

std::vector<glm::ivec2> letterCells(char letter) {
  const auto& bitmap = letterBitmap(letter);
  std::vector<glm::ivec2> cells;
  for (int r = 0; r < kLetterRows; ++r)
    for (int c = 0; c < kLetterColumns; ++c)
      if (bitmap[r][c] == '#') cells.push_back({c, r});
  return cells;
}

std::vector<glm::dvec2> letterFloorPositions(char letter, glm::dvec2 origin, double cellSize, double angle) {
  const double ca = std::cos(angle), sa = std::sin(angle);
  std::vector<glm::dvec2> out;
  for (const auto& cell : letterCells(letter)) {
    const glm::dvec2 p = glm::dvec2(cell) * cellSize;
    out.push_back(origin + glm::dvec2(p.x * ca + p.y * sa, -p.x * sa + p.y * ca));
  }
  return out;
}

namespace {

using Complex = std::complex<double>;
Complex asComplex(glm::dvec2 p) { return {p.x, p.y}; }

// Whether `cells` mapped by z ↦ a·z + b lands on `points` one to one, each within `radius`.
bool mapsOnto(const std::vector<Complex>& cells, Complex a, Complex b, const std::vector<Complex>& points, double radius) {
  std::vector<bool> used(points.size(), false);
  for (const auto& c : cells) {
    const Complex mapped = a * c + b;
    bool found = false;
    for (std::size_t i = 0; i < points.size() && !found; ++i)
      if (!used[i] && std::abs(points[i] - mapped) <= radius) used[i] = found = true;
    if (!found) return false;
  }
  return true;
}

bool letterMatches(char letter, const std::vector<Complex>& points, double tolerance) {
  std::vector<Complex> cells;
  for (const auto& c : letterCells(letter)) cells.push_back(Complex(c.x, c.y));
  if (cells.size() != points.size() || points.size() < 2) return false;
  // The farthest pair of points must be the image of a farthest pair of cells (a similarity
  // keeps the order of distances), which fixes rotation, scale and translation.
  std::size_t pa = 0, pb = 1;
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = i + 1; j < points.size(); ++j)
      if (std::abs(points[i] - points[j]) > std::abs(points[pa] - points[pb])) pa = i, pb = j;
  double cellMax = 0.0;
  for (const auto& a : cells)
    for (const auto& b : cells) cellMax = std::max(cellMax, std::abs(a - b));
  for (const auto& ci : cells)
    for (const auto& cj : cells) {
      if (std::abs(std::abs(ci - cj) - cellMax) > 1e-9) continue;
      const Complex a = (points[pb] - points[pa]) / (cj - ci);  // rotation · scale
      const Complex b = points[pa] - a * ci;
      if (mapsOnto(cells, a, b, points, tolerance * std::abs(a))) return true;
    }
  return false;
}

}  // namespace

std::vector<char> matchingLetters(const std::vector<glm::dvec2>& points, double tolerance) {
  std::vector<Complex> z;
  for (const auto& p : points) z.push_back(asComplex(p));
  std::vector<char> out;
  for (const char letter : patternLetters())
    if (letterMatches(letter, z, tolerance)) out.push_back(letter);
  return out;
}

}  // namespace tlab::tasks
