#pragma once
// The screens of `tlab serve` the serve fuzz targets send replies to: a trial of every answer
// kind (hand-made questions with candidate and mark labels, a floor plan, one with a turntable), a
// form with every field kind, consent and a message. Built once; kept alive for the whole run.
#include <memory>
#include <vector>

#include "study/serve/flow_pages.hpp"
#include "study/serve/trial_page.hpp"
#include "tasks/answer_form.hpp"
#include "tasks/gauge_frame.hpp"

namespace tlab::fuzz {

struct ServeScreens {
  study::PlannedTrial plan;
  std::vector<std::unique_ptr<study::PreparedTrial>> prepared;
  std::vector<study::Screen> screens;
};

inline const ServeScreens& serveScreens() {
  static const ServeScreens built = [] {
    ServeScreens s;
    s.plan.stimulus.width = s.plan.stimulus.height = 64;
    const std::string sha(64, 'a');
    constexpr int kKinds = 7;
    for (int kind = 0; kind <= kKinds; ++kind) {  // the seven answer kinds, then a layer-number trial with a turntable
      auto p = std::make_unique<study::PreparedTrial>();
      p->question.answerKind = static_cast<tasks::AnswerKind>(kind % kKinds);
      p->question.measurements = {{"layer", 1}, {"gauge-radius-px", 8}, {"start-slant", 10}, {"start-tilt", 20}};
      tasks::keepGaugeFrame(p->question, tasks::GaugeFrame{});
      p->question.points = {{"A", "probe", {}, {10, 10}, 0}, {"B", "candidate", {}, {20, 20}, 1}, {"C", "candidate", {}, {30, 30}, 2},
                            {"D", "mark", {}, {40, 40}, 3},  {"E", "mark", {}, {50, 50}, 4}};
      p->stimulusSha256 = sha;
      study::TrialImages images;
      if (tasks::answerForm(p->question).widget(p->question).kind == tasks::WidgetKind::FloorPlanPoint) {
        p->floorPlan = study::FloorPlan{};
        p->floorPlan->camera.eye = {0.0f, 5.0f, 0.01f};
        p->floorPlan->width = 48;
        p->floorPlan->height = 32;
        images.floorPlanSha256 = std::string(64, 'b');
      }
      if (kind == kKinds) {
        study::Turntable t{3, 2, 1, 0, {}};
        for (int v = 0; v < 6; ++v) t.views.push_back({v % 3, v / 3, 30.0 * v, 10.0, std::string(63, 'c') + char('0' + v), "view " + std::to_string(v)});
        images.turntable = t;
      }
      study::TrialView view{s.plan, *p, 30.0, 1, 7, {}};
      s.screens.push_back(study::trialScreen(view, images));
      s.prepared.push_back(std::move(p));
    }
    std::vector<study::FormField> fields(4);
    fields[0].id = "likert";
    fields[1] = {"choice", "Which?", study::FieldKind::Choice};
    fields[1].options = {"yes", "no", "\xc3\xa9t\xc3\xa9"};
    fields[2] = {"age", "Age", study::FieldKind::Number};
    fields[2].minimum = 18;
    fields[2].maximum = 99;
    fields[2].integer = true;
    fields[3] = {"comment", "Anything else?", study::FieldKind::Text};
    fields[3].required = false;
    s.screens.push_back(study::formScreen("About you", fields, study::ParticipantTexts()));
    s.screens.push_back(study::consentScreen("Consent", {"Do you agree?"}));
    s.screens.push_back(study::messageScreen("Welcome", "Hello"));
    return s;
  }();
  return built;
}

}  // namespace tlab::fuzz
