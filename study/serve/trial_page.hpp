#pragma once
// The trial screen of the browser front end: what the page gets (the picture's SHA-256 name and
// size, the labels it may click, the answer format, the time limit, the floor plan and the
// turntable views) and the check of what it sends back. The ground truth stays on the server: the
// page never sees it, and scoring happens in the session flow (TrialRunner) as for every front end.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "study/run/responder.hpp"
#include "study/serve/session_channel.hpp"

namespace tlab::study {

// One pre-rendered view of an orbit trial (Elmqvist ABSTRACT explored online).
struct TurntableView {
  int azimuth = 0, elevation = 0;  // indices
  double azimuthDegrees = 0.0, elevationDegrees = 0.0;
  std::string sha256;
  std::string camera;  // CameraNavigator::describe(), logged with each view change
};

struct Turntable {
  int azimuths = 0, elevations = 0;
  int startAzimuth = 0, startElevation = 0;
  std::vector<TurntableView> views;  // azimuth-major within each elevation: index = e * azimuths + a
};

// The SHA-256 name of the floor plan image of a FloorPoint trial ("" when none).
struct TrialImages {
  std::string floorPlanSha256;
  std::optional<Turntable> turntable;
  bool live = false;  // an orbit or walk trial whose views the server renders live ([online] live)
};

// A live trial's screen carries its LiveTrial (made anew for each screen: a trial starts at its
// start camera) and its page {"live": {"navigation": "orbit"|"walk", "lens": bool}}.
Screen trialScreen(const TrialView& view, const TrialImages& images);

// What checking an answer needs of a trial (kept by value: a reply may come late).
struct AnswerContext {
  tasks::Question question;
  std::optional<FloorPlan> floorPlan;
};

// The answer text the session flow scores, from the page's JSON answer to the question; throws
// std::invalid_argument with the reason for anything else (a wrong type, a label that is not
// offered, a click outside the floor plan). Shared by the check and the fuzz target.
std::string answerText(const AnswerContext& context, const nlohmann::json& answer);

}  // namespace tlab::study
