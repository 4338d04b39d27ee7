// The participant text table: every shipped language has exactly the keys of the English table
// (and the same {placeholders} in each text), plural forms by the language's rule, [text]
// overrides and `language` in the experiment file with file:line errors, and the session's
// wording in German.
#include <gtest/gtest.h>

#include <regex>
#include <set>

#include "study/design/experiment_file.hpp"
#include "study/design/participant_texts.hpp"
#include "study/run/session_wording.hpp"

using namespace tlab::study;

namespace {

std::set<std::string> keysOf(const std::map<std::string, std::string>& table) {
  std::set<std::string> keys;
  for (const auto& [key, text] : table) keys.insert(key);
  return keys;
}

std::set<std::string> placeholders(const std::string& text) {
  std::set<std::string> names;
  const std::regex name("\\{([a-z_]+)\\}");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), name); it != std::sregex_iterator(); ++it) names.insert((*it)[1]);
  return names;
}

const std::string kBase = R"(id = "x"
participants = 1
[[tasks]]
task = "layer-index"
)";

std::string errorOf(const std::string& text) {
  try {
    parseExperiment(text, "bad.toml", StimulusChecks::Skip);
  } catch (const ExperimentFileError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST(ParticipantTexts, EveryShippedLanguageHasEveryKeyWithTheSamePlaceholders) {
  const auto english = shippedTexts("en");
  ASSERT_FALSE(english.empty());
  const auto languages = shippedLanguages();
  EXPECT_GE(languages.size(), 3u);
  for (const auto& language : languages) {
    const auto table = shippedTexts(language);
    EXPECT_EQ(keysOf(table), keysOf(english)) << language << ": keys differ from en.toml";
    for (const auto& [key, text] : table) {
      EXPECT_FALSE(text.empty()) << language << ": " << key;
      if (english.count(key)) {
        EXPECT_EQ(placeholders(text), placeholders(english.at(key))) << language << ": " << key << " = " << text;
      }
    }
    EXPECT_TRUE(ParticipantTexts(language).untranslated().empty()) << language;
  }
  EXPECT_TRUE(shippedTexts("xx").empty());
}

TEST(ParticipantTexts, AnswerHintsExistForEveryAnswerKindAndNameNoInternalId) {
  const ParticipantTexts en;
  for (const char* kind : {"layer-number", "count", "label", "label-set", "letter", "floor-point"}) {
    EXPECT_TRUE(en.has(std::string("answer.") + kind)) << kind;
    EXPECT_TRUE(en.has(std::string("window_answer.") + kind)) << kind;
  }
  // Written for people: the layer number's hint says what 1 means in words.
  EXPECT_EQ(en.text("answer.layer-number"), "Type the layer number (1 is the front surface) and press Enter.");
}

TEST(ParticipantTexts, PluralFormsFollowTheLanguage) {
  const ParticipantTexts en, de("de"), fr("fr");
  EXPECT_EQ(en.count("count.trials", 1), "1 trial");
  EXPECT_EQ(en.count("count.trials", 0), "0 trials");
  EXPECT_EQ(de.count("count.trials", 2), "2 Durchgänge");
  EXPECT_EQ(fr.count("count.trials", 0), "0 essai");  // French: 0 takes the singular
  EXPECT_EQ(fr.count("count.trials", 2), "2 essais");
  EXPECT_EQ(en.amount("duration.minutes", 2.5), "2.5 minutes");
  EXPECT_EQ(de.amount("duration.minutes", 2.5), "2,5 Minuten");
  EXPECT_EQ(fr.amount("duration.minutes", 1.5), "1,5 minute");  // French: below 2 is singular
  EXPECT_EQ(en.format("trial.progress_test", {{"index", "3"}, {"total", "9"}}), "Trial 3 of 9");
  EXPECT_EQ(en.format("trial.progress_test"), "Trial {index} of {total}");  // a value not given stays as written
  EXPECT_THROW(en.text("no.such.key"), std::out_of_range);
}

TEST(ParticipantTexts, OverridesAndLanguagesWithoutATranslation) {
  ParticipantTexts es("es");
  const auto all = keysOf(shippedTexts("en"));
  const auto untranslated = es.untranslated();
  EXPECT_EQ(std::set<std::string>(untranslated.begin(), untranslated.end()), all);
  EXPECT_EQ(es.text("button.continue"), shippedTexts("en").at("button.continue"));  // English until given
  es.set("button.continue", "Continuar");
  EXPECT_EQ(es.text("button.continue"), "Continuar");
  EXPECT_EQ(es.untranslated().size(), all.size() - 1);
  EXPECT_THROW(es.set("button.go", "Ir"), std::out_of_range);
  const ParticipantTexts de = es.inLanguage("de");  // the overrides go along
  EXPECT_EQ(de.language(), "de");
  EXPECT_EQ(de.text("button.continue"), "Continuar");
  EXPECT_EQ(de.text("button.done"), shippedTexts("de").at("button.done"));
}

TEST(ParticipantTexts, TheExperimentFilePicksTheLanguageAndOverridesKeys) {
  const Experiment e = parseExperiment("language = \"de\"\n" + kBase + "[consent]\ntext = \"Einverstanden?\"\n[text]\n\"button.continue\" = \"Los\"\n"
                                                "[text.break]\ntitle = \"Kurze Pause\"\n",
                                       "de.toml", StimulusChecks::Skip);
  EXPECT_EQ(e.texts.language(), "de");
  EXPECT_EQ(e.texts.text("button.continue"), "Los");
  EXPECT_EQ(e.texts.text("break.title"), "Kurze Pause");  // a nested table's key is dotted
  EXPECT_EQ(e.texts.text("button.done"), shippedTexts("de").at("button.done"));
  // The sections' defaults are texts of the table, in the language.
  ASSERT_TRUE(e.consent.has_value());
  EXPECT_EQ(e.consent->accept, shippedTexts("de").at("defaults.consent_accept"));
  EXPECT_EQ(e.breaks.text, shippedTexts("de").at("defaults.break_text"));
  EXPECT_EQ(e.debrief.text, shippedTexts("de").at("defaults.debrief_text"));
  const Experiment en = parseExperiment(kBase, "en.toml", StimulusChecks::Skip);
  EXPECT_EQ(en.texts.language(), "en");
  EXPECT_EQ(en.debrief.text, "Thank you. The session is complete.");

  EXPECT_EQ(errorOf(kBase + "[text]\n\"button.go\" = \"Go\"\n"), "bad.toml:6: text.button.go: unknown key (tlab texts FILE lists every key)");
  EXPECT_EQ(errorOf(kBase + "[text.button]\ngo = \"Go\"\n"), "bad.toml:6: text.button.go: unknown key (tlab texts FILE lists every key)");
  EXPECT_EQ(errorOf(kBase + "[text]\n\"button.done\" = 3\n"), "bad.toml:6: text.button.done: must be a string");
  EXPECT_EQ(errorOf("language = \"German\"\n" + kBase), "bad.toml:1: language: expected a language code such as \"de\" or \"fr\", got 'German'");
}

// A {value} an override names that its text does not take would reach participants as written:
// refused with file:line and the values the text does take (a plural form takes its other form's).
TEST(ParticipantTexts, AnOverrideNamesOnlyValuesItsTextTakes) {
  EXPECT_EQ(errorOf(kBase + "[text]\n\"trial.progress_practice\" = \"Übung {index} von {totl}\"\n"),
            "bad.toml:6: text.trial.progress_practice: {totl} is not a value of this text, which participants would see as "
            "written (it takes {index}, {total})");
  EXPECT_EQ(errorOf(kBase + "[text.button]\ncontinue = \"Press {space}\"\n"),
            "bad.toml:6: text.button.continue: {space} is not a value of this text, which participants would see as written "
            "(it takes none)");
  const Experiment e = parseExperiment(kBase + "[text]\n\"break.trials_left.one\" = \"One trial ({n}) left, {SPACE} and { n } as written\"\n"
                                                "\"trial.progress_practice\" = \"{total}: {index}\"\n",
                                       "ok.toml", StimulusChecks::Skip);
  EXPECT_EQ(e.texts.count("break.trials_left", 1), "One trial (1) left, {SPACE} and { n } as written");
  EXPECT_EQ(e.texts.format("trial.progress_practice", {{"index", "2"}, {"total", "5"}}), "5: 2");
  EXPECT_EQ(ParticipantTexts::valuesOf("break.trials_left.other"), (std::set<std::string>{"n"}));
  EXPECT_TRUE(ParticipantTexts::valuesOf("button.continue").empty());
  EXPECT_EQ(placeholdersOf("{a} {b_c} {D} {} {x"), (std::set<std::string>{"a", "b_c"}));
}

TEST(ParticipantTexts, TheSessionsWordingInGerman) {
  const ParticipantTexts de("de");
  EXPECT_EQ(durationText(45, de), "45 Sekunden");
  EXPECT_EQ(durationText(60, de), "1 Minute");
  EXPECT_EQ(durationText(150, de), "2,5 Minuten");
  const Experiment e = parseExperiment("language = \"de\"\n" + kBase + "[breaks]\nevery = 1\ntext = \"Pause.\"\n", "de.toml", StimulusChecks::Skip);
  SessionPlan plan;
  for (int i = 0; i < 3; ++i) {
    PlannedTrial t;
    t.taskId = "layer";
    t.phase = Phase::Test;
    t.block = 1;
    t.timeLimitSeconds = 300;
    plan.trials.push_back(t);
  }
  EXPECT_EQ(taskIntroduction(plan, 0, "Welche Schicht?", e.texts),
            "Welche Schicht?\n\nEs folgen jetzt 3 Durchgänge dieser Art. Jeder hat ein Zeitlimit von 5 Minuten (ein Countdown zeigt die verbleibende Zeit).");
  EXPECT_EQ(breakText(plan, 1, e.breaks, e.texts), "Pause.\n\nNoch 1 Durchgang.");
  EXPECT_EQ(taskIntroduction(plan, 2, "Welche Schicht?", ParticipantTexts()),
            "Welche Schicht?\n\nThere is 1 trial of this kind now. It has a time limit of 5 minutes (a countdown shows the time left).");
}
