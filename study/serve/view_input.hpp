#pragma once
// ViewInput: what the participant page of a live trial sends to move its view (POST
// /api/<token>/view) — the mouse drag, the arrow keys and the wheel accumulated while the previous
// frame was on its way, and the cursor over the picture (the dynamic style's lens). The page sends
// only input: the camera itself is the server's (CameraNavigator), so a participant can move it only
// the way the window lets them. Checked here, apart from the server, so the serve_view fuzz target
// reaches the check without a socket.
#include <optional>
#include <string>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace tlab::study {

struct ViewInput {
  double dx = 0.0, dy = 0.0;       // dragged CSS pixels of the picture, summed
  int forward = 0, turn = 0;       // arrow-key presses (Up − Down, Right − Left) and wheel steps (forward)
  std::optional<glm::vec2> point;  // the cursor in fractions of the picture ((0, 0): top left), the latest

  bool empty() const { return dx == 0.0 && dy == 0.0 && forward == 0 && turn == 0 && !point; }
  // This input followed by `later` (a frame request dropped for a newer one gives its input to it).
  ViewInput then(const ViewInput& later) const;
  // "start", or the parts that moved: "drag DX,DY key FORWARD,TURN point X,Y" (LiveFrame::input).
  std::string describe() const;
};

// Per message: at most this many pixels dragged along each axis and this many key presses and wheel
// steps (a page sends what piled up during one frame; more is no person's input).
inline constexpr double kMaxDragPixels = 4000.0;
inline constexpr int kMaxKeySteps = 40;

// The "input" object of a view request: {"dx": n, "dy": n, "forward": k, "turn": k, "point": [x, y]},
// every field optional; numbers finite and within the limits above, the point within [0, 1]².
// Throws std::invalid_argument with the reason for anything else (unknown fields included).
ViewInput parseViewInput(const nlohmann::json& input);

}  // namespace tlab::study
