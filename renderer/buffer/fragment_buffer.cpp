#include "renderer/buffer/fragment_buffer.hpp"

#include <algorithm>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <utility>

#include "renderer/buffer/host_sort.hpp"
#include "renderer/gpu/gl_error.hpp"
#include "renderer/frame/frame_context.hpp"

namespace tlab::render {

namespace {

// Binding points of frame/fragment_layout.glsl.
enum Binding : GLuint {
  kPixelCount = 0, kPixelHead = 1, kPixelCursor = 2, kListNext = 3, kCounters = 4,
  kFragsUnsorted = 5, kFragsSorted = 6, kOrder = 7, kListSteps = 27, kCovered = 28, kColorPlane = 29,
};
constexpr std::uint32_t kPrefixBlock = 256;  // pixels per block in buffer/prefix_sum.comp
constexpr std::size_t kSlotBudgetBytes = std::size_t(256) << 20;  // at most this for per-pixel slots

gpu::ShaderDefines with(gpu::ShaderDefines d, const std::string& name, const std::string& value) {
  d.emplace_back(name, value);
  return d;
}

std::string humanBytes(double bytes) {
  std::ostringstream s;
  s.precision(1);
  if (bytes < 1024.0 * 1024.0) s << std::fixed << bytes / 1024.0 << " KiB";
  else s << std::fixed << bytes / (1024.0 * 1024.0) << " MiB";
  return s.str();
}

}  // namespace

FillMethod parseFillMethod(const std::string& name) {
  if (name == "scatter") return FillMethod::CountScatter;
  if (name == "list") return FillMethod::LinkedList;
  throw std::invalid_argument("unknown fill method '" + name + "' (known: scatter, list)");
}

std::string fillMethodName(FillMethod m) { return m == FillMethod::CountScatter ? "scatter" : "list"; }

FragmentBuffer::FragmentBuffer(gpu::ShaderCache& shaders, int width, int height, FragmentLayout layout,
                               FillMethod method, std::size_t initialCapacity, std::size_t maxBytes)
    : width_(width), height_(height), layout_(std::move(layout)), method_(method), maxBytes_(maxBytes), shaders_(shaders),
      prefixSumOnHost_(gpu::hostPassesWanted()), sortOnHost_(prefixSumOnHost_) {
  if (maxBytes_ == 0) {
    GLint64 limit = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &limit);
    maxBytes_ = static_cast<std::size_t>(limit);
  }
  if (width <= 0 || height <= 0) throw std::invalid_argument("image size must be positive");
  const std::size_t n = pixels();
  pixelCount_ = gpu::Buffer(n * 4);
  pixelHead_ = gpu::Buffer(n * 4);
  pixelCursor_ = gpu::Buffer(n * 4);
  counters_ = gpu::Buffer(16);
  blockSums_ = gpu::Buffer(((n + kPrefixBlock - 1) / kPrefixBlock) * 8);  // (fragments, covered pixels) a block
  coveredPixels_ = gpu::Buffer(n * 4);
  emptyFbo_ = gpu::makeFramebuffer();
  glNamedFramebufferParameteri(emptyFbo_.id(), GL_FRAMEBUFFER_DEFAULT_WIDTH, width);
  glNamedFramebufferParameteri(emptyFbo_.id(), GL_FRAMEBUFFER_DEFAULT_HEIGHT, height);

  const auto defines = layout_.defines();
  if (method_ == FillMethod::CountScatter) {
    countProgram_ = &shaders.graphics("buffer/scene_geometry.vert", "buffer/fill_count.frag", defines);
    sortProgram(SortSource::Slots, false);
    sortProgram(SortSource::ShortSlots, false);
  }
  sortProgram(SortSource::Block, false);
  for (int phase = 0; phase < 3; ++phase)
    prefix_[phase] = &shaders.compute("buffer/prefix_sum.comp", with(defines, "TLAB_PHASE", std::to_string(phase + 1)));
  ensureCapacity(initialCapacity == 0 ? n : initialCapacity);
  poolGrowths_ = 0;
}

