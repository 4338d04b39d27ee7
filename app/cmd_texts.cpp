// tlab texts EXPERIMENT.toml [--language L]: every participant text key with the text that
// experiment shows (its language, or L, with its [text] overrides), written as a [text] table the
// researcher can paste into the experiment file and translate. Keys with no text in the language
// (shown in English) are marked.
#include <algorithm>
#include <cstdio>
#include <memory>

#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "core/file_text.hpp"
#include "study/design/experiment_file.hpp"

namespace tlab::app {

namespace {

struct TextsOptions {
  std::string experiment;
  std::string language;
};

void run(const TextsOptions& o) {
  const auto text = core::readFileText(o.experiment);
  if (!text) throw study::ExperimentFileError(o.experiment + ": cannot open the experiment file");
  const study::Experiment e = study::parseExperiment(*text, o.experiment, study::StimulusChecks::Skip);
  const study::ParticipantTexts texts = o.language.empty() ? e.texts : e.texts.inLanguage(o.language);
  const auto untranslated = texts.untranslated();
  std::printf("# The participant texts of experiment %s in language \"%s\" (shipped: ", e.id.c_str(), texts.language().c_str());
  for (const auto& l : study::shippedLanguages()) std::printf("%s%s", l.c_str(), l == study::shippedLanguages().back() ? ")" : ", ");
  std::printf(";\n# %zu keys, %zu of them in English for want of a translation. Any key can be set in the experiment file's [text].\n",
              texts.entries().size(), untranslated.size());
  std::printf("[text]\n");
  for (const auto& [key, value] : texts.entries()) {
    const bool english = std::find(untranslated.begin(), untranslated.end(), key) != untranslated.end();
    std::printf("%s = %s%s\n", key.c_str(), nlohmann::json(value).dump().c_str(), english ? "  # not translated" : "");
  }
}

}  // namespace

void addTextsCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("texts", "Print every text participants see in an experiment, by key (a [text] table to translate)");
  auto o = std::make_shared<TextsOptions>();
  cmd->add_option("experiment", o->experiment, "experiment file (TOML)")->required();
  cmd->add_option("--language", o->language, "show the texts in this language instead of the file's (shipped: de, en, fr)");
  cmd->callback([o] { run(*o); });
}

}  // namespace tlab::app
