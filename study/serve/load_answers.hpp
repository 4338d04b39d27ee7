#pragma once
// What a simulated browser (tlab loadtest) sends for a screen: the reply a participant could give,
// chosen at random from what the page was sent — the labels offered, the letters, the floor plan's
// size, the form's fields — never from a truth (the page has none). Pure functions, so the choice
// is testable and reproducible from the seed.
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace tlab::study {

// The reply body ({"type": "answer", "answer": ..., "rt_ms": ...}) for a trial page, or
// {"type": "timeout"} when the page offers nothing to answer with (a label question without labels).
nlohmann::json loadAnswer(const nlohmann::json& trialPage, double rtMs, std::mt19937_64& rng);

// The reply body ({"type": "form", "values": [...]}) for a form page: one valid text per field.
nlohmann::json loadFormValues(const nlohmann::json& formPage, std::mt19937_64& rng);

// The SHA-256 names of the images a page shows (stimulus, floor plan, every turntable view): a
// browser fetches them all (the turntable preloads its views).
std::vector<std::string> pageImages(const nlohmann::json& page);

}  // namespace tlab::study