void FragmentBuffer::ensureCapacity(std::size_t fragments) {
  if (fragments <= capacity_) return;
  const std::size_t recordBytes = std::size_t(layout_.stride) * 4;
  const double need = double(fragments) * double(recordBytes);
  if (need > double(maxBytes_)) {
    std::ostringstream msg;
    msg << "the illustration buffer needs " << fragments << " fragments x " << recordBytes << " bytes = "
        << humanBytes(need) << " per fragment array, more than the allowed " << humanBytes(double(maxBytes_))
        << ": use a lower resolution";
    throw gpu::GlError(msg.str());
  }
  if (capacity_ > 0) ++poolGrowths_;
  capacity_ = fragments;
  fragsUnsorted_ = gpu::Buffer(capacity_ * recordBytes);
  fragsSorted_ = gpu::Buffer(capacity_ * recordBytes);
  order_ = gpu::Buffer(capacity_ * 8);  // (depth bits, source) per fragment
  if (method_ == FillMethod::LinkedList) listNext_ = gpu::Buffer(capacity_ * 4);
}

void FragmentBuffer::rasterize(const gpu::ShaderProgram& program, const GpuScene& scene, const RasterUniforms& u) const {
  beginFragmentCapture(emptyFbo_, width_, height_, program, u);
  glUniform1ui(program.uniform("uCapacity"), static_cast<GLuint>(capacity_));
  glUniform1ui(program.uniform("uSlots"), slotsUsed_);
  glUniform1ui(program.uniform("uPixels"), static_cast<GLuint>(pixels()));
  endFragmentCapture(scene, program);
}

const gpu::ShaderProgram& FragmentBuffer::shadingFill(const char* fragmentShader, const RasterUniforms& u) const {
  return shaders_.graphics("buffer/scene_geometry.vert", fragmentShader, withLighting(layout_.defines(), u.lighting));
}

std::uint32_t FragmentBuffer::prefixSum() {
  if (prefixSumOnHost_) return prefixSumOnHost();
  const auto n = static_cast<GLuint>(pixels());
  const GLuint blocks = (n + kPrefixBlock - 1) / kPrefixBlock;
  pixelCount_.bindBase(GL_SHADER_STORAGE_BUFFER, kPixelCount);
  pixelHead_.bindBase(GL_SHADER_STORAGE_BUFFER, kPixelHead);
  blockSums_.bindBase(GL_SHADER_STORAGE_BUFFER, kListNext);
  counters_.bindBase(GL_SHADER_STORAGE_BUFFER, kCounters);
  coveredPixels_.bindBase(GL_SHADER_STORAGE_BUFFER, kCovered);
  for (int phase = 0; phase < 3; ++phase) {
    const gpu::ShaderProgram& p = *prefix_[phase];
    p.use();
    glUniform1ui(p.uniform("uPixels"), n);
    glUniform1ui(p.uniform("uBlocks"), blocks);
    gpu::dispatchLinear(phase == 1 ? 1 : blocks);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  }
  std::uint32_t counters[4] = {0, 0, 0, 0};
  counters_.download(counters, sizeof(counters));
  coveredCount_ = counters[3];
  return counters[1];
}

// buffer/prefix_sum.comp's scan in one loop: each pixel's head is the sum of the counts before it,
// and the covered pixels are listed in pixel order. Counts are summed as 32-bit words, as there.
// (The shader also leaves the total and the covered count in the counters, for the host to read
// back; here the host has them already, and no pass reads those words.)
std::uint32_t FragmentBuffer::prefixSumOnHost() {
  const std::size_t n = pixels();
  hostHeads_.resize(n);
  hostCovered_.resize(n);
  std::uint32_t total = 0, covered = 0;
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);  // the fill's counts, for the host
  {
    const gpu::MappedRead counts(pixelCount_, n * 4);
    const std::uint32_t* count = counts.as<std::uint32_t>();
    for (std::size_t p = 0; p < n; ++p) {
      hostHeads_[p] = total;
      if (count[p] > 0u) hostCovered_[covered++] = std::uint32_t(p);
      total += count[p];
    }
  }
  pixelHead_.upload(hostHeads_.data(), n * 4);
  coveredPixels_.upload(hostCovered_.data(), std::size_t(covered) * 4);
  coveredCount_ = covered;
  return total;
}

