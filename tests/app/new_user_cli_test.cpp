// What a new user hit first (issue "The README works as written"), each as tlab runs from the
// command line: `tlab design` fails with file:line on what only a start found before (a task
// setting no probe can meet; a training stimulus shown again in a test trial), a failed start
// leaves no database file, every shipped example designs and simulates, `simulate --size`, row
// filters and missing values in `tlab stats`, the unknown-command line, one report per
// invocation, TOML's unterminated strings, and the camera `task probe` used.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/support/run_command.hpp"

namespace tlab::testing {
namespace {

namespace fs = std::filesystem;

CommandResult tlab(const std::string& arguments) { return runCommand(std::string(TLAB_EXE) + " " + arguments); }

// A small experiment on nested spheres: `task` lines replace the [[tasks]] table.
std::string experiment(const std::string& tasks, const std::string& scene = "builtin:nested-spheres?n=3") {
  return "id = \"plan\"\nseed = 3\nparticipants = 2\ncounterbalancing = \"latin-square\"\n\n[stimulus]\nsize = \"96x96\"\n"
         "scene = \"" + scene + "\"\n\n"
         "[[factors]]\nname = \"method\"\nlevels = [\n  { name = \"alpha\", style = \"constant\" },\n  { name = \"smart\", style = \"smart\" },\n]\n\n" +
         tasks;
}

fs::path write(const fs::path& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir / name) << text;
  return dir / name;
}

TEST(NewUser, DesignFailsWithFileAndLineOnATaskSettingNoProbeCanMeet) {
  const fs::path dir = freshDir("design_probe");
  const fs::path file = write(dir, "deep.toml", experiment("[[tasks]]\ntask = \"layer-index\"\nquestions = 6\nsettings = [\"min-layer=9\"]\n"));
  const CommandResult design = tlab("design " + quoted(file.string()));
  EXPECT_EQ(design.exitCode, 1) << design.out;
  // The settings line is line 20 of the file: "settings = [...]".
  EXPECT_NE(design.err.find(file.string() + ":20: tasks[1].settings: "), std::string::npos) << design.err;
  EXPECT_NE(design.err.find("found only 0 of 6"), std::string::npos) << design.err;
  EXPECT_EQ(std::count(design.err.begin(), design.err.end(), '\n'), 1) << "one line: " << design.err;
  const CommandResult quick = tlab("design --quick " + quoted(file.string()));
  EXPECT_EQ(quick.exitCode, 0) << quick.err;
}

// A task setting outside what the task declared is refused by the quick check too, where it is
// written (min-layer=2.5 used to be read as layer 2).
TEST(NewUser, DesignQuickFailsWithFileAndLineOnATaskSettingOutsideItsDeclaration) {
  const fs::path dir = freshDir("design_setting");
  const fs::path file = write(dir, "half.toml", experiment("[[tasks]]\ntask = \"layer-index\"\nquestions = 2\nsettings = [\"min-layer=2.5\"]\n"));
  const CommandResult quick = tlab("design --quick " + quoted(file.string()));
  EXPECT_EQ(quick.exitCode, 1) << quick.out;
  EXPECT_NE(quick.err.find(file.string() + ":20: tasks[1]"), std::string::npos) << quick.err;
  EXPECT_NE(quick.err.find("setting 'min-layer' = 2.5: expected a whole number in [1, 1000]"), std::string::npos) << quick.err;
  EXPECT_EQ(std::count(quick.err.begin(), quick.err.end(), '\n'), 1) << "one line: " << quick.err;
}

TEST(NewUser, DesignFailsWithFileAndLineOnATrainingStimulusShownInATest) {
  const fs::path dir = freshDir("design_training");
  // Counting marks nothing: a fixed scene shows its training trial the test trials' picture.
  const fs::path file = write(dir, "fixed.toml",
                              experiment("[[tasks]]\ntask = \"counting\"\ntrials = 2\ntraining_trials = 1\n", "builtin:abstract?seed=5"));
  const CommandResult design = tlab("design " + quoted(file.string()));
  EXPECT_EQ(design.exitCode, 1) << design.out;
  EXPECT_NE(design.err.find(file.string() + ":20: tasks[1].training_trials: "), std::string::npos) << design.err;
  EXPECT_NE(design.err.find("would show the stimulus of test trial"), std::string::npos) << design.err;

  // The start that fails leaves no database (a rerun is not refused as "already holds a study").
  const fs::path db = dir / "sim.db";
  const CommandResult simulate = tlab("simulate " + quoted(file.string()) + " --participants 1 --db " + quoted(db.string()));
  EXPECT_EQ(simulate.exitCode, 1);
  EXPECT_NE(simulate.err.find("would show the stimulus of test trial"), std::string::npos) << simulate.err;
  EXPECT_FALSE(fs::exists(db)) << "a failed start left " << db;
  EXPECT_FALSE(fs::exists(dir / "sim.db-wal"));

  // With {trial} in the scene, training gets scenes of its own: design and simulate pass.
  const fs::path fixed = write(dir, "ok.toml",
                               experiment("[[tasks]]\ntask = \"counting\"\ntrials = 2\ntraining_trials = 1\n", "builtin:abstract?seed={trial}"));
  EXPECT_EQ(tlab("design " + quoted(fixed.string())).exitCode, 0);
  const CommandResult ok = tlab("simulate " + quoted(fixed.string()) + " --participants 1 --db " + quoted(db.string()));
  EXPECT_EQ(ok.exitCode, 0) << ok.err;
  EXPECT_TRUE(fs::exists(db));
}

TEST(NewUser, ARunWithoutADisplayLeavesNoDatabase) {
  const fs::path dir = freshDir("run_no_display");
  const fs::path file = write(dir, "r.toml", experiment("[[tasks]]\ntask = \"layer-index\"\n"));
  const fs::path db = dir / "people.db";
  const CommandResult run = runCommand("env -u DISPLAY -u WAYLAND_DISPLAY " + std::string(TLAB_EXE) + " run " + quoted(file.string()) +
                                       " --participant P01 --db " + quoted(db.string()));
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  EXPECT_FALSE(fs::exists(db)) << "a run that could not open its window left " << db;
}

TEST(NewUser, AFailedStartKeepsADatabaseThatHoldsData) {
  const fs::path dir = freshDir("keep_db");
  const fs::path good = write(dir, "ok.toml", experiment("[[tasks]]\ntask = \"layer-index\"\n"));
  const fs::path db = dir / "sim.db";
  ASSERT_EQ(tlab("simulate " + quoted(good.string()) + " --participants 1 --db " + quoted(db.string())).exitCode, 0);
  const auto size = fs::file_size(db);
  // Another experiment that fails at its start, into the same database: the first one's data stay.
  const fs::path bad = write(dir, "bad.toml", std::regex_replace(experiment("[[tasks]]\ntask = \"layer-index\"\nquestions = 6\nsettings = [\"min-layer=9\"]\n"),
                                                                 std::regex("id = \"plan\""), "id = \"other\""));
  EXPECT_EQ(tlab("simulate " + quoted(bad.string()) + " --participants 1 --db " + quoted(db.string())).exitCode, 1);
  ASSERT_TRUE(fs::exists(db));
  EXPECT_GE(fs::file_size(db), size);
  const CommandResult exported = tlab("export " + quoted(db.string()) + " --csv " + quoted((dir / "csv").string()));
  EXPECT_EQ(exported.exitCode, 0) << exported.err;
}

// Every experiment file shipped in examples/ designs (with its stimulus and plan checks, at its
// own size) and simulates with 2 participants at 240x240 (the demo's reduced size; an example
// with images from another renderer at their size). One test per
// file, found when the tests are listed, so an example added later is tested too.
std::vector<std::string> exampleFiles() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(fs::path(TLAB_SOURCE_DIR) / "examples"))
    if (entry.path().extension() == ".toml") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

