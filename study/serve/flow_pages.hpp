#pragma once
// The screens of the session flow other than trials, for the browser front end: a message
// (welcome, instructions, "training is over", debrief), consent, a form (participant information,
// questionnaires), training feedback, a break, and the end. Each is the page's JSON plus the check
// of its reply; form answers are checked here with the same rule the runner applies again
// (study/design/form_field.hpp), so a bad value is refused with a message before it reaches the flow.
#include <optional>
#include <string>
#include <vector>

#include "study/design/experiment.hpp"
#include "study/run/responder.hpp"
#include "study/serve/session_channel.hpp"

namespace tlab::study {

Screen messageScreen(const std::string& title, const std::string& text);
Screen consentScreen(const std::string& title, const ConsentSpec& consent);
// A refused answer says why in the participants' language (`texts`).
Screen formScreen(const std::string& title, const std::vector<FormField>& fields, const ParticipantTexts& texts);
Screen feedbackScreen(const TrialView& view, const Feedback& feedback);
Screen breakScreen(const BreakSpec& spec);
// Screens that take no reply.
Screen endScreen(const std::string& title, const std::string& text, const std::string& completionCode, const std::string& completionUrl);
Screen waitScreen();
// The credit-card size calibration: the reply is the card's width in CSS px and device px per cm
// with the number of adjustments (at least one), or skipped ("I have no card", when `noCard`).
Screen calibrationScreen(bool noCard);
// The page that refuses a device [online] devices does not allow (the page's display report says
// "device": desktop, tablet or phone), saying why; nullopt when the device may take part.
std::optional<nlohmann::json> deviceRefusal(const Experiment& experiment, const nlohmann::json& display);

}  // namespace tlab::study
