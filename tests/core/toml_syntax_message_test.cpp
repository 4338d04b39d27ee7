#include "core/toml_syntax_message.hpp"

#include <gtest/gtest.h>

namespace tlab::core {
namespace {

TEST(TomlSyntaxMessage, AOneLineStringLeftOpenNamesTheLineItStarts) {
  EXPECT_EQ(tomlSyntaxMessage("id = \"x\"\nwelcome = \"Hello\nseed = 3\n", 2, "Error while parsing string: unescaped control characters"),
            "2: unterminated string starting at line 2 (a closing quote is missing)");
  EXPECT_EQ(tomlSyntaxMessage("a = 'it\nb = 1\n", 1, "Error while parsing literal string: control characters"),
            "1: unterminated string starting at line 1 (a closing quote is missing)");
}

TEST(TomlSyntaxMessage, AMultiLineStringLeftOpenNamesItsOpeningLine) {
  const char* text = "id = \"x\"\n# \"quoted\" and 'quoted' in a comment\nt = \"\"\"line \\\"\"\" inside\nmore\n";
  EXPECT_EQ(tomlSyntaxMessage(text, 5, "Error while parsing string: encountered end-of-file"),
            "3: unterminated string starting at line 3 (a closing quote is missing)");
}

TEST(TomlSyntaxMessage, OtherErrorsKeepTheParsersLineAndWords) {
  EXPECT_EQ(tomlSyntaxMessage("a = \"ok\"\nb = = 1\n", 2, "Error while parsing key-value pair: expected value"),
            "2: Error while parsing key-value pair: expected value");
  // Every string closed: the parser's own words stand even where they mention strings.
  EXPECT_EQ(tomlSyntaxMessage("a = \"\"\"x\"\"\"\nb = 'y'\n", 2, "Error while parsing string: bad escape"), "2: Error while parsing string: bad escape");
}

}  // namespace
}  // namespace tlab::core