void FragmentBuffer::sumHeads() {
  if (headsReady_) return;
  fragmentCount_ = prefixSum();
  fragmentCountKnown_ = true;
  headsReady_ = true;
}

void FragmentBuffer::ensureHeads() {
  sumHeads();
  ensureCapacity(fragmentCount_);
}

bool FragmentBuffer::colorsSortedOnHost() const {
  return sortInCompose_ && sortOnHost_ && method_ == FillMethod::CountScatter && layout_.properties.has(FragmentProperty::Color);
}

// Slots per pixel for this frame's count pass: as many as the largest list seen so far, when
// that many fit the memory budget for every pixel; else 0 (count, then scatter).
// A compositor that sorts keeps its keys beside the slots, within the same budget.
std::uint32_t FragmentBuffer::slotsForThisFrame() {
  const std::size_t bytes = pixels() * slotsWanted_ * std::size_t(layout_.stride) * 4;
  const std::size_t orderBytes = sortInCompose_ && !colorsSortedOnHost() ? pixels() * slotsWanted_ * 8 : 0;
  if (slotsWanted_ == 0 || std::max(bytes, orderBytes) > maxBytes_ || bytes + orderBytes > kSlotBudgetBytes) return 0;
  if (slots_.size() < bytes) slots_ = gpu::Buffer(bytes);
  if (slotOrder_.size() < orderBytes) slotOrder_ = gpu::Buffer(orderBytes);
  return slotsWanted_;
}

void FragmentBuffer::fillCountScatter(const GpuScene& scene, const RasterUniforms& u, PassTimer& timer) {
  timer.time("fill", [&] {
    pixelCount_.clearToZero();
    counters_.clearToZero();
    slotsUsed_ = slotsForThisFrame();
    pixelCount_.bindBase(GL_SHADER_STORAGE_BUFFER, kPixelCount);
    const bool intoSlots = slotsUsed_ > 0;
    if (intoSlots) {
      counters_.bindBase(GL_SHADER_STORAGE_BUFFER, kCounters);
      slots_.bindBase(GL_SHADER_STORAGE_BUFFER, kFragsUnsorted);
    }
    const auto& program = intoSlots ? shadingFill("buffer/fill_slots.frag", u) : *countProgram_;
    timer.part(intoSlots ? "fill rasterization into slots" : "fill count rasterization",
               [&] { rasterize(program, scene, u); });
    if (intoSlots) {
      std::uint32_t counters[3] = {0, 0, 0};
      counters_.download(counters, sizeof(counters));
      const std::uint32_t overflowMax = counters[2];  // the largest list beyond the slots (0: none)
      if (overflowMax == 0) {
        longestListBound_ = slotsUsed_;
        // The sort pass writes each list at its head.
        if (!sortInCompose_) timer.part("fill prefix sum", [&] { ensureHeads(); });
        return;
      }
      longestListBound_ = overflowMax;  // the longest list, past the slots
      slotsWanted_ = overflowMax;  // some list outgrew the slots: scatter this frame, more slots next
      slotsUsed_ = 0;
    }
    timer.part("fill prefix sum", [&] { ensureHeads(); });
    pixelCursor_.clearToZero();
    pixelHead_.bindBase(GL_SHADER_STORAGE_BUFFER, kPixelHead);
    pixelCursor_.bindBase(GL_SHADER_STORAGE_BUFFER, kPixelCursor);
    fragsUnsorted_.bindBase(GL_SHADER_STORAGE_BUFFER, kFragsUnsorted);
    timer.part("fill scatter rasterization", [&] { rasterize(shadingFill("buffer/fill_scatter.frag", u), scene, u); });
  });
}