class ShippedExample : public ::testing::TestWithParam<std::string> {};

// An example whose level takes images from another renderer (`images = "renders/{scene}.png"`)
// gets them as the README's workflow makes them: its scenes exported and drawn by VTK, in a copy
// of examples/. Returns the example to run and whether its size is fixed by those images.
std::pair<fs::path, bool> prepareExample(const std::string& name, const fs::path& dir) {
  const fs::path source = fs::path(TLAB_SOURCE_DIR) / "examples" / (name + ".toml");
  const std::string text = readText(source.string());
  if (text.find("images = ") == std::string::npos) return {source, false};
  fs::copy(fs::path(TLAB_SOURCE_DIR) / "examples", dir / "examples", fs::copy_options::recursive);
  fs::create_directories(dir / "examples" / "renders");
  const std::regex level("\\{ name = \"([a-z]+)\", scene = \"([^\"]+)\" \\}");
  const std::string vtk = "xvfb-run -a -s '-screen 0 640x480x24' /usr/bin/python3 " + std::string(TLAB_SOURCE_DIR) + "/scripts/render_with_vtk.py ";
  std::smatch sized;
  EXPECT_TRUE(std::regex_search(text, sized, std::regex("size = \"([0-9]+x[0-9]+)\""))) << "the example's [stimulus] size";
  const std::string size = sized[1];
  for (std::sregex_iterator m(text.begin(), text.end(), level), end; m != end; ++m) {
    const fs::path glb = dir / ((*m)[1].str() + ".glb");
    EXPECT_EQ(tlab("scene export " + quoted((*m)[2].str()) + " --size " + size + " -o " + quoted(glb.string())).exitCode, 0);
    const CommandResult drawn = runCommand(vtk + quoted(glb.string()) + " " + quoted((dir / "examples" / "renders" / ((*m)[1].str() + ".png")).string()));
    EXPECT_EQ(drawn.exitCode, 0) << drawn.err;
  }
  return {dir / "examples" / (name + ".toml"), true};
}

