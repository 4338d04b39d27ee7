#pragma once
// A style loaded from a file (styles/style_file.hpp) beside the built-in ones: the Renderer runs it
// like any other style — the illustration buffer with the declared properties, the optional
// per-fragment stage over Carnecky Alg. 2 links, then the user's compositor.
#include "renderer/styles/style.hpp"
#include "renderer/styles/style_file.hpp"

namespace tlab::render {

class FileStyle final : public Style {
 public:
  explicit FileStyle(StyleFile file) : file_(std::move(file)) {}
  const StyleFile& file() const { return file_; }

  std::string name() const override { return file_.declaration.name; }
  std::string description() const override { return file_.declaration.description; }
  std::vector<ParamSpec> params() const override { return file_.params(); }
  FragmentProperties properties(const StyleParams& params, const SceneFacts& facts) const override;
  void validate(const StyleParams& params) const override;
  std::vector<std::unique_ptr<RenderPass>> passes(const StyleParams& params) const override;
  std::optional<std::string> fileSha256() const override { return file_.sha256; }

  // Compiles every stage of the style on the current GL context (tlab design checks a style this
  // way before any session); throws "FILE:LINE: message".
  void compile(gpu::ShaderCache& shaders) const;

 private:
  StyleFile file_;
};

}  // namespace tlab::render
