#pragma once
// LoggedTrial: an interactive trial as the study database holds it — the planned trial rebuilt
// from the experiment text stored with the version the participant ran and their slot (scene,
// style, render settings, size, navigation), its live frames ("frame" events,
// study/run/frame_log.hpp) in the order shown, the answer given, and what each session that showed
// it stored of its GL renderer and tlab version. Read-only: the store is only queried.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "study/design/session_plan.hpp"
#include "study/run/frame_log.hpp"
#include "study/store/store.hpp"

namespace tlab::study {

// What a session that showed the trial stored of how it rendered ("" where it stored nothing).
struct FrameSession {
  std::string mode;         // window, browser, autopilot, ...
  std::string glRenderer;   // its display JSON's gl_renderer: the GL that rendered the live frames
  std::string tlabVersion;  // its display JSON's tlab_version
};

struct LoggedFrame {
  LiveFrame frame;
  std::int64_t session = 0;
};

struct LoggedTrial {
  std::string location;  // the store, for messages
  std::string experimentId;
  std::string participant;
  PlannedTrial plan;
  std::string question;               // the question's text
  std::string truth;                  // its ground truth (JSON)
  std::optional<std::string> answer;  // the answer given; nullopt: none (missing or not stored yet)
  std::optional<bool> correct;        // nullopt: no response stored
  std::optional<double> rtSeconds;
  std::int64_t responseNs = 0;        // when the answer was given (0: no response stored)
  std::vector<LoggedFrame> frames;    // in the order stored; a frame with index 0 starts a showing
  std::map<std::int64_t, FrameSession> sessions;
};

// The trial whose `sequence` (its 1-based place in the participant's session, the `sequence` of
// tlab export's trials.csv) is given. `experimentId` may be empty when the store holds one
// experiment. Throws StoreError with one line naming what is wrong: no such experiment or
// participant, no such trial, a trial that is not interactive or has no frames logged.
LoggedTrial loadLoggedTrial(Store& store, const std::string& experimentId, const std::string& participant, int sequence);

// "trial 3 of participant 'P1'", for messages.
std::string trialName(const LoggedTrial& trial);

}  // namespace tlab::study
