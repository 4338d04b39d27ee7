#pragma once
// A transparency style: its parameters, the fill and fragment properties it needs, and the ordered
// passes (operators, then compositing) it runs on that fill. The pipeline builds exactly what the
// style declares.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "renderer/buffer/fragment_layout.hpp"
#include "renderer/kbuffer/bucketed_kbuffer.hpp"
#include "renderer/frame/render_pass.hpp"
#include "renderer/params/style_params.hpp"

namespace tlab::render {

// The fill a style declares (renderer/frame/fill.hpp): none (the nearest surface only), the
// illustration buffer, or the bucketed k-buffer (seed 002) with its settings (near/far are set
// from the camera). Depth peeling is asked for by the request (RenderRequest::depthPeeling) and
// takes the local styles only.
struct FillSpec {
  enum class Kind { None, FragmentBuffer, BucketedKBuffer };
  Kind kind = Kind::FragmentBuffer;
  KBufferSettings kBuffer{};  // for Kind::BucketedKBuffer
  // For Kind::FragmentBuffer: the style's compositor sorts each pixel's list itself (issue #29,
  // compose/blend.comp), so the fill may leave the lists unsorted; a pass that binds the sorted
  // lists all the same gets them sorted then.
  bool sortsInCompose = false;
  // For Kind::FragmentBuffer: the sort also writes each fragment's colour word into a plane of its
  // own (FragmentBuffer::setColorPlane), for a compositor that reads only the colour of the records.
  bool colorPlane = false;
};

// Facts about the scene a style may use to leave out what it does not need.
struct SceneFacts {
  std::uint32_t componentCount = 1;
};

class Style {
 public:
  virtual ~Style() = default;
  virtual std::string name() const = 0;
  virtual std::string description() const = 0;
  // The style's own parameters; `lighting` is added for every style (see allParams).
  virtual std::vector<ParamSpec> params() const = 0;
  // The fill the style needs; the illustration buffer unless a style says otherwise.
  virtual FillSpec fill(const StyleParams&) const { return {}; }
  virtual FragmentProperties properties(const StyleParams& params, const SceneFacts& facts) const = 0;
  // Checks combinations of parameters (single values are checked against their ParamSpec).
  virtual void validate(const StyleParams&) const {}
  virtual std::vector<std::unique_ptr<RenderPass>> passes(const StyleParams& params) const = 0;
  // A style loaded from a file: the SHA-256 of its text (its identity); built-in styles have none.
  virtual std::optional<std::string> fileSha256() const { return std::nullopt; }

  std::vector<ParamSpec> allParams() const;
  StyleParams resolve(const std::map<std::string, std::string>& settings) const;
};

// The common `lighting` key (every style has it; a style may declare it with its own default) and
// the TLAB_LIGHTING value of frame/surface_shading.glsl it selects: 0 none, 1 headlight, 2 pbr.
ParamSpec lightingParam(const std::string& defaultValue);
int lightingModel(const StyleParams& params);

// The registered styles, by name, or a style file by its path (a name ending in .glsl: loaded,
// validated and kept for the process, reloaded when the file changes); throws
// std::invalid_argument listing the known ones, or "FILE:LINE: message" for a bad style file.
const Style& findStyle(const std::string& name);
std::vector<std::string> styleNames();

}  // namespace tlab::render
