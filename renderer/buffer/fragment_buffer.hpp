#pragma once
// The illustration buffer (Carnecky Sec. 4): every fragment of every surface layer, per pixel,
// sorted front to back into contiguous per-pixel blocks (pixelHead/pixelCount, Sec. 4.3).
//
// Two ways to fill it:
//  - CountScatter: a count pass (per-pixel atomics only) → prefix sum → a scatter pass writing
//    each fragment straight into its pixel's block. The pool is sized from the exact count.
//    When K slots per pixel, K the longest list seen so far, fit the memory budget, the count
//    pass also stores each pixel's first K records in slots (buffer/fill_slots.frag: one
//    rasterization instead of two); a pixel with more than K fragments makes that frame fall
//    back to the scatter pass, which the exact counts already prepared (issue #29). The sorted
//    buffer is the same either way. A frame whose lists all fit their slots and whose compositor
//    sorts (setSortInCompose) skips the prefix sum: nothing it draws needs the heads, and
//    whoever asks for them (sorting, read-backs, the fragment count) gets them then.
//  - LinkedList: the paper's Alg. 1 (a global counter and per-pixel linked lists); when the pool
//    overflows it grows to the required size and the scene is re-rendered (Sec. 4.2).
// Measured on llvmpipe (`tlab bench render --fill`), CountScatter is the faster and the default.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/buffer/fragment_layout.hpp"
#include "renderer/gpu/gl_objects.hpp"
#include "renderer/gpu/shader_cache.hpp"
#include "renderer/frame/fill.hpp"
#include "renderer/frame/fragment_capture.hpp"
#include "renderer/frame/gpu_scene.hpp"
#include "renderer/frame/pass_timer.hpp"

namespace tlab::render {

enum class FillMethod { CountScatter, LinkedList };
FillMethod parseFillMethod(const std::string& name);  // "scatter" | "list"
std::string fillMethodName(FillMethod m);

class FragmentBuffer final : public Fill {
 public:
  // `initialCapacity` fragments are allocated up front (0: one per pixel); the pool grows as
  // needed up to `maxBytes` per fragment array (0: the GL limit for one shader storage block),
  // beyond which build() throws naming the sizes.
  FragmentBuffer(gpu::ShaderCache& shaders, int width, int height, FragmentLayout layout, FillMethod method,
                 std::size_t initialCapacity = 0, std::size_t maxBytes = 0);

  // Fill (rasterize all layers) and sort, unless the style's compositor sorts (setSortInCompose).
  // Timed as passes "fill" and "sort".
  void build(const GpuScene& scene, const RasterUniforms& uniforms, PassTimer& timer);
  void build(FrameContext& frame, PassTimer& timer) override;  // Fill: the frame's scene and camera
  // When on, build() leaves the lists unsorted for a compositor that sorts each list as it blends
  // (compose/blend.comp, TLAB_FUSED; FillSpec::sortsInCompose): no sorted buffer is written.
  void setSortInCompose(bool on) { sortInCompose_ = on; }
  bool sorted() const { return sorted_; }
  // Each list's (max |∂z/∂x|, max |∂z/∂y|) as two floats a pixel (the connect pass's maxStep),
  // written by this frame's sort when the records carry a depth gradient; null otherwise (no
  // gradient, or the lists not sorted yet). Pixels without fragments are left as they were.
  const gpu::Buffer* listSteps() const { return listStepsWritten_ ? &listSteps_ : nullptr; }
  // When on (FillSpec::colorPlane), the sort also writes each fragment's colour word alone, one
  // word a fragment in the sorted order, for a compositor that reads nothing else of the records
  // (issue #29: reading one word of each 8-word record cost smart's compose on the 16-layer stack
  // about 20 of its 24 ms). colorPlane() is that buffer once this frame's sort wrote it, null
  // otherwise (off, records without a colour, or not sorted yet). Where the compositor sorts
  // (setSortInCompose) and the sort runs as host code (setSortOnHost), build() writes the colour
  // plane alone, without the sorted records (sorted() stays false), for compose/host_blend.hpp.
  void setColorPlane(bool on) { colorPlane_ = on; }
  const gpu::Buffer* colorPlane() const { return colorPlaneWritten_ ? &colorPlaneBuffer_ : nullptr; }
  // The sort pass sorts lists up to 16 fragments in registers (on) or every list by insertion
  // in the order buffer (off): the same sorted buffer either way (tests compare the two).
  void setRegisterSort(bool on) { registerSort_ = on; }

