#include "study/design/image_files.hpp"

#include <filesystem>
#include <regex>
#include <set>
#include <sstream>

#include "core/file_text.hpp"
#include "core/sha256.hpp"
#include "study/design/counterbalancing.hpp"
#include "study/design/experiment_file.hpp"

namespace tlab::study {

namespace {
const char* const kRecord = "# tlab image file ";
}  // namespace

std::vector<StimulusKey> externalImageStimuli(const Experiment& e) {
  bool any = false;
  for (const auto& f : e.factors)
    for (const auto& l : f.levels) any = any || l.images.has_value();
  if (!any) return {};
  const Design design = makeDesign(e);
  std::vector<StimulusKey> keys;
  std::set<std::string> seen;
  for (std::size_t slot = 0; slot < design.balancedMultiple(); ++slot)
    for (const auto& t : makeSessionPlan(e, design, int(slot)).trials)
      if (!t.stimulus.images.empty() && seen.insert(t.stimulus.images).second) keys.push_back(t.stimulus);
  return keys;
}

void refuseLiveViewsOfImages(const Experiment& e) {
  if (externalImageStimuli(e).empty()) return;
  const Design design = makeDesign(e);
  for (std::size_t slot = 0; slot < design.balancedMultiple(); ++slot)
    for (const auto& t : makeSessionPlan(e, design, int(slot)).trials)
      if (!t.stimulus.images.empty() && t.navigation != Navigation::None)
        for (const auto& task : e.tasks)
          if (task.id == t.taskId)
            throw ExperimentFileError(task.navigationSource + ": navigation = \"" + navigationName(t.navigation) +
                                      "\" draws tlab's live view of the scene, which cannot show the images from another renderer of " +
                                      t.condition + " (give the task a `when` without that level, or no navigation)");
}

std::vector<StyleFileUse> recordedImageFiles(const std::string& text) {
  static const std::regex line(R"(^# tlab image file (.+) = (.+) sha256 ([0-9a-f]{64})\r?$)");
  std::vector<StyleFileUse> uses;
  std::istringstream lines(text);
  for (std::string l; std::getline(lines, l);) {
    std::smatch m;
    if (std::regex_match(l, m, line)) uses.push_back({m[1], m[2], m[3]});
  }
  return uses;
}

void recordImageFiles(Experiment& e, bool readFiles) {
  if (!readFiles || !recordedImageFiles(e.text).empty()) return;
  namespace fs = std::filesystem;
  const fs::path folder = fs::absolute(e.path).parent_path();
  std::string trailer;
  for (const auto& key : externalImageStimuli(e)) {
    const auto bytes = core::readFileText(key.images);
    if (!bytes) continue;
    trailer += kRecord + fs::path(key.images).lexically_relative(folder).string() + " = " + key.images + " sha256 " + core::sha256Hex(*bytes) + "\n";
  }
  if (trailer.empty()) return;
  e.text += (e.text.empty() || e.text.back() == '\n' ? "" : "\n") + trailer;
}

}  // namespace tlab::study