void FragmentBuffer::fillLinkedList(const GpuScene& scene, const RasterUniforms& u, PassTimer& timer) {
  timer.time("fill", [&] {
    for (;;) {
      pixelCount_.clearToZero();
      counters_.clearToZero();
      pixelCount_.bindBase(GL_SHADER_STORAGE_BUFFER, kPixelCount);
      pixelCursor_.bindBase(GL_SHADER_STORAGE_BUFFER, kPixelCursor);
      listNext_.bindBase(GL_SHADER_STORAGE_BUFFER, kListNext);
      counters_.bindBase(GL_SHADER_STORAGE_BUFFER, kCounters);
      fragsUnsorted_.bindBase(GL_SHADER_STORAGE_BUFFER, kFragsUnsorted);
      rasterize(shadingFill("buffer/fill_list.frag", u), scene, u);
      std::uint32_t written = 0;
      counters_.download(&written, 4);
      if (written <= capacity_) break;
      ensureCapacity(written);  // Sec. 4.2: resize to the required size and repeat the rendering
      ++rerenders_;
    }
    ensureHeads();
  });
}

void FragmentBuffer::build(FrameContext& frame, PassTimer& timer) { build(frame.gpuScene, frame.raster, timer); }

void FragmentBuffer::build(const GpuScene& scene, const RasterUniforms& uniforms, PassTimer& timer) {
  rerenders_ = 0;
  poolGrowths_ = 0;
  slotsUsed_ = 0;
  longestListBound_ = 0;
  sorted_ = false;
  listStepsWritten_ = false;
  colorPlaneWritten_ = false;
  headsReady_ = false;
  fragmentCountKnown_ = false;
  triangles_ = scene.triangleCount();
  if (method_ == FillMethod::CountScatter) fillCountScatter(scene, uniforms, timer);
  else fillLinkedList(scene, uniforms, timer);
  if (!sortInCompose_ || method_ == FillMethod::LinkedList) timer.time("sort", [&] { ensureSorted(); });
  else if (colorsSortedOnHost()) timer.time("sort", [&] { sortColorsOnHost(); });
  gpu::checkGl("building the illustration buffer");
}

// buffer/sort.comp for where the unsorted records sit (a block, a linked list or slots) and
// whether it writes the colour plane; compiled on first use, then kept.
const gpu::ShaderProgram& FragmentBuffer::sortProgram(SortSource source, bool colorPlane) const {
  const gpu::ShaderProgram*& kept = sortPrograms_[int(source)][colorPlane ? 1 : 0];
  if (kept) return *kept;
  gpu::ShaderDefines defines = layout_.defines();
  if (method_ == FillMethod::LinkedList) defines = with(defines, "TLAB_LINKED_LIST", "1");
  if (source != SortSource::Block) defines = with(defines, "TLAB_SLOTS", "1");
  if (source == SortSource::ShortSlots) defines = with(defines, "TLAB_REGISTER_SORT", "8");
  if (colorPlane) defines = with(defines, "TLAB_COLOR_PLANE", "1");
  kept = &shaders_.compute("buffer/sort.comp", defines);
  return *kept;
}

void FragmentBuffer::ensureSorted() {
  if (sorted_) return;
  ensureHeads();
  sortLists();
}

