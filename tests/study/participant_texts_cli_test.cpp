// `tlab texts FILE [--language L]` prints every participant text key with the experiment's text
// (a [text] table that reads back as one), and `tlab design` warns about each key the chosen
// language has no text for.
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <map>
#include <regex>
#include <sstream>

#include <toml++/toml.h>

#include "study/design/participant_texts.hpp"
#include "tests/study/study_test_support.hpp"
#include "tests/support/run_command.hpp"

using namespace tlab::testing;

namespace {

const std::string kTlab = TLAB_EXE;

std::string writeExperiment(const std::filesystem::path& dir, const std::string& name, const std::string& extra) {
  const auto path = dir / name;
  std::ofstream(path) << "id = \"texts\"\nparticipants = 1\n" << extra
                      << "\n[stimulus]\nsize = \"64x64\"\n[[tasks]]\ntask = \"layer-index\"\nscene = \"builtin:nested-spheres?n=2\"\n";
  return path.string();
}

// The [text] table `tlab texts` printed, read back as TOML: key -> text.
std::map<std::string, std::string> printedTable(const std::string& out) {
  std::map<std::string, std::string> table;
  const toml::table root = toml::parse(out);
  std::function<void(const toml::table&, const std::string&)> walk = [&](const toml::table& t, const std::string& prefix) {
    for (auto&& [key, node] : t) {
      if (const auto* inner = node.as_table()) walk(*inner, prefix + std::string(key.str()) + ".");
      else table[prefix + std::string(key.str())] = node.as_string()->get();
    }
  };
  walk(*root["text"].as_table(), "");
  return table;
}

}  // namespace

TEST(TextsCli, PrintsEveryKeyInTheFilesLanguageWithItsOverrides) {
  const auto dir = freshDir("texts_cli");
  const std::string file = writeExperiment(dir, "de.toml", "language = \"de\"\n[text]\n\"button.continue\" = \"Los geht's\"\n");
  const auto r = runCommand(kTlab + " texts " + file);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto expected = tlab::study::shippedTexts("de");
  expected["button.continue"] = "Los geht's";
  EXPECT_EQ(printedTable(r.out), expected);  // every key, German, with the override
  EXPECT_EQ(r.out.find("# not translated"), std::string::npos) << "German is complete";

  const auto fr = runCommand(kTlab + " texts " + file + " --language fr");
  ASSERT_EQ(fr.exitCode, 0) << fr.err;
  expected = tlab::study::shippedTexts("fr");
  expected["button.continue"] = "Los geht's";  // the file's override holds in any language
  EXPECT_EQ(printedTable(fr.out), expected);

  const std::string bad = writeExperiment(dir, "bad.toml", "[text]\n\"button.go\" = \"Go\"\n");
  const auto refused = runCommand(kTlab + " texts " + bad);
  EXPECT_EQ(refused.exitCode, 1);
  EXPECT_EQ(refused.err, "tlab: error: " + bad + ":4: text.button.go: unknown key (tlab texts FILE lists every key)\n");
}

TEST(TextsCli, DesignWarnsAboutEachKeyTheLanguageHasNoTextFor) {
  const auto dir = freshDir("texts_design");
  const std::string file = writeExperiment(dir, "es.toml", "language = \"es\"\n[text]\n\"button.continue\" = \"Continuar\"\n");
  const auto r = runCommand(kTlab + " design --quick " + file);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::set<std::string> warned;
  std::istringstream lines(r.err);
  const std::regex warning("warning: " + std::regex_replace(file, std::regex("[.]"), "\\.") +
                           ":3: language = \"es\": text\\.(\\S+) has no text in this language; participants see the English .*");
  for (std::string line; std::getline(lines, line);) {
    std::smatch m;
    ASSERT_TRUE(std::regex_match(line, m, warning)) << line;
    warned.insert(m[1]);
  }
  std::set<std::string> expected;
  for (const auto& [key, text] : tlab::study::shippedTexts("en"))
    if (key != "button.continue") expected.insert(key);  // the one [text] gives
  EXPECT_EQ(warned, expected);

  const auto german = runCommand(kTlab + " design --quick " + writeExperiment(dir, "de.toml", "language = \"de\"\n"));
  ASSERT_EQ(german.exitCode, 0) << german.err;
  EXPECT_EQ(german.err.find("warning"), std::string::npos) << german.err;
}
