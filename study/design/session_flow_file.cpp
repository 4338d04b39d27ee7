#include "study/design/session_flow_file.hpp"

#include <regex>
#include <set>
#include <stdexcept>

namespace tlab::study {

namespace {

// Likert anchors and the other defaults of a form field, in the participants' language.
FormField fieldDefaults(const ParticipantTexts& t, FieldKind kind) {
  FormField f;
  f.kind = kind;
  f.lowAnchor = t.text("defaults.likert_low");
  f.highAnchor = t.text("defaults.likert_high");
  return f;
}

// The participant information most vision studies ask for (standard_info = true).
std::vector<FormField> standardInfo(const ParticipantTexts& t) {
  FormField age = fieldDefaults(t, FieldKind::Number), gender = fieldDefaults(t, FieldKind::Choice), vision = gender;
  age.id = "age";
  age.text = t.text("info.age");
  age.minimum = 16;
  age.maximum = 120;
  age.integer = true;
  gender.id = "gender";
  gender.text = t.text("info.gender");
  gender.options = {t.text("info.gender_female"), t.text("info.gender_male"), t.text("info.gender_nonbinary"), t.text("info.gender_none")};
  vision.id = "vision";
  vision.text = t.text("info.vision");
  vision.options = {t.text("info.vision_normal"), t.text("info.vision_corrected"), t.text("info.vision_other")};
  return {age, gender, vision};
}

// [text]: its tables flattened to dotted keys, each set in the table (an unknown key fails).
void readTextOverrides(const FieldReader& r, const toml::table& table, const std::string& prefix, ParticipantTexts& texts) {
  for (auto&& [key, node] : table) {
    const std::string name = prefix + std::string(key.str());
    if (const toml::table* inner = node.as_table()) {
      readTextOverrides(r, *inner, name + ".", texts);
      continue;
    }
    if (!node.is_string()) r.fail(&node, "text." + name, "must be a string");
    const std::string& value = node.as_string()->get();
    try {
      texts.set(name, value);
    } catch (const std::out_of_range&) {
      r.fail(&node, "text." + name, "unknown key (tlab texts FILE lists every key)");
    }
    // A {value} the text does not take would reach participants as written ("{totl}").
    const auto takes = ParticipantTexts::valuesOf(name);
    for (const auto& v : placeholdersOf(value))
      if (!takes.count(v)) {
        std::string known;
        for (const auto& t : takes) known += (known.empty() ? "{" : ", {") + t + "}";
        r.fail(&node, "text." + name, "{" + v + "} is not a value of this text, which participants would see as written (" +
                                          (known.empty() ? "it takes none" : "it takes " + known) + ")");
      }
  }
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

// stimulus_size = "native" | "css" | "10cm" (a physical width needs the size calibration).
void readStimulusSize(const FieldReader& r, const toml::table& t, OnlineSpec& o) {
  const toml::node* n = t.get("stimulus_size");
  if (!n) return;
  const std::string size = r.string(t, "stimulus_size", "online", true);
  std::smatch m;
  if (size == "native" || size == "css") {
    o.stimulusSize = size;
  } else if (std::regex_match(size, m, std::regex("([0-9]+(\\.[0-9]+)?) ?cm")) && std::stod(m[1]) > 0.0 && std::stod(m[1]) <= 100.0) {
    if (!o.sizeCalibration) r.fail(n, "online.stimulus_size", "a size in cm needs size_calibration = true (the page must know its pixels per cm)");
    o.stimulusSize = "cm";
    o.stimulusCm = std::stod(m[1]);
  } else {
    r.fail(n, "online.stimulus_size", "expected \"native\", \"css\" or a width such as \"10cm\" (up to 100 cm), got '" + size + "'");
  }
}

void readOnline(const FieldReader& r, const toml::table& root, OnlineSpec& o) {
  const toml::table* t = optionalTable(r, root, "online",
                                       {"participant_parameter", "study_parameter", "session_parameter", "timeout_minutes", "turntable_azimuths",
                                        "turntable_elevations", "turntable_elevation_degrees", "completion_url", "size_calibration",
                                        "calibration_no_card", "stimulus_size", "devices", "live", "frames", "jpeg_quality"});
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
  if (const toml::node* n = t->get("calibration_no_card")) {
    if (!n->is_boolean()) r.fail(n, "online.calibration_no_card", "must be true or false");
    o.calibrationNoCard = n->as_boolean()->get();
  }
  if (const toml::node* n = t->get("live")) {
    if (!n->is_boolean()) r.fail(n, "online.live", "must be true or false");
    o.live = n->as_boolean()->get();
  }
  o.frames = r.string(*t, "frames", "online", false, o.frames);
  if (o.frames != "png" && o.frames != "jpeg")
    r.fail(t->get("frames"), "online.frames", "expected \"png\" (lossless) or \"jpeg\" (lossy), got '" + o.frames + "'");
  const std::int64_t quality = r.integer(*t, "jpeg_quality", "online", o.jpegQuality, 1);
  if (quality > 100) r.fail(t->get("jpeg_quality"), "online.jpeg_quality", "must be between 1 and 100");
  o.jpegQuality = int(quality);
  if (t->get("jpeg_quality") && o.frames != "jpeg") r.fail(t->get("jpeg_quality"), "online.jpeg_quality", "only with frames = \"jpeg\"");
  readStimulusSize(r, *t, o);
  if (t->get("devices")) o.devices = r.strings(*t, "devices", "online");
  for (const auto& d : o.devices)
    if (d != "desktop" && d != "tablet" && d != "phone")
      r.fail(t->get("devices"), "online.devices", "expected desktop, tablet or phone, got '" + d + "'");
  if (o.devices.empty()) r.fail(t->get("devices"), "online.devices", "at least one kind of device must be allowed");
}

}  // namespace

void readParticipantTexts(const FieldReader& r, const toml::table& root, Experiment& e) {
  const std::string language = r.string(root, "language", "", false, "en");
  if (!std::regex_match(language, std::regex("[a-z]{2,3}(-[A-Za-z0-9]{2,8})?")))
    r.fail(root.get("language"), "language", "expected a language code such as \"de\" or \"fr\", got '" + language + "'");
  e.texts = ParticipantTexts(language);
  e.languageSource = root.get("language") ? r.at(root.get("language"), "language") : e.path;
  if (const toml::node* n = root.get("text")) {
    if (!n->is_table()) r.fail(n, "text", "must be a table of texts ([text] KEY = \"...\")");
    readTextOverrides(r, *n->as_table(), "", e.texts);
  }
}

void readSessionFlow(const FieldReader& r, const toml::table& root, Experiment& e) {
  const ParticipantTexts& texts = e.texts;
  e.participantTitle = r.string(root, "participant_title", "", false);
  e.breaks.text = texts.text("defaults.break_text");
  e.debrief.text = texts.text("defaults.debrief_text");
  if (const toml::table* c = optionalTable(r, root, "consent", {"text", "accept", "decline"})) {
    ConsentSpec consent{"", texts.text("defaults.consent_accept"), texts.text("defaults.consent_decline")};
    consent.text = r.string(*c, "text", "consent", true);
    consent.accept = r.string(*c, "accept", "consent", false, consent.accept);
    consent.decline = r.string(*c, "decline", "consent", false, consent.decline);
    e.consent = consent;
  }
  if (const toml::node* n = root.get("standard_info")) {
    if (!n->is_boolean()) r.fail(n, "standard_info", "must be true or false");
    if (n->as_boolean()->get()) e.info = standardInfo(texts);
  }
  const auto info = r.tables(root, "info");
  const FormField infoDefaults = fieldDefaults(texts, FieldKind::Text);
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

std::vector<Questionnaire> readQuestionnaires(const FieldReader& r, const toml::table& root, const ParticipantTexts& texts) {
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
    FormField defaults = fieldDefaults(texts, FieldKind::Likert);  // likert items take the questionnaire's points and anchors
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