void FragmentBuffer::sortLists() {
  const bool steps = layout_.properties.has(FragmentProperty::DepthGradient);
  if (steps && listSteps_.size() < pixels() * 8) listSteps_ = gpu::Buffer(pixels() * 8);
  const bool plane = colorPlane_ && layout_.properties.has(FragmentProperty::Color);
  if (plane && colorPlaneBuffer_.size() < capacity_ * 4) colorPlaneBuffer_ = gpu::Buffer(capacity_ * 4);
  if (sortOnHost_ && method_ != FillMethod::LinkedList) {
    sortListsOnHost(true, steps, plane);
    return;
  }
  pixelCount_.bindBase(GL_SHADER_STORAGE_BUFFER, kPixelCount);
  pixelHead_.bindBase(GL_SHADER_STORAGE_BUFFER, kPixelHead);
  pixelCursor_.bindBase(GL_SHADER_STORAGE_BUFFER, kPixelCursor);
  if (listNext_) listNext_.bindBase(GL_SHADER_STORAGE_BUFFER, kListNext);
  (slotsUsed_ > 0 ? slots_ : fragsUnsorted_).bindBase(GL_SHADER_STORAGE_BUFFER, kFragsUnsorted);
  fragsSorted_.bindBase(GL_SHADER_STORAGE_BUFFER, kFragsSorted);
  order_.bindBase(GL_SHADER_STORAGE_BUFFER, kOrder);
  if (steps) listSteps_.bindBase(GL_SHADER_STORAGE_BUFFER, kListSteps);
  if (plane) colorPlaneBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, kColorPlane);
  // Lists in at most 8 slots all fit the sort's 8-register network (buffer/sort.comp).
  const bool shortLists = slotsUsed_ > 0 && slotsUsed_ <= 8;
  const SortSource source = shortLists ? SortSource::ShortSlots : slotsUsed_ > 0 ? SortSource::Slots : SortSource::Block;
  const gpu::ShaderProgram& program = sortProgram(source, plane);
  program.use();
  glUniform1ui(program.uniform("uPixels"), static_cast<GLuint>(pixels()));
  // The register sort's key holds triangle * 16 + position in one word (buffer/sort.comp).
  const bool registers = registerSort_ && triangles_ <= (std::size_t{1} << 28);
  glUniform1ui(program.uniform("uRegisterSortMax"), registers ? (shortLists ? 8u : 16u) : 0u);
  dispatchCovered(program);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  sorted_ = true;
  listStepsWritten_ = steps;
  colorPlaneWritten_ = plane;
}

// buffer/sort.comp's words, written by host code into the mapped buffers (buffer/host_sort.hpp):
// the sorted records (`records`; otherwise they are left as they were), the list steps and the
// colour plane, as asked.
void FragmentBuffer::sortListsOnHost(bool records, bool steps, bool plane) {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);  // the fill's records and counts, for the host
  const std::size_t n = pixels(), fragments = fragmentCount_, stride = layout_.stride;
  const gpu::Buffer& unsorted = slotsUsed_ > 0 ? slots_ : fragsUnsorted_;
  const std::size_t unsortedWords = slotsUsed_ > 0 ? std::size_t(slotsUsed_) * n * stride : fragments * stride;
  {
    const gpu::MappedRead unsortedRecords(unsorted, unsortedWords * 4), counts(pixelCount_, n * 4), heads(pixelHead_, n * 4),
        covered(coveredPixels_, std::size_t(coveredCount_) * 4);
    const gpu::MappedWrite sorted(fragsSorted_, records ? fragments * stride * 4 : 0),
        colors(colorPlaneBuffer_, plane ? fragments * 4 : 0), listSteps(listSteps_, steps ? n * 8 : 0);
    const UnsortedLists in{unsortedRecords.as<std::uint32_t>(), layout_.stride, slotsUsed_ > 0 ? n : 0, counts.as<std::uint32_t>(),
                           heads.as<std::uint32_t>(), covered.as<std::uint32_t>(), coveredCount_};
    const SortedLists out{sorted.as<std::uint32_t>(), colors.as<std::uint32_t>(), layout_.colorOffset,
                          listSteps.as<float>(), layout_.depthGradientOffset};
    render::sortListsOnHost(in, out, std::thread::hardware_concurrency());
  }
  sorted_ = records;
  listStepsWritten_ = steps;
  colorPlaneWritten_ = plane;
}

// Where the compositor sorts and the GL runs on the CPU: the colour words alone, in each list's
// sorted order, which compose/host_blend.hpp blends. On llvmpipe the two took a third of the time
// of the compose pass sorting its lists in lanes (issue #29, twenty-eighth round).
// The heads alone: records in slots need no pool (a reader that wants them sorted gets one then).
void FragmentBuffer::sortColorsOnHost() {
  sumHeads();
  if (colorPlaneBuffer_.size() < fragmentCount_ * 4) colorPlaneBuffer_ = gpu::Buffer(fragmentCount_ * 4);
  sortListsOnHost(false, false, true);
}

