#pragma once
// A style written as a file (Filament's material files as the anchor: declared, validated, then
// compiled). One file holds the declarations — in a leading `/* tlab style ... */` comment, as
// TOML — and the GLSL that follows it:
//
//   /* tlab style
//   name = "depth-tinted-alpha"
//   description = "opacity grows with depth"
//   properties = ["color"]          # depth is always there
//   neighbors = false               # true: the per-fragment stage with Carnecky Alg. 2 links
//   iterations = 0                  # its default number of iterations (the `iterations` parameter)
//   [[parameter]]
//   name = "alpha_near"
//   type = "float"                  # float | int | bool
//   default = 0.1
//   range = [0.0, 1.0]              # float and int: finite, within the uniform type's range
//   description = "opacity of a layer at the near plane"
//   */
//   vec4 composite() { ... }
//
// Every error names the file and the line: "FILE:LINE: field: message".
#include <string>
#include <vector>

#include "renderer/buffer/fragment_layout.hpp"
#include "renderer/params/style_params.hpp"
#include "renderer/params/style_program.hpp"

namespace tlab::render {

struct StyleParameter {
  ParamSpec spec;
  StyleValueType type = StyleValueType::Float;
  int line = 0;  // where the parameter is declared
};

struct StyleDeclaration {
  std::string name;
  std::string description;
  std::vector<StyleParameter> parameters;
  FragmentProperties properties;  // beyond depth, which every record holds
  bool neighbors = false;
  int iterations = 0;  // default of the `iterations` parameter when neighbors = true
};

struct StyleFile {
  std::string path;    // as given (made absolute by whoever resolves a relative one)
  std::string text;    // the whole file, bytes unchanged
  std::string sha256;  // of text: the style's identity in stats, manifests and the database
  StyleDeclaration declaration;
  // The parameters as the Style interface lists them (the declared ones, then `iterations`).
  std::vector<ParamSpec> params() const;
  // "FILE:LINE: message"
  std::string at(int line, const std::string& message) const;
  // The GLSL program with these parameter values (resolved by Style::resolve).
  StyleProgram program(const StyleParams& params) const;
};

// Whether a --style / style = value names a file rather than a built-in style.
bool isStyleFilePath(const std::string& style);

// Reads and validates a style file; throws std::invalid_argument "FILE:LINE: field: message".
StyleFile loadStyleFile(const std::string& path);
// The same from text already read (for tests and for the loader).
StyleFile parseStyleFile(const std::string& path, std::string text);

// The declared property names, as --stats-json lists them (FragmentLayout::propertyNames).
FragmentProperty parsePropertyName(const std::string& name);

}  // namespace tlab::render
