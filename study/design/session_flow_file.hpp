#pragma once
// The experiment file's sections for the participant's session flow: participant_title, welcome,
// [consent], [[info]] (and standard_info = true: age, gender, vision), [training] feedback,
// [breaks], [debrief] (text, completion_code; `goodbye` is its older name) and
// [[questionnaires]] with items of kinds likert, choice, number and text; `language` and [text]
// (the participant texts, read first: the sections' defaults are texts of the table).
#include <toml++/toml.h>

#include "study/design/experiment.hpp"
#include "study/design/field_reader.hpp"

namespace tlab::study {

void readParticipantTexts(const FieldReader& r, const toml::table& root, Experiment& e);
void readSessionFlow(const FieldReader& r, const toml::table& root, Experiment& e);
std::vector<Questionnaire> readQuestionnaires(const FieldReader& r, const toml::table& root, const ParticipantTexts& texts);

}  // namespace tlab::study
