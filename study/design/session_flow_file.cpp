#include "study/design/session_flow_file.hpp"

#include <set>

namespace tlab::study {

namespace {

// The participant information most vision studies ask for (standard_info = true).
std::vector<FormField> standardInfo() {
  FormField age{"age", "Your age in years", FieldKind::Number};
  age.minimum = 16;
  age.maximum = 120;
  age.integer = true;
  FormField gender{"gender", "Your gender", FieldKind::Choice};
  gender.options = {"female", "male", "non-binary", "prefer not to say"};
  FormField vision{"vision", "Your vision", FieldKind::Choice};
  vision.options = {"normal", "corrected to normal (glasses, lenses)", "other"};
  return {age, gender, vision};
}

FieldKind parseKind(const FieldReader& r, const toml::table& t, const std::string& where, FieldKind fallback) {
  const std::string kind = r.string(t, "kind", where, false, fieldKindName(fallback));
  for (const auto k : {FieldKind::Likert, FieldKind::Choice, FieldKind::Number, FieldKind::Text})
    if (kind == fieldKindName(k)) return k;
  r.fail(t.get("kind"), where + ".kind", "expected likert, choice, number or text, got '" + kind + "'");
}

// One field: a table { id, text, kind, points, anchors, options, min, max, integer, required }.
FormField readField(const FieldReader& r, const toml::table& t, const std::string& where, const FormField& defaults) {
  r.checkKeys(t, where, {"id", "text", "kind", "points", "anchors", "options", "min", "max", "integer", "required"});
  FormField f = defaults;
  f.id = r.string(t, "id", where, true);
  if (f.id.empty()) r.fail(t.get("id"), where + ".id", "must not be empty");
  f.text = r.string(t, "text", where, true);
  f.kind = parseKind(r, t, where, defaults.kind);
  f.points = int(r.integer(t, "points", where, defaults.points, 2));
  if (f.points > 11) r.fail(t.get("points"), where + ".points", "at most 11 points");
  const auto anchors = r.strings(t, "anchors", where);
  if (!anchors.empty()) {
    if (anchors.size() != 2) r.fail(t.get("anchors"), where + ".anchors", "expected [\"low\", \"high\"]");
    f.lowAnchor = anchors[0];
    f.highAnchor = anchors[1];
  }
  f.options = r.strings(t, "options", where);
  if (f.kind == FieldKind::Choice && f.options.size() < 2)
    r.fail(t.get("options") ? t.get("options") : &t, where + ".options", "a choice needs at least two options");
  if (f.kind != FieldKind::Choice && !f.options.empty()) r.fail(t.get("options"), where + ".options", "only choice fields have options");
  f.minimum = r.number(t, "min", where, f.minimum, -1e12, 1e12);
  f.maximum = r.number(t, "max", where, f.maximum, -1e12, 1e12);
  if (f.minimum > f.maximum) r.fail(t.get("min"), where + ".min", "must not exceed max");
  if (const toml::node* n = t.get("integer")) {
    if (!n->is_boolean()) r.fail(n, where + ".integer", "must be true or false");
    f.integer = n->as_boolean()->get();
  }
  if (const toml::node* n = t.get("required")) {
    if (!n->is_boolean()) r.fail(n, where + ".required", "must be true or false");
    f.required = n->as_boolean()->get();
  }
  return f;
}

void requireUniqueIds(const FieldReader& r, const std::vector<FormField>& fields, const toml::node* node, const std::string& where) {
  std::set<std::string> seen;
  for (const auto& f : fields)
    if (!seen.insert(f.id).second) r.fail(node, where, "the id '" + f.id + "' is used twice");
}

const toml::table* optionalTable(const FieldReader& r, const toml::table& root, const char* key, const std::set<std::string>& keys) {
  const toml::table* t = r.table(root, key, "");
  if (t) r.checkKeys(*t, key, keys);
  return t;
}

void readOnline(const FieldReader& r, const toml::table& root, OnlineSpec& o) {
  const toml::table* t = optionalTable(r, root, "online",
                                       {"participant_parameter", "study_parameter", "session_parameter", "timeout_minutes", "turntable_azimuths",
                                        "turntable_elevations", "turntable_elevation_degrees", "completion_url", "size_calibration"});
  if (!t) return;
  o.participantParameter = r.string(*t, "participant_parameter", "online", false, o.participantParameter);
  if (o.participantParameter.empty()) r.fail(t->get("participant_parameter"), "online.participant_parameter", "must not be empty");
  o.studyParameter = r.string(*t, "study_parameter", "online", false);
  o.sessionParameter = r.string(*t, "session_parameter", "online", false);
  o.timeoutMinutes = r.number(*t, "timeout_minutes", "online", o.timeoutMinutes, 0.05, 7 * 24 * 60.0);
  o.turntableAzimuths = int(r.integer(*t, "turntable_azimuths", "online", o.turntableAzimuths, 4));
  o.turntableElevations = int(r.integer(*t, "turntable_elevations", "online", o.turntableElevations, 1));
  if (o.turntableAzimuths * o.turntableElevations > 720)
    r.fail(t->get("turntable_azimuths"), "online.turntable_azimuths", "at most 720 views in all (azimuths x elevations)");
  o.turntableElevationDegrees = r.number(*t, "turntable_elevation_degrees", "online", o.turntableElevationDegrees, 0.0, 160.0);
  o.completionUrl = r.string(*t, "completion_url", "online", false);
  if (!o.completionUrl.empty() && o.completionUrl.rfind("https://", 0) != 0 && o.completionUrl.rfind("http://", 0) != 0)
    r.fail(t->get("completion_url"), "online.completion_url", "must start with https:// or http://");
  if (const toml::node* n = t->get("size_calibration")) {
    if (!n->is_boolean()) r.fail(n, "online.size_calibration", "must be true or false");
    o.sizeCalibration = n->as_boolean()->get();
  }
}

}  // namespace

void readSessionFlow(const FieldReader& r, const toml::table& root, Experiment& e) {
  e.participantTitle = r.string(root, "participant_title", "", false);
  if (const toml::table* c = optionalTable(r, root, "consent", {"text", "accept", "decline"})) {
    ConsentSpec consent;
    consent.text = r.string(*c, "text", "consent", true);
    consent.accept = r.string(*c, "accept", "consent", false, consent.accept);
    consent.decline = r.string(*c, "decline", "consent", false, consent.decline);
    e.consent = consent;
  }
  if (const toml::node* n = root.get("standard_info")) {
    if (!n->is_boolean()) r.fail(n, "standard_info", "must be true or false");
    if (n->as_boolean()->get()) e.info = standardInfo();
  }
  const auto info = r.tables(root, "info");
  FormField infoDefaults;
  infoDefaults.kind = FieldKind::Text;
  for (std::size_t i = 0; i < info.size(); ++i) e.info.push_back(readField(r, *info[i], "info[" + std::to_string(i + 1) + "]", infoDefaults));
  requireUniqueIds(r, e.info, root.get("info"), "info");
  if (const toml::table* t = optionalTable(r, root, "training", {"feedback"})) {
    if (const toml::node* n = t->get("feedback")) {
      if (!n->is_boolean()) r.fail(n, "training.feedback", "must be true or false");
      e.trainingFeedback = n->as_boolean()->get();
    }
  }
  if (const toml::table* t = optionalTable(r, root, "breaks", {"every", "unit", "min_seconds", "text"})) {
    e.breaks.every = int(r.integer(*t, "every", "breaks", 0, 1, true));
    const std::string unit = r.string(*t, "unit", "breaks", false, "trials");
    if (unit != "trials" && unit != "blocks") r.fail(t->get("unit"), "breaks.unit", "expected \"trials\" or \"blocks\", got '" + unit + "'");
    e.breaks.blocks = unit == "blocks";
    e.breaks.minSeconds = r.number(*t, "min_seconds", "breaks", 0.0, 0.0, 3600.0);
    e.breaks.text = r.string(*t, "text", "breaks", false, e.breaks.text);
  }
  readOnline(r, root, e.online);
  e.debrief.text = r.string(root, "goodbye", "", false, e.debrief.text);
  if (const toml::table* t = optionalTable(r, root, "debrief", {"text", "completion_code"})) {
    e.debrief.text = r.string(*t, "text", "debrief", false, e.debrief.text);
    e.debrief.completionCode = r.string(*t, "completion_code", "debrief", false);
  }
}

std::vector<Questionnaire> readQuestionnaires(const FieldReader& r, const toml::table& root) {
  std::vector<Questionnaire> out;
  const auto tables = r.tables(root, "questionnaires");
  for (std::size_t i = 0; i < tables.size(); ++i) {
    const toml::table& t = *tables[i];
    const std::string where = "questionnaires[" + std::to_string(i + 1) + "]";
    r.checkKeys(t, where, {"id", "when", "title", "points", "anchors", "items"});
    Questionnaire q;
    q.id = r.string(t, "id", where, true);
    q.when = r.string(t, "when", where, false, "end");
    if (q.when != "start" && q.when != "end" && q.when != "after-block")
      r.fail(t.get("when"), where + ".when", "expected start, end or after-block");
    q.title = r.string(t, "title", where, false);
    FormField defaults;  // likert items take the questionnaire's points and anchors
    defaults.points = int(r.integer(t, "points", where, 7, 2));
    if (defaults.points > 11) r.fail(t.get("points"), where + ".points", "at most 11 points");
    const auto anchors = r.strings(t, "anchors", where);
    if (!anchors.empty()) {
      if (anchors.size() != 2) r.fail(t.get("anchors"), where + ".anchors", "expected [\"low\", \"high\"]");
      defaults.lowAnchor = anchors[0];
      defaults.highAnchor = anchors[1];
    }
    const toml::array* items = t.get("items") ? t.get("items")->as_array() : nullptr;
    if (!items || items->empty()) r.fail(t.get("items") ? t.get("items") : &t, where + ".items", "at least one item is required");
    for (std::size_t k = 0; k < items->size(); ++k) {
      const toml::node& n = *items->get(k);
      const std::string itemWhere = where + ".items[" + std::to_string(k + 1) + "]";
      if (n.is_string()) {
        FormField item = defaults;
        item.id = "item" + std::to_string(k + 1);
        item.text = n.as_string()->get();
        q.items.push_back(item);
      } else if (const toml::table* it = n.as_table()) {
        q.items.push_back(readField(r, *it, itemWhere, defaults));
      } else {
        r.fail(&n, itemWhere, "an item is a string or { id = ..., text = ..., kind = ... }");
      }
    }
    requireUniqueIds(r, q.items, t.get("items"), where + ".items");
    out.push_back(std::move(q));
  }
  return out;
}

}  // namespace tlab::study
