// tlab demo end to end at a reduced size, as a researcher runs it: the database holds every
// participant's finished session with one response per trial, the report is one HTML page with
// stimuli and plots, and it opens in headless Chromium (a real browser; screenshot checked).
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <filesystem>
#include <string>

#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>

#include "tests/support/run_command.hpp"

namespace tlab::testing {
namespace {

namespace fs = std::filesystem;

// The single integer a query returns.
long long scalar(sqlite3* db, const std::string& sql) {
  sqlite3_stmt* statement = nullptr;
  EXPECT_EQ(sqlite3_prepare_v2(db, sql.c_str(), -1, &statement, nullptr), SQLITE_OK) << sql;
  long long value = -1;
  if (sqlite3_step(statement) == SQLITE_ROW) value = sqlite3_column_int64(statement, 0);
  sqlite3_finalize(statement);
  return value;
}

// One run of the demo is checked by the parts below (ctest runs each TEST in its own process, so
// they are one TEST: the demo runs once).
struct DemoRun {
  std::string dir_;
  CommandResult result_;
  void printsTheSummaryAndTheTests();
  void databaseHoldsEveryFinishedSessionAndOneResponsePerTrial();
  void reportIsOnePageWithStimuliAndPlotsThatChromiumRenders();
  void refusesToOverwriteAStudy();
};

TEST(Demo, ReducedCarneckyReplicationEndToEnd) {
  DemoRun run;
  run.dir_ = freshDir("tlab_demo_test").string();
  run.result_ = runCommand(std::string(TLAB_EXE) + " demo --out " + testing::quoted(run.dir_) + " --participants 3 --size 240x240");
  ASSERT_EQ(run.result_.exitCode, 0) << run.result_.err;
  {
    SCOPED_TRACE("summary");
    run.printsTheSummaryAndTheTests();
  }
  {
    SCOPED_TRACE("database");
    run.databaseHoldsEveryFinishedSessionAndOneResponsePerTrial();
  }
  {
    SCOPED_TRACE("report in Chromium");
    run.reportIsOnePageWithStimuliAndPlotsThatChromiumRenders();
  }
  {
    SCOPED_TRACE("second run refused");
    run.refusesToOverwriteAStudy();
  }
}

void DemoRun::printsTheSummaryAndTheTests() {
  EXPECT_NE(result_.out.find("Percentage correct by task and method"), std::string::npos) << result_.out;
  for (const char* method : {"alpha", "normal-variation", "smart"}) EXPECT_NE(result_.out.find(method), std::string::npos) << method;
  EXPECT_NE(result_.out.find("t("), std::string::npos) << "a paired t-test line";
  EXPECT_NE(result_.out.find("report: "), std::string::npos);
}

void DemoRun::databaseHoldsEveryFinishedSessionAndOneResponsePerTrial() {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open_v2((dir_ + "/study.db").c_str(), &db, SQLITE_OPEN_READONLY, nullptr), SQLITE_OK);
  EXPECT_EQ(scalar(db, "SELECT count(*) FROM participants"), 3);
  EXPECT_EQ(scalar(db, "SELECT count(*) FROM participants WHERE status = 'finished'"), 3);
  const long long trials = scalar(db, "SELECT count(*) FROM trials");
  EXPECT_GT(trials, 3 * 3);
  EXPECT_EQ(scalar(db, "SELECT count(*) FROM responses"), trials);
  EXPECT_EQ(scalar(db, "SELECT count(DISTINCT trial) FROM responses"), trials);
  // Every trial names a stimulus file that exists and whose hash is recorded.
  EXPECT_EQ(scalar(db, "SELECT count(*) FROM trials WHERE length(stimulus_sha256) <> 64"), 0);
  sqlite3_close(db);
  // The experiment text stored is the file the demo wrote (with the reduced size).
  const std::string written = readText(dir_ + "/carnecky2013.toml");
  EXPECT_NE(written.find("size = \"240x240\""), std::string::npos);
}

void DemoRun::reportIsOnePageWithStimuliAndPlotsThatChromiumRenders() {
  const std::string html = readText(dir_ + "/report.html");
  EXPECT_NE(html.find("data:image/png;base64,"), std::string::npos) << "stimulus gallery";
  EXPECT_NE(html.find("data:image/svg+xml;base64,"), std::string::npos) << "plots";
  EXPECT_NE(html.find("Percentage correct by task and method"), std::string::npos);

  const std::string shot = dir_ + "/report.png";
  const CommandResult chromium = runCommand(
      "chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run --disable-background-networking "
      "--disable-component-update --disable-sync --user-data-dir=" + testing::quoted(dir_ + "/chromium-profile") +
      " --window-size=1200,1600 --screenshot=" + testing::quoted(shot) + " " + testing::quoted("file://" + fs::absolute(dir_ + "/report.html").string()));
  ASSERT_EQ(chromium.exitCode, 0) << chromium.err;
  int w = 0, h = 0, n = 0;
  unsigned char* pixels = stbi_load(shot.c_str(), &w, &h, &n, 3);
  ASSERT_NE(pixels, nullptr) << "screenshot " << shot;
  EXPECT_EQ(w, 1200);
  EXPECT_EQ(h, 1600);
  // A rendered page: dark text and coloured stimuli on a white background, not a blank page.
  long dark = 0, white = 0;
  for (long i = 0; i < long(w) * h; ++i) {
    const int sum = pixels[3 * i] + pixels[3 * i + 1] + pixels[3 * i + 2];
    dark += sum < 3 * 128;
    white += sum == 3 * 255;
  }
  stbi_image_free(pixels);
  EXPECT_GT(dark, long(w) * h / 200) << "too little ink: the page did not render";
  EXPECT_GT(white, long(w) * h / 4);
}

void DemoRun::refusesToOverwriteAStudy() {
  const auto again = runCommand(std::string(TLAB_EXE) + " demo --out " + testing::quoted(dir_) + " --participants 3 --size 240x240");
  EXPECT_EQ(again.exitCode, 1);
  EXPECT_NE(again.err.find("already holds a study"), std::string::npos) << again.err;
  EXPECT_EQ(again.err.find('\n'), again.err.size() - 1) << "one line: " << again.err;
}

}  // namespace
}  // namespace tlab::testing
