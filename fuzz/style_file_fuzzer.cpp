// Fuzz target: a style file's text (a researcher's own technique, "Your own technique") through
// parseStyleFile — the TOML declarations read by toml++ and checked field by field — and, when it
// is accepted, through what every render then does with it before any GL: resolve the parameters
// (defaults, and each range's two ends as a user would type them back from the listing) and build
// the program's uniforms. A rejection is one std::invalid_argument "FILE:LINE: ..."; an accepted
// file's every default must resolve, and every value its ranges allow must fit its GLSL type.
// fuzz-sources: renderer/styles/style_file.cpp renderer/params/style_params.cpp
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "core/parse_number.hpp"
#include "renderer/styles/style_file.hpp"

namespace {

using namespace tlab::render;

void require(bool ok) {
  if (!ok) std::abort();
}

// Every uniform of the program with these parameters holds a value of its GLSL type.
void requireUniformsFit(const StyleFile& f, const StyleParams& params) {
  for (const auto& u : f.program(params).uniforms) {
    require(std::isfinite(u.value));
    if (u.type == StyleValueType::Int)
      require(u.value == std::floor(u.value) && u.value >= double(INT32_MIN) && u.value <= double(INT32_MAX));
    if (u.type == StyleValueType::Float) require(std::abs(u.value) <= double(FLT_MAX));
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  StyleFile f;
  try {
    f = parseStyleFile("fuzz.glsl", std::string(reinterpret_cast<const char*>(data), size));
  } catch (const std::invalid_argument& e) {
    require(std::string(e.what()).rfind("fuzz.glsl:", 0) == 0);
    return 0;
  }
  const auto specs = f.params();
  const StyleParams defaults(f.declaration.name, specs, {});  // must not throw: the file was accepted
  requireUniformsFit(f, defaults);
  for (const auto& spec : specs) {
    if (spec.kind != ParamSpec::Kind::Number) continue;
    const double d = defaults.number(spec.name);
    require(d >= spec.minValue && d <= spec.maxValue);
    require(tlab::core::roundTripText(d) == spec.defaultValue);
    for (const double end : {spec.minValue, spec.maxValue}) {
      const StyleParams at(f.declaration.name, specs, {{spec.name, tlab::core::roundTripText(end)}});
      require(at.number(spec.name) == end);
      requireUniformsFit(f, at);
    }
  }
  return 0;
}
