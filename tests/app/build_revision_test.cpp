// The version every study record, report and replay stores ("0.1.0+1fc72aa") names the tree the
// binary was built from: cmake/RevisionScript.cmake runs at every build, not once at configure
// time (where a pull or an edit followed by `cmake --build` kept the old commit), marks a tree
// whose tracked files differ from the commit "-dirty", and says "unknown" outside a checkout of
// its own. Tested on throw-away git repositories, then on the built tlab and what it logs.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "tests/support/run_command.hpp"
#include "tests/support/tlab_version.hpp"

namespace tlab::testing {
namespace {

namespace fs = std::filesystem;

const std::string kScript = std::string(TLAB_SOURCE_DIR) + "/cmake/RevisionScript.cmake";

CommandResult git(const fs::path& repo, const std::string& arguments) {
  return runCommand("git -C " + quoted(repo.string()) +
                    " -c user.name=tlab -c user.email=tlab@example.org -c commit.gpgsign=false " + arguments);
}

std::string shortHead(const fs::path& repo) {
  const auto r = git(repo, "rev-parse --short HEAD");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  return r.out.substr(0, r.out.find('\n'));
}

// Runs the script for `source` and returns the revision the generated file returns.
std::string revisionOf(const fs::path& source, const fs::path& out) {
  const auto r = runCommand("cmake -DSOURCE_DIR=" + quoted(source.string()) + " -DOUT=" + quoted(out.string()) + " -P " + kScript);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  std::smatch m;
  const std::string text = readText(out.string());
  EXPECT_TRUE(std::regex_search(text, m, std::regex("buildRevision\\(\\) \\{ return \"([^\"]*)\"; \\}"))) << text;
  return m.size() > 1 ? m[1].str() : "";
}

fs::path repoWithOneCommit(const std::string& name) {
  const fs::path dir = freshDir(name);
  const fs::path repo = dir / "src";
  fs::create_directories(repo / "inner");
  std::ofstream(repo / "inner" / "a.txt") << "one\n";
  EXPECT_EQ(git(repo, "init -q").exitCode, 0);
  EXPECT_EQ(git(repo, "add inner/a.txt").exitCode, 0);
  EXPECT_EQ(git(repo, "commit -q -m one").exitCode, 0);
  return repo;
}

TEST(BuildRevision, NamesTheCommitAndMarksATreeWhoseTrackedFilesDifferFromIt) {
  const fs::path repo = repoWithOneCommit("revision_commit");
  const fs::path out = repo.parent_path() / "build_revision.cpp";
  const std::string first = shortHead(repo);
  ASSERT_FALSE(first.empty());
  EXPECT_EQ(revisionOf(repo, out), first);

  // A file git does not track (a study database, a build folder) leaves the tree clean, and an
  // unchanged revision does not rewrite the file (nothing relinks).
  std::ofstream(repo / "study.db") << "x";
  const auto written = fs::last_write_time(out);
  fs::last_write_time(out, written - std::chrono::hours(1));
  EXPECT_EQ(revisionOf(repo, out), first);
  EXPECT_EQ(fs::last_write_time(out), written - std::chrono::hours(1));

  // An edited tracked file, staged or not, is not the commit.
  std::ofstream(repo / "inner" / "a.txt") << "two\n";
  EXPECT_EQ(revisionOf(repo, out), first + "-dirty");
  ASSERT_EQ(git(repo, "add inner/a.txt").exitCode, 0);
  EXPECT_EQ(revisionOf(repo, out), first + "-dirty");

  // Committed, the next build names the new commit.
  ASSERT_EQ(git(repo, "commit -q -m two").exitCode, 0);
  const std::string second = shortHead(repo);
  EXPECT_NE(second, first);
  EXPECT_EQ(revisionOf(repo, out), second);
  fs::remove_all(repo.parent_path());
}

TEST(BuildRevision, IsUnknownOutsideAGitCheckoutOfItsOwn) {
  const fs::path repo = repoWithOneCommit("revision_unknown");
  const fs::path out = repo.parent_path() / "build_revision.cpp";
  // A source folder inside some other repository (an unpacked tarball in a checkout) is not
  // that repository's commit.
  EXPECT_EQ(revisionOf(repo / "inner", out), "unknown");
  const fs::path plain = repo.parent_path() / "plain";
  fs::create_directories(plain);
  EXPECT_EQ(revisionOf(plain, out), "unknown");
  fs::remove_all(repo.parent_path());
}

TEST(BuildRevision, TlabPrintsAndLogsTheRevisionOfItsSourceTree) {
  const std::string version = tlabVersionString();
  ASSERT_NE(version, "") << runCommand(std::string(TLAB_EXE) + " version").out;
  const std::string revision = version.substr(version.find('+') + 1);
  const auto top = runCommand("git -C " + quoted(TLAB_SOURCE_DIR) + " rev-parse --show-toplevel");
  if (top.exitCode == 0 && fs::equivalent(top.out.substr(0, top.out.find('\n')), TLAB_SOURCE_DIR))
    EXPECT_EQ(revision.substr(0, revision.find('-')), shortHead(TLAB_SOURCE_DIR)) << "rebuild after a commit";
  else
    EXPECT_EQ(revision, "unknown");

  // What a study stores: the session's display and the participant's record.
  const fs::path dir = freshDir("revision_logged");
  std::ofstream(dir / "e.toml") << "id = \"plan\"\nseed = 3\nparticipants = 1\n\n[stimulus]\nsize = \"48x48\"\n"
                                   "scene = \"builtin:nested-spheres?n=2\"\nstyle = \"constant\"\n\n"
                                   "[[tasks]]\ntask = \"layer-index\"\ntrials = 1\n";
  const std::string db = (dir / "s.db").string(), csv = (dir / "csv").string();
  const auto simulated = runCommand(std::string(TLAB_EXE) + " simulate " + (dir / "e.toml").string() + " --participants 1 --db " + db);
  ASSERT_EQ(simulated.exitCode, 0) << simulated.err;
  ASSERT_EQ(runCommand(std::string(TLAB_EXE) + " export " + db + " --csv " + csv).exitCode, 0);
  const std::string logged = "\"\"tlab_version\"\":\"\"" + version + "\"\"";
  EXPECT_NE(readText(csv + "/sessions.csv").find(logged), std::string::npos) << readText(csv + "/sessions.csv");
  // And what the researcher reads: tlab timing (and the report's timing table) per session.
  const auto timing = runCommand(std::string(TLAB_EXE) + " timing " + db);
  ASSERT_EQ(timing.exitCode, 0) << timing.err;
  EXPECT_NE(timing.out.find(" " + version + " "), std::string::npos) << timing.out;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tlab::testing