  // Binds pixelCount, pixelHead and the sorted fragment records (and the colour plane, where this
  // frame's sort wrote one) for operator/compose passes, sorting them first when this frame's
  // build left them unsorted.
  void bindSorted();
  void bindSorted() const;  // the same where the lists are sorted; throws where they are not
  // Binds pixelCount, the unsorted records (binding FRAGS_UNSORTED) and the order buffer (ORDER)
  // for a compositor that sorts; true when the records sit in slots (record i of a pixel at
  // i * pixels + pixel, as buffer/fill_slots.frag stores them, and so does the order buffer its
  // keys), false when in the pixel's block (pixelHead bound, a key per fragment at the block).
  bool bindUnsorted() const;
  // Dispatches `program` with one invocation per pixel that holds a fragment, in pixel order
  // (frame/covered_pixels.glsl: binding BIND_COVERED and uniform uCovered; the prefix sum lists
  // them with the heads, so this frame's heads must be ready: after bindSorted, for instance).
  void dispatchCovered(const gpu::ShaderProgram& program) const;
  std::uint32_t coveredPixelCount() const;
  // The per-pixel counts and heads themselves (what bindSorted binds), e.g. for texture views.
  const gpu::Buffer& pixelCountBuffer() const { return pixelCount_; }
  const gpu::Buffer& pixelHeadBuffer() const { return pixelHead_; }
  const gpu::Buffer& sortedRecordBuffer() const;  // this frame's sorted records; throws where the lists are not sorted
  const gpu::Buffer& coveredPixelBuffer() const { return coveredPixels_; }  // coveredPixelCount() words (heads ready)
  // One RGBA32F texel per pixel for a compositor's output, kept across frames (a fresh buffer
  // each frame costs page faults whose price varies with the machine's load).
  const gpu::Buffer& composeOutput() const;

  int width() const { return width_; }
  int height() const { return height_; }
  std::size_t pixels() const { return std::size_t(width_) * height_; }
  const FragmentLayout& layout() const { return layout_; }
  FillMethod method() const { return method_; }
  std::uint64_t fragmentCount() const;  // the sum of the counts (summed here when the fill skipped the prefix sum)
  std::size_t capacity() const { return capacity_; }
  int rerenders() const { return rerenders_; }      // full re-renders after an overflow (LinkedList)
  int poolGrowths() const { return poolGrowths_; }  // times the pool was enlarged
  // Slots per pixel the last build stored its records in (0: it ran the scatter pass).
  std::uint32_t slotsUsed() const { return slotsUsed_; }
  // No list of the last build is longer than this (its slots, or the longest list the slot fill
  // saw overflow them); 0 where the build did not learn it (count pass alone, linked lists).
  std::uint32_t longestListBound() const { return longestListBound_; }

  // Read-backs, in GL pixel order (row 0 = bottom): per-pixel counts and heads (the exclusive
  // prefix sum of the counts, summed here when the fill skipped it), sorted records.
  std::vector<std::uint32_t> pixelCounts() const;
  std::vector<std::uint32_t> pixelHeads() const;
  std::vector<std::uint32_t> sortedRecords(std::size_t firstFragment, std::size_t count);  // sorts first if needed
  std::vector<std::uint32_t> coveredPixels() const;  // the list dispatchCovered runs over (heads ready)
  // The prefix sum as host code (on by default where the GL runs on the CPU) or as
  // buffer/prefix_sum.comp (off): the same heads, covered pixels and counts.
  void setPrefixSumOnHost(bool on) { prefixSumOnHost_ = on; }
  // The sort as host code over the mapped buffers (buffer/host_sort.hpp; on by default where the
  // GL runs on the CPU) or as buffer/sort.comp (off): the same sorted records, colour plane and
  // list steps. Linked lists are always sorted by the shader. Where the compositor sorts, on means
  // the colour plane sorted by host code, off the compositor's own sort (setColorPlane).
  void setSortOnHost(bool on) { sortOnHost_ = on; }
  bool sortsOnHost() const { return sortOnHost_; }

