// docs/cli-reference.md is generated from `tlab ... --help` (scripts/cli-reference.sh); this test
// generates it again from the tlab just built and compares, so that a changed option or
// description cannot leave the committed reference behind (it had: `tlab --version` was missing).
#include <gtest/gtest.h>

#include "tests/support/run_command.hpp"

using namespace tlab::testing;

TEST(CliReference, TheCommittedReferenceIsWhatTlabHelpPrints) {
  const std::string source = TLAB_SOURCE_DIR;
  const auto dir = freshDir("cli_reference");
  const auto fresh = (dir / "cli-reference.md").string();
  const auto r = runCommand("TLAB=" + quoted(TLAB_EXE) + " bash " + quoted(source + "/scripts/cli-reference.sh") + " " + quoted(fresh));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(readText(fresh) == readText(source + "/docs/cli-reference.md"))
      << "docs/cli-reference.md is not what this tlab's --help prints: run `bash scripts/cli-reference.sh` and commit it\n"
      << runCommand("diff " + quoted(source + "/docs/cli-reference.md") + " " + quoted(fresh)).out;
}
