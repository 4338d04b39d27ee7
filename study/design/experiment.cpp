#include "study/design/experiment.hpp"

namespace tlab::study {

int Factor::levelIndex(const std::string& levelName) const {
  for (std::size_t i = 0; i < levels.size(); ++i)
    if (levels[i].name == levelName) return int(i);
  return -1;
}

const char* fieldKindName(FieldKind kind) {
  switch (kind) {
    case FieldKind::Likert: return "likert";
    case FieldKind::Choice: return "choice";
    case FieldKind::Number: return "number";
    case FieldKind::Text: return "text";
  }
  return "?";
}

const char* counterbalancingName(Counterbalancing c) {
  switch (c) {
    case Counterbalancing::Fixed: return "fixed";
    case Counterbalancing::LatinSquare: return "latin-square";
    case Counterbalancing::Williams: return "williams";
    case Counterbalancing::GraecoLatin: return "graeco-latin";
    case Counterbalancing::Permutation: return "permutation";
    case Counterbalancing::Random: return "random";
  }
  return "?";
}

std::vector<const Factor*> Experiment::withinFactors() const {
  std::vector<const Factor*> out;
  for (const auto& f : factors)
    if (f.kind == FactorKind::Within) out.push_back(&f);
  return out;
}

std::vector<const Factor*> Experiment::betweenFactors() const {
  std::vector<const Factor*> out;
  for (const auto& f : factors)
    if (f.kind == FactorKind::Between) out.push_back(&f);
  return out;
}

const Factor* Experiment::factor(const std::string& name) const {
  for (const auto& f : factors)
    if (f.name == name) return &f;
  return nullptr;
}

const TaskSpec* Experiment::task(const std::string& id) const {
  for (const auto& t : tasks)
    if (t.id == id) return &t;
  return nullptr;
}

}  // namespace tlab::study
