#pragma once
// One pass of a style (VTK render-pass style): a small object with one job, run on the frame in
// the order the style lists them.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "renderer/frame/frame_context.hpp"

namespace tlab::render {

class RenderPass {
 public:
  virtual ~RenderPass() = default;
  virtual std::string name() const = 0;
  virtual void run(FrameContext& frame) = 0;
  // What the pass computes and what it leaves out for these parameters (for --stats-json).
  virtual std::vector<std::string> operations() const { return {}; }
};

// A pass that is a name and a callable: most passes are one operator or compositor call with the
// style's settings, so they need no class of their own. The callable may note in `operations`
// what it computed and what it left out.
class FunctionPass final : public RenderPass {
 public:
  using Body = std::function<void(FrameContext& frame, std::vector<std::string>& operations)>;
  FunctionPass(std::string name, Body body) : name_(std::move(name)), body_(std::move(body)) {}
  std::string name() const override { return name_; }
  void run(FrameContext& frame) override { body_(frame, operations_); }
  std::vector<std::string> operations() const override { return operations_; }

 private:
  std::string name_;
  Body body_;
  std::vector<std::string> operations_;
};

// A FunctionPass that notes no operations.
inline std::unique_ptr<RenderPass> functionPass(std::string name, std::function<void(FrameContext&)> run) {
  return std::make_unique<FunctionPass>(std::move(name),
                                        [run = std::move(run)](FrameContext& frame, std::vector<std::string>&) { run(frame); });
}

}  // namespace tlab::render
