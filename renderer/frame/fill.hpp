#pragma once
// A fill: one way to build the per-pixel fragment store of a frame (ARCHITECTURE "Fill"). Three
// implementations: the illustration buffer (buffer/FragmentBuffer), the bucketed k-buffer
// (kbuffer/BucketedKBuffer) and depth peeling (peel/DepthPeeling). A Style declares which one it
// needs (Style::fill); the Renderer builds it, then runs the style's passes on it.
namespace tlab::render {

struct FrameContext;
class PassTimer;

class Fill {
 public:
  virtual ~Fill() = default;
  // Rasterizes the frame's scene into the store; timed under the fill's own pass names.
  virtual void build(FrameContext& frame, PassTimer& timer) = 0;
  // True for a fill that composes the picture itself while it builds (depth peeling blends each
  // layer as it peels it): the Renderer then runs no style pass after it.
  virtual bool composesPicture() const { return false; }
};

}  // namespace tlab::render