 private:
  void ensureCapacity(std::size_t fragments);
  void rasterize(const gpu::ShaderProgram& program, const GpuScene& scene, const RasterUniforms& u) const;
  // The fill whose fragment shader shades (buffer/fill_scatter, fill_slots or fill_list.frag), for
  // u's lighting model (withLighting; compiled on the first frame that model is drawn).
  const gpu::ShaderProgram& shadingFill(const char* fragmentShader, const RasterUniforms& u) const;
  std::uint32_t prefixSum();
  std::uint32_t prefixSumOnHost();  // the same heads, covered pixels and fragment count, summed by host code
  void sumHeads();     // this frame's prefix sum (heads, fragment count, covered pixels), once
  void ensureHeads();  // sumHeads and a pool that holds the frame's fragments
  // The compositor sorts, and its colours are sorted by host code instead (see setColorPlane).
  bool colorsSortedOnHost() const;
  void fillCountScatter(const GpuScene& scene, const RasterUniforms& u, PassTimer& timer);
  std::uint32_t slotsForThisFrame();
  void ensureSorted();  // the heads, then sortLists(), unless this frame's lists are sorted
  enum class SortSource { Block, Slots, ShortSlots };  // where the unsorted records sit (ShortSlots: at most 8)
  const gpu::ShaderProgram& sortProgram(SortSource source, bool colorPlane) const;
  void sortLists();
  void sortListsOnHost(bool records, bool steps, bool plane);
  void sortColorsOnHost();  // the heads, then the colour plane alone (see setColorPlane)
  void fillLinkedList(const GpuScene& scene, const RasterUniforms& u, PassTimer& timer);

  int width_, height_;
  FragmentLayout layout_;
  FillMethod method_;
  std::size_t capacity_ = 0;
  std::size_t maxBytes_;
  mutable std::uint64_t fragmentCount_ = 0;
  mutable bool fragmentCountKnown_ = false;
  bool headsReady_ = false;  // this frame's prefix sum ran: pixelHead_ and fragmentCount_ are set
  int rerenders_ = 0;
  int poolGrowths_ = 0;
  std::uint32_t slotsWanted_ = 8;  // the largest list seen so far (slots to try next frame)
  std::uint32_t slotsUsed_ = 0;
  std::uint32_t longestListBound_ = 0;  // see longestListBound()
  bool sortInCompose_ = false;
  bool sorted_ = false;  // this frame's lists are in fragsSorted_

  gpu::Framebuffer emptyFbo_;
  gpu::Buffer pixelCount_, pixelHead_, pixelCursor_, counters_, blockSums_;
  gpu::Buffer listNext_, fragsUnsorted_, fragsSorted_, order_, slots_;
  gpu::Buffer listSteps_;   // see listSteps()
  gpu::Buffer coveredPixels_;  // the pixels with a fragment, in pixel order (buffer/prefix_sum.comp)
  std::uint32_t coveredCount_ = 0;
  bool listStepsWritten_ = false;
  bool colorPlane_ = false;         // see setColorPlane()
  bool colorPlaneWritten_ = false;  // this frame's sort wrote colorPlaneBuffer_
  gpu::Buffer colorPlaneBuffer_;
  gpu::Buffer slotOrder_;  // a compositor's sort keys beside the slots (i * pixels + pixel)
  mutable gpu::Buffer composeOutput_;
  gpu::ShaderCache& shaders_;
  const gpu::ShaderProgram* countProgram_ = nullptr;
  const gpu::ShaderProgram* prefix_[3] = {nullptr, nullptr, nullptr};
  mutable const gpu::ShaderProgram* sortPrograms_[3][2] = {};  // by SortSource, without/with the colour plane
  bool registerSort_ = true;
  // Whether the prefix sum runs as host code over the mapped counts (where the GL runs on the CPU:
  // a loop over the pixels costs less than three dispatches of lanes looping over blocks) or as
  // buffer/prefix_sum.comp; the same words either way (tests compare).
  bool prefixSumOnHost_;
  std::vector<std::uint32_t> hostHeads_, hostCovered_;  // prefixSumOnHost's, kept between frames
  bool sortOnHost_;  // see setSortOnHost()
  std::size_t triangles_ = 0;  // of the last build's scene: the register sort's keys hold triangle * 16
};

}  // namespace tlab::render
