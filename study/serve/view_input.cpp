#include "study/serve/view_input.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>

#include "study/run/frame_log.hpp"

namespace tlab::study {

namespace {

double boundedNumber(const nlohmann::json& v, const char* name, double limit) {
  if (!v.is_number()) throw std::invalid_argument(std::string("'") + name + "' must be a number");
  const double x = v.get<double>();
  if (!std::isfinite(x) || std::abs(x) > limit) throw std::invalid_argument(std::string("'") + name + "' is out of range");
  return x;
}

int boundedSteps(const nlohmann::json& v, const char* name) {
  if (!v.is_number_integer()) throw std::invalid_argument(std::string("'") + name + "' must be a whole number of steps");
  const std::int64_t k = v.get<std::int64_t>();
  if (k < -kMaxKeySteps || k > kMaxKeySteps) throw std::invalid_argument(std::string("'") + name + "' is out of range");
  return int(k);
}

}  // namespace

ViewInput ViewInput::then(const ViewInput& later) const {
  ViewInput sum;
  sum.dx = dx + later.dx;
  sum.dy = dy + later.dy;
  sum.forward = forward + later.forward;
  sum.turn = turn + later.turn;
  sum.point = later.point ? later.point : point;
  return sum;
}

std::string ViewInput::describe() const {
  if (empty()) return "start";
  std::string text;  // one summed input: its parts joined by spaces
  auto add = [&text](const std::string& part) { text += (text.empty() ? "" : " ") + part; };
  if (dx != 0.0 || dy != 0.0) add(frameInputPart("drag", dx, dy));
  if (forward != 0 || turn != 0) add(frameInputPart("key", forward, turn));
  if (point) add(frameInputPart("point", point->x, point->y));
  return text;
}

ViewInput parseViewInput(const nlohmann::json& input) {
  if (!input.is_object()) throw std::invalid_argument("'input' must be an object");
  if (input.size() > 5) throw std::invalid_argument("'input' has more than dx, dy, forward, turn and point");
  ViewInput v;
  for (const auto& [key, value] : input.items()) {
    if (key == "dx") v.dx = boundedNumber(value, "dx", kMaxDragPixels);
    else if (key == "dy") v.dy = boundedNumber(value, "dy", kMaxDragPixels);
    else if (key == "forward") v.forward = boundedSteps(value, "forward");
    else if (key == "turn") v.turn = boundedSteps(value, "turn");
    else if (key == "point") {
      if (!value.is_array() || value.size() != 2) throw std::invalid_argument("'point' must be [x, y]");
      const double x = boundedNumber(value[0], "point", 1.0), y = boundedNumber(value[1], "point", 1.0);
      if (x < 0.0 || y < 0.0) throw std::invalid_argument("'point' must lie on the picture (0 to 1)");
      v.point = glm::vec2(float(x), float(y));
    } else {
      throw std::invalid_argument("unknown input '" + key.substr(0, 24) + "' (expected dx, dy, forward, turn, point)");
    }
  }
  return v;
}

}  // namespace tlab::study
