#pragma once
// Parsers from typed answer text to values. Each error names what was expected and what was
// given, so a bad `tlab task check --answer` or a bad response file is easy to fix.
#include <cstdint>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "tasks/question.hpp"

namespace tlab::tasks {

// A refused answer. what() is the English message for logs and the command line; `key` (a key of
// the participant text table's [refusal], study/design/texts/en.toml) and `args` say the same to a
// participant in the experiment's language. An empty key: a refusal no participant's input can
// cause (a hostile or broken client), said in English only.
class AnswerFormatError : public std::invalid_argument {
 public:
  explicit AnswerFormatError(const std::string& message, std::string key = "", std::map<std::string, std::string> args = {})
      : std::invalid_argument(message), key_(std::move(key)), args_(std::move(args)) {}
  const std::string& key() const { return key_; }
  const std::map<std::string, std::string>& args() const { return args_; }

 private:
  std::string key_;
  std::map<std::string, std::string> args_;
};

std::int64_t parseLayerNumber(const std::string& text);   // whole number >= 1
std::int64_t parseCount(const std::string& text);         // whole number >= 0
// Labels separated by commas and/or spaces; "none", "-" or "" is the empty set. Every label must
// be one of `allowed`; repeated labels are an error.
std::set<std::string> parseLabelSet(const std::string& text, const std::vector<std::string>& allowed);
std::string parseLabel(const std::string& text, const std::vector<std::string>& allowed);
glm::dvec2 parseFloorPoint(const std::string& text);       // "X,Z"
std::string parseLetter(const std::string& text);          // C, K, R, X or Y (either case)
glm::dvec3 parseDirection(const std::string& text);        // "x,y,z", not all 0; normalized

// Parses `text` as the question's answer kind into the same alternative as its ground truth
// (its answer form's parser).
GroundTruth parseAnswer(const Question& question, const std::string& text);

}  // namespace tlab::tasks