TEST_P(ShippedExample, DesignsAndSimulates) {
  const fs::path dir = freshDir("example_" + GetParam());
  const auto [file, sizeFixed] = prepareExample(GetParam(), dir);
  const CommandResult design = tlab("design " + quoted(file.string()));
  EXPECT_EQ(design.exitCode, 0) << design.err;
  EXPECT_NE(design.out.find("no training stimulus shown in a test trial"), std::string::npos) << design.out;
  const fs::path db = dir / "sim.db";
  const CommandResult simulate = tlab("simulate " + quoted(file.string()) + " --participants 2" + (sizeFixed ? "" : " --size 240x240") +
                                      " --db " + quoted(db.string()));
  EXPECT_EQ(simulate.exitCode, 0) << simulate.err;
  EXPECT_NE(simulate.out.find("simulated 2 participants"), std::string::npos) << simulate.out;
}

INSTANTIATE_TEST_SUITE_P(Examples, ShippedExample, ::testing::ValuesIn(exampleFiles()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param;
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

TEST(NewUser, SimulateSizeRendersSmallerAndStoresTheSize) {
  const fs::path dir = freshDir("simulate_size");
  const fs::path file = write(dir, "s.toml", experiment("[[tasks]]\ntask = \"layer-index\"\n"));
  const fs::path db = dir / "s.db";
  ASSERT_EQ(tlab("simulate " + quoted(file.string()) + " --participants 1 --size 48x40 --db " + quoted(db.string())).exitCode, 0);
  const CommandResult exported = tlab("export " + quoted(db.string()) + " --csv " + quoted((dir / "csv").string()));
  ASSERT_EQ(exported.exitCode, 0) << exported.err;
  // Every stimulus file is 48x40 (PNG IHDR width and height at bytes 16..23).
  int stimuli = 0;
  for (const auto& png : fs::directory_iterator(dir / "s-stimuli")) {
    const std::string bytes = readText(png.path().string());
    ASSERT_GT(bytes.size(), 24u);
    const auto be32 = [&](std::size_t at) {
      return (unsigned(std::uint8_t(bytes[at])) << 24) | (unsigned(std::uint8_t(bytes[at + 1])) << 16) |
             (unsigned(std::uint8_t(bytes[at + 2])) << 8) | unsigned(std::uint8_t(bytes[at + 3]));
    };
    EXPECT_EQ(be32(16), 48u) << png.path();
    EXPECT_EQ(be32(20), 40u) << png.path();
    ++stimuli;
  }
  EXPECT_GT(stimuli, 0);
  const CommandResult bad = tlab("simulate " + quoted(file.string()) + " --participants 1 --size 48 --db " + quoted((dir / "b.db").string()));
  EXPECT_EQ(bad.exitCode, 1);
  EXPECT_NE(bad.err.find("--size"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(dir / "b.db"));
}

TEST(NewUser, StatsReadsTheExportWithWhereAndDropsMissingValues) {
  const fs::path dir = freshDir("stats_where");
  // Participant p3's rt in condition b is missing (empty), p4's is NA; a training row is filtered out.
  std::ofstream(dir / "t.csv") << "participant,phase,method,rt\n"
                                  "p1,test,a,1\np1,test,b,2\np2,test,a,1.5\np2,test,b,2.5\np3,test,a,2\np3,test,b,\n"
                                  "p4,test,a,3\np4,test,b,NA\np1,training,a,100\n";
  const std::string csv = quoted((dir / "t.csv").string());
  const CommandResult plain = tlab("stats ttest " + csv + " --dv rt --between method");
  EXPECT_EQ(plain.exitCode, 0) << plain.err;
  EXPECT_NE(plain.out.find("note: 2 rows with a missing 'rt' (empty or NA) dropped"), std::string::npos) << plain.out;

  const CommandResult where = tlab("stats ttest " + csv + " --dv rt --between method --where phase=test --json");
  ASSERT_EQ(where.exitCode, 0) << where.err;
  const auto j = nlohmann::json::parse(where.out);
  EXPECT_EQ(j["input_rows"]["read"], 9);
  EXPECT_EQ(j["input_rows"]["kept_by_where"], 8);
  EXPECT_EQ(j["input_rows"]["dropped_missing_dv"], 2);
  EXPECT_EQ(j["input_rows"]["used"], 6);

  // Welch's t of a = {1, 1.5, 2, 3} against b = {2, 2.5}: the same with the rows filtered by hand.
  std::ofstream(dir / "by_hand.csv") << "method,rt\na,1\na,1.5\na,2\na,3\nb,2\nb,2.5\n";
  const CommandResult byHand = tlab("stats ttest " + quoted((dir / "by_hand.csv").string()) + " --dv rt --between method --json");
  ASSERT_EQ(byHand.exitCode, 0) << byHand.err;
  const auto h = nlohmann::json::parse(byHand.out);
  ASSERT_TRUE(h.contains("t"));
  EXPECT_EQ(j["t"], h["t"]);
  EXPECT_EQ(j["df"], h["df"]);
  EXPECT_EQ(j["p"], h["p"]);

  const CommandResult twoValues = tlab("stats ttest " + csv + " --dv rt --where participant=p1,p2 --where phase=test --json");
  ASSERT_EQ(twoValues.exitCode, 0) << twoValues.err;
  EXPECT_EQ(nlohmann::json::parse(twoValues.out)["input_rows"]["used"], 4);

  const CommandResult noColumn = tlab("stats ttest " + csv + " --dv rt --where nope=1");
  EXPECT_EQ(noColumn.exitCode, 1);
  EXPECT_NE(noColumn.err.find("no column 'nope'"), std::string::npos) << noColumn.err;
  const CommandResult malformed = tlab("stats anova " + csv + " --dv rt --between method --where phase");
  EXPECT_EQ(malformed.exitCode, 1);
  EXPECT_NE(malformed.err.find("--where 'phase': expected COLUMN=VALUE"), std::string::npos) << malformed.err;
}

TEST(NewUser, AnUnknownCommandIsNamedWithTheKnownOnes) {
  const CommandResult stats = tlab("stats glmm x.csv");
  EXPECT_EQ(stats.exitCode, 1);
  EXPECT_NE(stats.err.find("unknown command 'glmm' for 'tlab stats' (known: ttest, "), std::string::npos) << stats.err;
  EXPECT_NE(stats.err.find(" mixed,"), std::string::npos) << "the mixed model is where a GLMM is: " << stats.err;
  const CommandResult top = tlab("foo");
  EXPECT_EQ(top.exitCode, 1);
  EXPECT_NE(top.err.find("unknown command 'foo' for 'tlab' (known: demo, render"), std::string::npos) << top.err;
  const CommandResult none = tlab("stats");
  EXPECT_EQ(none.exitCode, 1);
  EXPECT_NE(none.err.find("'tlab stats' needs a command (known: ttest"), std::string::npos) << none.err;
}

// `tlab --version`, as most command-line tools take it: the line `tlab version` prints, exit 0
// (before, "'tlab' needs a command" and exit 1).
TEST(NewUser, VersionFlagPrintsWhatTheVersionCommandPrints) {
  const CommandResult flag = tlab("--version");
  const CommandResult command = tlab("version");
  EXPECT_EQ(flag.exitCode, 0) << flag.err;
  EXPECT_EQ(command.exitCode, 0) << command.err;
  EXPECT_EQ(flag.out.rfind("tlab 0.", 0), 0u) << flag.out;
  EXPECT_EQ(flag.out, command.out);
  EXPECT_EQ(flag.err, "");
}

// An option the command does not know is named even where a required argument is missing too
// (CLI11 checks those first: `tlab render --version` said "scene is required", and a mistyped
// option was never named).
TEST(NewUser, AnUnknownOptionIsNamedBeforeAMissingArgument) {
  const CommandResult version = tlab("render --version");
  EXPECT_EQ(version.exitCode, 1);
  EXPECT_EQ(version.err, "tlab: error: The following argument was not expected: --version (see --help)\n");
  const CommandResult typo = tlab("export --csvv out");
  EXPECT_EQ(typo.exitCode, 1);
  EXPECT_NE(typo.err.find("not expected: --csvv"), std::string::npos) << typo.err;
  const CommandResult missing = tlab("render --style smart");
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_NE(missing.err.find("scene is required"), std::string::npos) << missing.err;
}

TEST(NewUser, AnUnterminatedStringNamesTheLineItStarts) {
  const fs::path dir = freshDir("toml_string");
  const fs::path one = write(dir, "one.toml", "id = \"x\"\nwelcome = \"Hello\nseed = 3\n");
  const CommandResult a = tlab("design " + quoted(one.string()));
  EXPECT_EQ(a.exitCode, 1);
  EXPECT_NE(a.err.find(one.string() + ":2: unterminated string starting at line 2"), std::string::npos) << a.err;
  const fs::path multi = write(dir, "multi.toml", "id = \"x\"\n# a \"quoted\" comment\nwelcome = \"\"\"Hello\nthere\nseed = 3\n");
  const CommandResult b = tlab("design " + quoted(multi.string()));
  EXPECT_EQ(b.exitCode, 1);
  EXPECT_NE(b.err.find(multi.string() + ":3: unterminated string starting at line 3"), std::string::npos) << b.err;
  const fs::path other = write(dir, "other.toml", "id = \"x\"\nseed = = 3\n");
  const CommandResult c = tlab("design " + quoted(other.string()));
  EXPECT_EQ(c.exitCode, 1);
  EXPECT_EQ(c.err.find("unterminated"), std::string::npos) << c.err;
  EXPECT_NE(c.err.find(other.string() + ":2: "), std::string::npos) << c.err;
}

TEST(NewUser, TaskProbePrintsTheCameraItUsed) {
  const CommandResult probe = tlab("task probe builtin:open-cylinders --task layer-index --count 1 --seed 1 --size 96x96 --json");
  ASSERT_EQ(probe.exitCode, 0) << probe.err;
  const auto j = nlohmann::json::parse(probe.out);
  const std::string camera = j["camera"];
  EXPECT_EQ(camera.rfind("eye=", 0), 0u) << camera;
  EXPECT_NE(camera.find(" fovy="), std::string::npos) << camera;
  // Given back as --camera, the camera probes the same questions.
  const CommandResult again =
      tlab("task probe builtin:open-cylinders --task layer-index --count 1 --seed 1 --size 96x96 --json --camera " + quoted(camera));
  ASSERT_EQ(again.exitCode, 0) << again.err;
  const auto k = nlohmann::json::parse(again.out);
  EXPECT_EQ(k["camera"], j["camera"]);
  EXPECT_EQ(k["questions"], j["questions"]);
}

TEST(NewUser, AStudyReportIsOneFileWithEveryPlannedAnalysis) {
  const fs::path dir = freshDir("one_report");
  const fs::path file = write(dir, "two.toml",
                              experiment("[[tasks]]\ntask = \"layer-index\"\n\n[[analysis]]\ntitle = \"First\"\ndv = [\"correct\"]\nwithin = [\"method\"]\n"
                                         "tests = [\"t-tests\"]\n\n[[analysis]]\ntitle = \"Second\"\ndv = [\"rt\"]\nwithin = [\"method\"]\ntests = [\"t-tests\"]\n"));
  const fs::path db = dir / "two.db";
  ASSERT_EQ(tlab("simulate " + quoted(file.string()) + " --participants 2 --db " + quoted(db.string())).exitCode, 0);
  const CommandResult report = tlab("report " + quoted(db.string()) + " -o " + quoted((dir / "r" / "report.html").string()));
  ASSERT_EQ(report.exitCode, 0) << report.err;
  EXPECT_NE(report.out.find("report.html (2 planned analyses)"), std::string::npos) << report.out;
  int files = 0;
  for (const auto& f : fs::directory_iterator(dir / "r")) files += f.is_regular_file() ? 1 : 0;
  EXPECT_EQ(files, 1);
  const std::string html = readText((dir / "r" / "report.html").string());
  EXPECT_NE(html.find("First"), std::string::npos);
  EXPECT_NE(html.find("Second"), std::string::npos);
}

}  // namespace
}  // namespace tlab::testing
