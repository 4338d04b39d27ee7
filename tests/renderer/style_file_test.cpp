// A style file's declarations: what they declare, and one line "FILE:LINE: field: message" for
// every mistake (no GL: the GLSL is compiled by style_file_gl_test).
#include <gtest/gtest.h>

#include "renderer/params/style_program.hpp"
#include "renderer/styles/style.hpp"
#include "renderer/styles/style_file.hpp"

using namespace tlab::render;

namespace {

const std::string kValid = R"(/* tlab style
name = "halo"
description = "a test style"
properties = ["color", "normal"]
neighbors = true
iterations = 12

[[parameter]]
name = "width"
type = "float"
default = 0.5
range = [0.0, 2.0]
description = "how wide"

[[parameter]]
name = "steps"
type = "int"
default = 3
range = [1, 8]
description = "how many"

[[parameter]]
name = "flip"
type = "bool"
default = false
description = "whether to flip"
*/
vec4 composite() { return vec4(width); }
)";

std::string errorOf(const std::string& text) {
  try {
    parseStyleFile("s.glsl", text);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

}  // namespace

TEST(StyleFile, ReadsTheDeclarations) {
  const StyleFile f = parseStyleFile("s.glsl", kValid);
  EXPECT_EQ(f.declaration.name, "halo");
  EXPECT_EQ(f.declaration.description, "a test style");
  EXPECT_TRUE(f.declaration.properties.has(FragmentProperty::Color));
  EXPECT_TRUE(f.declaration.properties.has(FragmentProperty::Normal));
  EXPECT_FALSE(f.declaration.properties.has(FragmentProperty::Ids));
  EXPECT_TRUE(f.declaration.neighbors);
  EXPECT_EQ(f.declaration.iterations, 12);
  ASSERT_EQ(f.declaration.parameters.size(), 3u);
  EXPECT_EQ(f.declaration.parameters[0].spec.name, "width");
  EXPECT_EQ(f.declaration.parameters[0].spec.minValue, 0.0);
  EXPECT_EQ(f.declaration.parameters[0].spec.maxValue, 2.0);
  EXPECT_EQ(f.declaration.parameters[0].line, 8);
  EXPECT_EQ(f.declaration.parameters[1].type, StyleValueType::Int);
  EXPECT_EQ(f.declaration.parameters[2].type, StyleValueType::Bool);
  const auto specs = f.params();
  ASSERT_EQ(specs.size(), 4u);
  EXPECT_EQ(specs[3].name, "iterations");
  EXPECT_EQ(specs[3].defaultValue, "12");
  // SHA-256 of the bytes as written (the same text as `sha256sum` reads).
  EXPECT_EQ(f.sha256.size(), 64u);
  EXPECT_NE(parseStyleFile("s.glsl", kValid + " ").sha256, f.sha256);
}

TEST(StyleFile, ParametersBecomeUniformsWithTheResolvedValues) {
  const StyleFile f = parseStyleFile("s.glsl", kValid);
  const StyleParams params("halo", f.params(), {{"width", "1.5"}, {"flip", "true"}});
  const StyleProgram p = f.program(params);
  ASSERT_EQ(p.uniforms.size(), 3u);
  EXPECT_EQ(p.uniforms[0].name, "width");
  EXPECT_EQ(p.uniforms[0].value, 1.5);
  EXPECT_EQ(p.uniforms[1].value, 3.0);
  EXPECT_EQ(p.uniforms[2].value, 1.0);
  EXPECT_THROW(StyleParams("halo", f.params(), {{"width", "2.5"}}), std::invalid_argument);
}

TEST(StyleFile, EveryMistakeNamesTheFileLineAndField) {
  EXPECT_EQ(errorOf("vec4 composite() { return vec4(1); }\n").substr(0, 9), "s.glsl:1:");
  EXPECT_EQ(errorOf(replaced(kValid, "description = \"how wide\"", "description = \"how wide\"\nunit = \"mm\"")),
            "s.glsl:14: parameter[1].unit: unknown key (known: default, description, name, range, type)");
  EXPECT_EQ(errorOf(replaced(kValid, "default = 0.5", "default = 3.5")), "s.glsl:11: parameter[1].default: outside its range");
  EXPECT_EQ(errorOf(replaced(kValid, "\"normal\"]", "\"curvature\"]")).substr(0, 32), "s.glsl:4: properties[2]: unknown");
  EXPECT_EQ(errorOf(replaced(kValid, "type = \"int\"", "type = \"vec3\"")),
            "s.glsl:17: parameter[2].type: expected \"float\", \"int\" or \"bool\", got 'vec3'");
  EXPECT_EQ(errorOf(replaced(kValid, "name = \"steps\"", "name = \"lighting\"")),
            "s.glsl:16: parameter[2].name: 'lighting' is tlab's own parameter");
  EXPECT_EQ(errorOf(replaced(kValid, "default = 3\n", "default = 2.5\n")),
            "s.glsl:18: parameter[2].default: an int parameter takes whole numbers (default and range)");
  EXPECT_EQ(errorOf(replaced(kValid, "neighbors = true", "neighbors = false")),
            "s.glsl:6: iterations: only a style with neighbors = true iterates");
  EXPECT_EQ(errorOf(replaced(kValid, "name = \"halo\"", "name = halo")).substr(0, 23), "s.glsl:2: declarations:");
  EXPECT_EQ(errorOf(replaced(kValid, "vec4 composite()", "#version 450\nvec4 composite()")),
            "s.glsl:28: #version: tlab supplies it (450 core); remove the line");
  EXPECT_EQ(errorOf(replaced(kValid, "*/", "")).substr(0, 9), "s.glsl:1:");
}

// A default resolves to the number declared, every digit of it (it used to be rounded to six
// significant digits: 0.1234567 became 0.123457, and a default at the end of its range was
// refused as "0.123457 is outside [0, 0.123457]" by the style that declared it).
TEST(StyleFile, ADefaultIsTheDeclaredNumberToTheLastDigit) {
  const StyleFile f = parseStyleFile("s.glsl", replaced(replaced(kValid, "default = 0.5", "default = 0.1234567"),
                                                        "range = [0.0, 2.0]", "range = [0.0, 0.1234567]"));
  EXPECT_EQ(f.params()[0].defaultValue, "0.1234567");
  const StyleParams defaults("halo", f.params(), {});
  EXPECT_EQ(defaults.number("width"), 0.1234567);
  EXPECT_EQ(f.program(defaults).uniforms[0].value, 0.1234567);
  // The range a refusal prints is the declared one, which a user can type back.
  try {
    StyleParams("halo", f.params(), {{"width", "0.12345671"}});
    ADD_FAILURE() << "a value above the range was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "style 'halo' parameter 'width' = 0.12345671 is outside [0, 0.1234567]");
  }
  EXPECT_EQ(StyleParams("halo", f.params(), {{"width", "0.1234567"}}).number("width"), 0.1234567);
}

// A parameter is a GLSL uniform: its default and range are finite, and its range fits its type
// (an int range beyond 32 bits let --set pass 3000000000, which no GLSL int holds).
TEST(StyleFile, ParametersFitTheirGlslType) {
  EXPECT_EQ(errorOf(replaced(kValid, "range = [1, 8]", "range = [0, 1e12]")),
            "s.glsl:19: parameter[2].range: an int parameter's range lies within [-2147483648, 2147483647] (a GLSL int)");
  EXPECT_EQ(errorOf(replaced(kValid, "range = [1, 8]", "range = [-2147483649, 8]")),
            "s.glsl:19: parameter[2].range: an int parameter's range lies within [-2147483648, 2147483647] (a GLSL int)");
  EXPECT_EQ(parseStyleFile("s.glsl", replaced(kValid, "range = [1, 8]", "range = [-2147483648, 2147483647]"))
                .declaration.parameters[1].spec.maxValue,
            2147483647.0);
  EXPECT_EQ(errorOf(replaced(kValid, "range = [0.0, 2.0]", "range = [0.0, 1e39]")),
            "s.glsl:12: parameter[1].range: a float parameter's range lies within [-3.40282e+38, 3.40282e+38] (a GLSL float)");
  EXPECT_EQ(errorOf(replaced(kValid, "default = 0.5", "default = nan")), "s.glsl:11: parameter[1].default: must be a finite number");
  EXPECT_EQ(errorOf(replaced(kValid, "range = [0.0, 2.0]", "range = [0.0, inf]")), "s.glsl:12: parameter[1].range: must be a finite number");
  EXPECT_EQ(errorOf(replaced(kValid, "range = [0.0, 2.0]", "range = [-inf, 2.0]")), "s.glsl:12: parameter[1].range: must be a finite number");
}

TEST(StyleFile, AStyleFileIsNamedByItsPath) {
  EXPECT_TRUE(isStyleFilePath("styles/mine.glsl"));
  EXPECT_TRUE(isStyleFilePath("mine.glsl"));
  EXPECT_FALSE(isStyleFilePath("constant"));
  EXPECT_FALSE(isStyleFilePath(".glsl"));
  EXPECT_THROW(findStyle("/nonexistent/mine.glsl"), std::invalid_argument);
}

TEST(StyleFile, CompilerLogsMapToTheUsersLine) {
  // Mesa (llvmpipe) and NVIDIA word their logs differently; source string 1 is the user's file.
  EXPECT_EQ(mapStyleCompileLog("a.glsl", "1:17(12): error: `alpah' undeclared\n1:17(3): error: ..."),
            "a.glsl:17: `alpah' undeclared");
  EXPECT_EQ(mapStyleCompileLog("a.glsl", "1(23) : error C1008: undefined variable \"alpah\""),
            "a.glsl:23: undefined variable \"alpah\"");
  EXPECT_EQ(mapStyleCompileLog("a.glsl", "2:12(3): error: no function with name 'composite'").substr(0, 52),
            "a.glsl:1: no function with name 'composite' (in tlab");
  // Drivers that ignore #line's source-string number: tlab's own lines are numbered from 10^6.
  EXPECT_EQ(mapStyleCompileLog("a.glsl", "0:17(12): error: `alpah' undeclared"), "a.glsl:17: `alpah' undeclared");
  EXPECT_EQ(mapStyleCompileLog("a.glsl", "0:2000004(3): error: no function with name 'composite'").substr(0, 44),
            "a.glsl:1: no function with name 'composite' ");
}
