#pragma once
// The five pattern letters of Elmqvist T2 ("C, K, R, X, and Y, rasterized in a 5 × 7 horizontal
// grid ... rotated in an arbitrary fashion around the vertical axis", Elmqvist Sec. 4, Fig. 5),
// their placement on the floor plan, and the identification of a letter from target positions.
//
// Floor-plan coordinates are world (x, z) seen from above (+y): bitmap column → +x and bitmap
// row (row 0 = top line of the letter) → +z, so a plan drawn with x to the right and z downward
// shows the letter upright and unmirrored.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace tlab::tasks {

constexpr int kLetterColumns = 5;
constexpr int kLetterRows = 7;

// "CKRXY".
const std::string& patternLetters();

// 7 rows of 5 characters, '#' = target, '.' = empty. Throws for a letter not in patternLetters().
const std::array<std::string, kLetterRows>& letterBitmap(char letter);

// The filled cells as (column, row).
std::vector<glm::ivec2> letterCells(char letter);

// Floor positions (x, z) of the letter's cells: cell (c, r) at `origin` + R(angle) · (c, r) ·
// cellSize, with R the rotation about the vertical axis (x, z) → (x cos a + z sin a, −x sin a + z cos a).
std::vector<glm::dvec2> letterFloorPositions(char letter, glm::dvec2 origin, double cellSize, double angleRadians);

// The letters whose cells match `points` one to one under some rotation, uniform scale and
// translation in the floor plane (no mirroring), to `tolerance` cell sizes. Empty: no letter.
std::vector<char> matchingLetters(const std::vector<glm::dvec2>& points, double tolerance = 0.25);

}  // namespace tlab::tasks
