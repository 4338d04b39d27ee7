#pragma once
// LiveFrame: one frame of an interactive trial as it was shown — the exact camera (and the dynamic
// style's lens, if it follows the cursor), the participant's input that led to it, when it was shown
// and the SHA-256 of its rendered pixels. Every front end that shows live frames (the window, the
// browser) stores each one as an event of kind "frame" whose detail is frameJson(); `tlab replay`
// reads them back with parseFrameJson(), renders every camera again and compares the hashes.
#include <cstdint>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "renderer/scene/camera.hpp"
#include "study/run/canvas.hpp"

namespace tlab::study {

// The event kind a live frame is stored under.
inline constexpr const char* kFrameEvent = "frame";

struct LiveFrame {
  int index = 0;                   // 0 = the trial's first frame, counted per trial and session
  render::Camera camera;           // exactly as rendered (render::cameraText round-trips every float)
  std::optional<glm::vec2> lens;   // the dynamic lens centre in fractions of the picture, when it follows the cursor
  std::string input;               // what moved the view: "start", "drag DX,DY", "key FORWARD,TURN", "point X,Y", ...
  std::int64_t shownNs = 0;        // monotonic clock when the frame was shown (window: after the swap)
  std::string sha256;              // framePixelsSha256 of the rendered frame
  std::string encoding{};          // how it was sent: "png" (lossless), "jpeg quality=Q" (lossy); "" shown as rendered (the window)
};

// One part of LiveFrame::input: "drag 15,5", "key 1,0", "point 0.453125,0.21875" — `what` and two
// numbers, each written with 9 significant digits (a float's value reads back exactly). The window
// and the server write every input this way.
std::string frameInputPart(const char* what, double a, double b);

// SHA-256 of a frame's pixels: "WxH:" followed by its RGBA bytes, row 0 at the top — the same
// numbers wherever the frame is rendered, independent of any image encoding.
std::string framePixelsSha256(const Canvas& frame);

// One line of JSON: {"index":…, "camera":"eye=… target=… up=… fovy=… near=… far=…",
// "lens":[x,y] (when set), "input":"…", "shown_ns":…, "sha256":"…", "encoding":"…" (when set)}; floats
// written so they read back exactly.
std::string frameJson(const LiveFrame& frame);
// Throws std::invalid_argument naming the missing or bad field.
LiveFrame parseFrameJson(const std::string& json);

}  // namespace tlab::study
