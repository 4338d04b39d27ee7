#pragma once
// What a form answer may be: every front end (window, browser, simulated observer) checks an
// answer with these functions before it is stored, and the runner checks again before storing.
#include <optional>
#include <string>

#include "study/design/experiment.hpp"

namespace tlab::study {

// Why `value` is not an answer to `field` ("" when it is). Likert: 1..points; choice: one of the
// options; number: within [min, max] (whole if integer); text: any (empty only if not required).
// In the participants' language (`texts`), English without.
std::string fieldError(const FormField& field, const std::string& value, const ParticipantTexts& texts = ParticipantTexts());

// The numeric value stored beside the text (likert and number; the option's 1-based position for
// a choice; none for text or an empty answer).
std::optional<double> fieldNumber(const FormField& field, const std::string& value);

// How the field is answered, for the screen ("Type a number from 16 to 120 and press Enter.").
std::string fieldHint(const FormField& field, const ParticipantTexts& texts);

}  // namespace tlab::study
