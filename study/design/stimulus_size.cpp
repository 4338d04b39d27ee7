#include "study/design/stimulus_size.hpp"

#include <sstream>
#include <stdexcept>
#include <vector>

#include "study/design/experiment_file.hpp"

namespace tlab::study {

namespace {

std::string trimmed(const std::string& s) {
  const auto begin = s.find_first_not_of(" \t\r");
  if (begin == std::string::npos) return "";
  return s.substr(begin, s.find_last_not_of(" \t\r") - begin + 1);
}

bool isHeader(const std::string& line) { return !trimmed(line).empty() && trimmed(line).front() == '['; }

bool isSizeLine(const std::string& line) {
  const std::string t = trimmed(line);
  return t.rfind("size", 0) == 0 && trimmed(t.substr(4)).rfind('=', 0) == 0;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

}  // namespace

std::string withStimulusSize(const std::string& text, const std::string& size) {
  const std::string sizeLine = "size = \"" + size + "\"";
  std::vector<std::string> all = lines(text);
  std::size_t header = all.size();
  for (std::size_t i = 0; i < all.size() && header == all.size(); ++i)
    if (trimmed(all[i]) == "[stimulus]") header = i;
  if (header == all.size()) {
    all.insert(all.end(), {"", "[stimulus]", sizeLine});
  } else {
    std::size_t i = header + 1;
    while (i < all.size() && !isHeader(all[i]) && !isSizeLine(all[i])) ++i;
    if (i < all.size() && isSizeLine(all[i])) all[i] = sizeLine;
    else all.insert(all.begin() + std::ptrdiff_t(header) + 1, sizeLine);
  }
  std::string out;
  for (const auto& line : all) out += line + "\n";
  return out;
}

Experiment withStimulusSize(const Experiment& experiment, const std::string& size) {
  return parseExperiment(withStimulusSize(experiment.text, size), experiment.path, StimulusChecks::Skip);
}

}  // namespace tlab::study