void FragmentBuffer::bindSorted() {
  ensureSorted();
  std::as_const(*this).bindSorted();
}

void FragmentBuffer::bindSorted() const {
  if (!sorted_) throw std::logic_error("a pass bound the sorted lists of a frame whose sort was left to the compose pass");
  pixelCount_.bindBase(GL_SHADER_STORAGE_BUFFER, kPixelCount);
  pixelHead_.bindBase(GL_SHADER_STORAGE_BUFFER, kPixelHead);
  fragsSorted_.bindBase(GL_SHADER_STORAGE_BUFFER, kFragsSorted);
  if (colorPlaneWritten_) colorPlaneBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, kColorPlane);
}

const gpu::Buffer& FragmentBuffer::sortedRecordBuffer() const {
  if (!sorted_) throw std::logic_error("a pass read the sorted records of a frame whose sort was left to the compose pass");
  return fragsSorted_;
}

bool FragmentBuffer::bindUnsorted() const {
  pixelCount_.bindBase(GL_SHADER_STORAGE_BUFFER, kPixelCount);
  if (slotsUsed_ > 0) {
    slots_.bindBase(GL_SHADER_STORAGE_BUFFER, kFragsUnsorted);
    slotOrder_.bindBase(GL_SHADER_STORAGE_BUFFER, kOrder);
    return true;
  }
  pixelHead_.bindBase(GL_SHADER_STORAGE_BUFFER, kPixelHead);
  fragsUnsorted_.bindBase(GL_SHADER_STORAGE_BUFFER, kFragsUnsorted);
  order_.bindBase(GL_SHADER_STORAGE_BUFFER, kOrder);
  return false;
}

std::uint32_t FragmentBuffer::coveredPixelCount() const {
  if (!headsReady_) throw std::logic_error("the covered pixels of a frame are listed with its heads (ensureHeads)");
  return coveredCount_;
}

void FragmentBuffer::dispatchCovered(const gpu::ShaderProgram& program) const {
  const std::uint32_t n = coveredPixelCount();
  coveredPixels_.bindBase(GL_SHADER_STORAGE_BUFFER, kCovered);
  program.use();
  glUniform1ui(program.uniform("uCovered"), n);
  gpu::dispatchLinear(n);
}

const gpu::Buffer& FragmentBuffer::composeOutput() const {
  if (!composeOutput_) composeOutput_ = gpu::Buffer(pixels() * sizeof(glm::vec4));
  return composeOutput_;
}

std::vector<std::uint32_t> FragmentBuffer::pixelCounts() const {
  std::vector<std::uint32_t> v(pixels());
  pixelCount_.download(v.data(), v.size() * 4);
  return v;
}

std::uint64_t FragmentBuffer::fragmentCount() const {
  if (!fragmentCountKnown_) {
    const auto counts = pixelCounts();
    fragmentCount_ = std::accumulate(counts.begin(), counts.end(), std::uint64_t(0));
    fragmentCountKnown_ = true;
  }
  return fragmentCount_;
}

std::vector<std::uint32_t> FragmentBuffer::pixelHeads() const {
  std::vector<std::uint32_t> v(pixels());
  if (headsReady_) {
    pixelHead_.download(v.data(), v.size() * 4);
  } else {  // buffer/prefix_sum.comp's exclusive prefix sum, here
    const auto counts = pixelCounts();
    std::exclusive_scan(counts.begin(), counts.end(), v.begin(), std::uint32_t(0));
  }
  return v;
}

std::vector<std::uint32_t> FragmentBuffer::coveredPixels() const {
  std::vector<std::uint32_t> v(coveredPixelCount());
  if (!v.empty()) coveredPixels_.download(v.data(), v.size() * 4);
  return v;
}

std::vector<std::uint32_t> FragmentBuffer::sortedRecords(std::size_t first, std::size_t count) {
  ensureSorted();
  std::vector<std::uint32_t> v(count * layout_.stride);
  fragsSorted_.download(v.data(), v.size() * 4, first * layout_.stride * 4);
  return v;
}

}  // namespace tlab::render
