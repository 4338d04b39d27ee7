#include "renderer/ops/connect_pass.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <stdexcept>
#include <thread>
#include <vector>

#include "renderer/buffer/fragment_layout.hpp"
#include "renderer/gpu/gl_error.hpp"
#include "renderer/ops/boundary_conditions.hpp"
#include "renderer/ops/fast_links.hpp"

namespace tlab::render {

namespace {
// A listed field's initial values: 0, then 1 at each of its seeds (ops/set_listed.comp).
void writeSeeds(gpu::ShaderCache& shaders, TransparencyFields& fields, Field field) {
  constexpr GLuint kValue = 14, kList = 23;  // BIND_BETA_OUT, BIND_FRONTIER_IN of ops/field_bindings.glsl
  fields.setUniform(field, 0.0f);
  const gpu::Buffer& values = fields.current(field);  // cleared to 0
  values.bindBase(GL_SHADER_STORAGE_BUFFER, kValue);
  const gpu::Buffer& seeds = fields.frontier(field);
  seeds.bindBase(GL_SHADER_STORAGE_BUFFER, kList);
  const auto& program = shaders.compute("ops/set_listed.comp");
  program.use();
  glUniform1f(program.uniform("uValue"), 1.0f);
  TransparencyFields::dispatchOnList(program, seeds);
}

constexpr Field kSeeded[2] = {Field::Beta, Field::Gamma};

// What phase 2 (ops/connect.comp) writes, as host code: per seeded field, its seeds as a list
// (Eq. 9's spreading), or its values in its output copy; the flags, and the links from their pair
// bits (where phase 1 kept them so).
struct Phase2Outputs {
  bool listed[2] = {false, false}, valued[2] = {false, false};
  Phase2Outputs(const TransparencyFields& fields, bool listSeeds) {
    for (int i = 0; i < 2; ++i) {
      listed[i] = listSeeds && fields.has(kSeeded[i]);
      valued[i] = !listSeeds && fields.has(kSeeded[i]);
    }
  }
  // The buffers mapped (the links readable: phase 2 reads them), and the conditions over them
  // appending seeds to `seeds`.
  struct Mapped {
    Mapped(const Phase2Outputs& outputs, const FragmentBuffer& buffer, TransparencyFields& fields, bool linkMasks)
        : links(fields.links(), fields.fragments() * sizeof(glm::uvec4), 0, true), flags(fields.flags(), fields.fragments() * 4) {
      if (linkMasks) pairs.emplace(fields.connectPairs(buffer.pixels()), buffer.pixels() * sizeof(glm::uvec4));
      for (int i = 0; i < 2; ++i)
        if (outputs.valued[i]) values[i].emplace(fields.output(kSeeded[i]), fields.fragments() * 4);
    }
    gpu::MappedWrite links, flags;
    std::optional<gpu::MappedRead> pairs;
    std::optional<gpu::MappedWrite> values[2];
    BoundaryConditions conditions(std::vector<std::uint32_t> (&seeds)[2], const bool (&listed)[2]) const {
      return {links.as<glm::uvec4>(),
              pairs ? pairs->as<glm::uvec4>() : nullptr,
              flags.as<std::uint32_t>(),
              values[0] ? values[0]->as<float>() : nullptr,
              values[1] ? values[1]->as<float>() : nullptr,
              listed[0] ? &seeds[0] : nullptr,
              listed[1] ? &seeds[1] : nullptr};
    }
  };
};

// Phase 1 as host code with phase 2 folded in leaves phase 2 the pixels it deferred, and its seeds.
struct FoldedPhase2 {
  std::vector<std::uint32_t> deferred;
  std::vector<std::uint32_t> seeds[2];  // β's, γ's (pixel and layer order)
};

// Phase 2 (ops/connect.comp) as host code over the mapped buffers (ops/boundary_conditions.hpp):
// over every covered pixel, or where phase 1 folded it in (`folded`), over the pixels it deferred,
// their seeds merged with the folded ones (both in pixel and layer order: ascending).
void setBoundaryConditions(const FragmentBuffer& buffer, TransparencyFields& fields, bool linkMasks, bool listSeeds,
                           FoldedPhase2* folded) {
  const std::size_t pixels = buffer.pixels();
  const Phase2Outputs outputs(fields, listSeeds);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);  // phases 1 and 3's words, for the host
  std::vector<std::uint32_t> seeds[2];  // β's, γ's
  if (!folded || !folded->deferred.empty()) {
    const gpu::MappedRead counts(buffer.pixelCountBuffer(), pixels * 4), heads(buffer.pixelHeadBuffer(), pixels * 4);
    std::optional<gpu::MappedRead> covered;
    if (!folded) covered.emplace(buffer.coveredPixelBuffer(), std::size_t(buffer.coveredPixelCount()) * 4);
    const Phase2Outputs::Mapped mapped(outputs, buffer, fields, linkMasks);
    const CoveredGrid grid{buffer.width(),
                           buffer.height(),
                           counts.as<std::uint32_t>(),
                           heads.as<std::uint32_t>(),
                           folded ? folded->deferred.data() : covered->as<std::uint32_t>(),
                           folded ? folded->deferred.size() : std::size_t(buffer.coveredPixelCount())};
    setBoundaryConditionsOnHost(grid, mapped.conditions(seeds, outputs.listed), std::thread::hardware_concurrency());
  }
  for (int i = 0; i < 2; ++i) {
    if (!outputs.listed[i]) continue;
    if (folded) {
      std::vector<std::uint32_t> all(seeds[i].size() + folded->seeds[i].size());
      std::merge(seeds[i].begin(), seeds[i].end(), folded->seeds[i].begin(), folded->seeds[i].end(), all.begin());
      seeds[i] = std::move(all);
    }
    TransparencyFields::writeList(fields.frontier(kSeeded[i]), seeds[i]);
  }
}

// Phase 1 (ops/connect.comp) as host code over the mapped buffers (ops/fast_links.hpp): the links
// the fast path settles (as words, or as pair bits where `linkMasks`), and the work buffer's count,
// `partial` word and listed pairs for phase 3. Returns the header (count, partial).
std::array<std::uint32_t, 2> settleFastLinks(const FragmentBuffer& buffer, const SmartSettings& settings, float objectRadius,
                                             TransparencyFields& fields, bool linkMasks, bool listSeeds, FoldedPhase2* fold) {
  const std::size_t pixels = buffer.pixels(), n = buffer.fragmentCount();
  if (n == 0) return {0, 0};  // (the work buffer's header is cleared)
  const FragmentLayout& layout = buffer.layout();
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);  // the sort's words, for the host
  FastLinks out;
  {
    const gpu::MappedRead counts(buffer.pixelCountBuffer(), pixels * 4), heads(buffer.pixelHeadBuffer(), pixels * 4),
        records(buffer.sortedRecordBuffer(), n * layout.stride * 4), steps(*buffer.listSteps(), pixels * sizeof(glm::vec2));
    const Phase2Outputs outputs(fields, listSeeds);
    std::optional<gpu::MappedWrite> links, pairs;
    std::optional<Phase2Outputs::Mapped> mapped;  // phase 2's buffers, where it is folded in (links as words)
    if (fold) {
      mapped.emplace(outputs, buffer, fields, false);
      out.conditions = mapped->conditions(fold->seeds, outputs.listed);
    } else {
      links.emplace(fields.links(), n * sizeof(glm::uvec4));
    }
    if (linkMasks) pairs.emplace(fields.connectPairs(pixels), pixels * sizeof(glm::uvec4));
    const CoveredGrid grid{buffer.width(), buffer.height(), counts.as<std::uint32_t>(), heads.as<std::uint32_t>(), nullptr, 0};
    const bool ids = layout.properties.has(FragmentProperty::Ids);
    const SortedSurfels surfels{records.as<std::uint32_t>(), layout.stride, layout.depthGradientOffset, layout.normalOffset,
                                ids, layout.idsOffset, steps.as<glm::vec2>()};
    // The shader's uniforms, computed as connectFragments sets them.
    const ContinuityWeights weights{objectRadius, float(settings.wz), float(settings.wz / objectRadius), float(settings.wn)};
    out.links = fold ? mapped->links.as<glm::uvec4>() : links->as<glm::uvec4>();
    out.pairs = pairs ? pairs->as<glm::uvec4>() : nullptr;
    settleFastLinksOnHost(grid, surfels, weights, out, fields.fastLinkRows(), std::thread::hardware_concurrency());
  }
  if (fold) fold->deferred = std::move(out.deferred);
  const std::array<std::uint32_t, 2> header{std::uint32_t(out.listed.size()), out.partial ? 1u : 0u};
  const gpu::MappedWrite work(fields.connectWork(pixels), (2 + out.listed.size()) * 4);
  std::copy(header.begin(), header.end(), work.as<std::uint32_t>());
  std::copy(out.listed.begin(), out.listed.end(), work.as<std::uint32_t>() + 2);
  return header;
}

}  // namespace

std::unique_ptr<TransparencyFields> connectFragments(const FragmentBuffer& buffer, gpu::ShaderCache& shaders,
                                                     const SmartSettings& settings, float objectRadius,
                                                     NeighborSearch search) {
  auto fields = std::make_unique<TransparencyFields>();
  connectFragments(buffer, shaders, settings, objectRadius, *fields, search);
  return fields;
}

std::size_t connectFragments(const FragmentBuffer& buffer, gpu::ShaderCache& shaders, const SmartSettings& settings,
                             float objectRadius, TransparencyFields& fields, NeighborSearch search, ConnectOutput output,
                             PassTimer* timer) {
  constexpr GLuint kConnectWork = 22;   // BIND_CONNECT_WORK of ops/field_bindings.glsl
  constexpr GLuint kConnectPairs = 25;  // BIND_CONNECT_PAIRS
  constexpr GLuint kListSteps = 27;     // BIND_LIST_STEPS of frame/fragment_layout.glsl
  constexpr GLuint kFragsSorted = 6;   // BIND_FRAGS_SORTED of frame/fragment_layout.glsl
  constexpr GLuint kSortedWordsUnit = 0;
  constexpr GLuint kSeedsBeta = 23, kSeedsGamma = 24;  // BIND_SEEDS_BETA/GAMMA
  constexpr std::uint32_t kAllFree = 7;                 // FREE_ALPHA | FREE_BETA | FREE_GAMMA
  fields.resize(buffer.fragmentCount(), settings.silhouettes, settings.halos);
  const FragmentLayout& layout = buffer.layout();
  gpu::ShaderDefines defines = gpu::joined(layout.defines(), fields.defines());
  if (search == NeighborSearch::AllPairs) defines.emplace_back("TLAB_ALL_PAIRS", "1");
  GLint maxTexels = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
  // The fast path's links as bits of each pixel's pairs, where a pair's 32 bits hold every layer
  // (phase 2 reads them as one RGBA32UI texel a pixel, on unit 6).
  constexpr GLuint kPairTexelsUnit = 6;
  constexpr std::uint32_t kShortestForBits = 9, kLongestForBits = 32;
  const std::uint32_t longest = buffer.longestListBound();
  const bool linkMasks = (search == NeighborSearch::BoundedBits ||
                          (search == NeighborSearch::Bounded && longest >= kShortestForBits)) &&
                         longest > 0 && longest <= kLongestForBits && double(buffer.pixels()) <= double(maxTexels);
  gpu::Texture pairTexels;
  if (linkMasks) {
    defines.emplace_back("TLAB_LINK_MASKS", "1");
    const gpu::Buffer& pairs = fields.connectPairs(buffer.pixels());
    pairs.bindBase(GL_SHADER_STORAGE_BUFFER, kConnectPairs);
    pairTexels = gpu::bindBufferTexture(pairs.id(), GL_RGBA32UI, buffer.pixels() * 16, kPairTexelsUnit);
  }
  const bool bounded = search != NeighborSearch::AllPairs;
  gpu::Buffer& work = fields.connectWork(buffer.pixels());
  work.fillWords(0, 2);  // count, partial
  work.bindBase(GL_SHADER_STORAGE_BUFFER, kConnectWork);
  buffer.bindSorted();
  // Each list's maxStep, written by the sort pass (it reads every record anyway).
  const gpu::Buffer* steps = buffer.listSteps();
  if (!steps) throw std::logic_error("the connect pass needs fragment records with a depth gradient");
  steps->bindBase(GL_SHADER_STORAGE_BUFFER, kListSteps);
  fields.bindCurrent();
  // Where the GL can show the sorted records (as bindSorted bound them) as a buffer texture of
  // that many words, the pass reads them so (TLAB_SORTED_TEXELS); else as a storage buffer.
  GLint sortedId = 0;
  glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, kFragsSorted, &sortedId);
  gpu::Texture sortedWords, sortedQuads;
  constexpr GLuint kSortedQuadsUnit = 2;
  if (bounded && sortedId != 0 && buffer.fragmentCount() > 0 &&
      double(buffer.fragmentCount()) * layout.stride <= double(maxTexels)) {
    const std::size_t bytes = buffer.fragmentCount() * layout.stride * 4;
    sortedWords = gpu::bindBufferTexture(GLuint(sortedId), GL_R32UI, bytes, kSortedWordsUnit);
    defines.emplace_back("TLAB_SORTED_TEXELS", "1");
    if (layout.quads > 0) {  // the same words as RGBA32UI texels: a record's surfel in a texel per quad
      sortedQuads = gpu::bindBufferTexture(GLuint(sortedId), GL_RGBA32UI, bytes, kSortedQuadsUnit);
      defines.emplace_back("TLAB_SORTED_QUADS", "1");
    }
  } else if (layout.stride % 2 == 0 && layout.depthGradientOffset % 2 == 0) {
    defines.emplace_back("TLAB_GRADIENT_PAIR", "1");  // the storage buffer's gradient in one load
  }
  // Eq. 9 spreads only from fragments above 0: phase 2 lists them for the solve's frontier.
  const bool listSeeds = settings.spreadByMax && (fields.hasBeta() || fields.hasGamma());
  if (listSeeds)
    for (Field f : {Field::Beta, Field::Gamma})
      if (fields.has(f)) {
        TransparencyFields::clearList(fields.frontier(f));
        fields.frontier(f).bindBase(GL_SHADER_STORAGE_BUFFER, f == Field::Beta ? kSeedsBeta : kSeedsGamma);
      }
  // Phases 1 and 2 read the per-pixel counts, heads and maxSteps as buffer textures
  // (TLAB_PIXEL_TEXELS), where the GL allows that many texels.
  constexpr GLuint kPixelCountsUnit = 3, kPixelHeadsUnit = 4, kListStepsUnit = 5;
  gpu::Texture pixelCounts, pixelHeads, stepTexels;
  const bool pixelTexels = bounded && double(buffer.pixels()) <= double(maxTexels);
  if (pixelTexels) {
    pixelCounts = gpu::bindBufferTexture(buffer.pixelCountBuffer().id(), GL_R32UI, buffer.pixels() * 4, kPixelCountsUnit);
    pixelHeads = gpu::bindBufferTexture(buffer.pixelHeadBuffer().id(), GL_R32UI, buffer.pixels() * 4, kPixelHeadsUnit);
    stepTexels = gpu::bindBufferTexture(steps->id(), GL_RG32F, buffer.pixels() * 8, kListStepsUnit);
  }
  // Phase 2 reads the links as a buffer texture of one RGBA32UI texel per fragment (TLAB_LINK_TEXELS).
  constexpr GLuint kLinkTexelsUnit = 1;
  gpu::Texture linkTexels;
  if (bounded && !linkMasks && buffer.fragmentCount() > 0 && double(buffer.fragmentCount()) <= double(maxTexels)) {
    linkTexels = gpu::bindBufferTexture(fields.links().id(), GL_RGBA32UI, buffer.fragmentCount() * 16, kLinkTexelsUnit);
  }
  const auto run = [&](const char* phase, std::size_t items = 0) {
    gpu::ShaderDefines phaseDefines = defines;
    phaseDefines.emplace_back("TLAB_PHASE", phase);
    if (listSeeds && phase[0] == '2') phaseDefines.emplace_back("TLAB_LIST_SEEDS", "1");
    if (settings.adaptiveAlpha && phase[0] == '2') phaseDefines.emplace_back("TLAB_ADAPTIVE_ALPHA", "1");
    if (linkTexels && phase[0] == '2') phaseDefines.emplace_back("TLAB_LINK_TEXELS", "1");
    if (pixelTexels && phase[0] != '3') phaseDefines.emplace_back("TLAB_PIXEL_TEXELS", "1");
    const auto& program = shaders.compute("ops/connect.comp", phaseDefines);
    program.use();
    glUniform1i(program.uniform("uWidth"), buffer.width());
    glUniform1i(program.uniform("uHeight"), buffer.height());
    glUniform1f(program.uniform("uObjectRadius"), objectRadius);
    glUniform1f(program.uniform("uWz"), float(settings.wz));
    glUniform1f(program.uniform("uGapScale"), float(settings.wz / objectRadius));
    glUniform1f(program.uniform("uWn"), float(settings.wn));
    glUniform1f(program.uniform("uS"), float(settings.s));
    glUniform1i(program.uniform("uSortedWords"), kSortedWordsUnit);
    glUniform1i(program.uniform("uSortedQuads"), kSortedQuadsUnit);
    glUniform1i(program.uniform("uLinkTexels"), kLinkTexelsUnit);
    glUniform1i(program.uniform("uPairTexels"), kPairTexelsUnit);
    glUniform1i(program.uniform("uPixelCounts"), kPixelCountsUnit);
    glUniform1i(program.uniform("uPixelHeads"), kPixelHeadsUnit);
    glUniform1i(program.uniform("uListSteps"), kListStepsUnit);
    timePart(timer, std::string("connect phase ") + phase, [&] {
      if (phase[0] == '3') gpu::dispatchLinear(items);
      else buffer.dispatchCovered(program);  // phases 1 and 2: the pixels that hold a fragment
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                      GL_BUFFER_UPDATE_BARRIER_BIT);
    });
  };
  // Phase 1 settles most pairs of adjacent pixels; phase 3 searches the pairs it listed; phase 2
  // sets the fields from the (mutual) links.
  // The listed pairs, and whether some fragment lacks a same-layer link: from phase 1 as host code
  // where the host passes run (gpu::hostPassesWanted), else from the shader's work buffer.
  std::array<std::uint32_t, 2> header{0, 0};
  // Phase 2 as host code where the host passes run (gpu::hostPassesWanted), unless Eq. 5's α
  // varies (left to the shader's pow, whose last bit the host's need not match); folded into phase
  // 1 where that is host code too, for the pixels whose pairs it settles (FastLinks::conditions),
  // unless the links are pair bits (where a stack linked all round leaves phase 2 out, below).
  const bool hostPhase2 = gpu::hostPassesWanted() && !settings.adaptiveAlpha;
  std::optional<FoldedPhase2> folded;
  if (bounded && gpu::hostPassesWanted()) {
    if (hostPhase2 && !linkMasks) folded.emplace();
    timePart(timer, "connect phase 1 on the host", [&] {
      header = settleFastLinks(buffer, settings, objectRadius, fields, linkMasks, listSeeds, folded ? &*folded : nullptr);
    });
  } else {
    run("1");
    fields.readSmall(work, header.data(), sizeof header);
  }
  const std::uint32_t listed = header[0];
  // Phase 2 would find every fragment with its 4 neighbours (see ConnectOutput) where the links
  // are bits joining whole lists all round; the frame then reads nothing it writes, unless Eq. 5's
  // α varies or Eq. 8 spreading reads every fragment.
  const bool whole = linkMasks && listed == 0 && header[1] == 0;
  const bool leaveOutPhase2 = output == ConnectOutput::WhatTheFrameReads && whole && !settings.adaptiveAlpha &&
                              (listSeeds || (!fields.hasBeta() && !fields.hasGamma()));
  if (leaveOutPhase2) {
    // No seed is listed (β and γ are 0, below), every flag is free, and no link is stored.
    fields.setFlagsUniform(kAllFree);
    fields.setLinksStored(false);
  } else {
    if (listed > 0) run("3", listed);
    if (hostPhase2)
      timePart(timer, "connect phase 2 on the host",
               [&] { setBoundaryConditions(buffer, fields, linkMasks, listSeeds, folded ? &*folded : nullptr); });
    else
      run("2");
    // Phase 2 wrote each field's output copy, where it stored one (see ops/connect.comp): make
    // those current.
    fields.swap(Field::Alpha);
    if (fields.hasBeta()) fields.swap(Field::Beta);
    if (fields.hasGamma()) fields.swap(Field::Gamma);
  }
  // Eq. 4's α is s everywhere; a listed field is 1 at its seeds and 0 elsewhere.
  fields.setSeedsListed(listSeeds);
  if (!settings.adaptiveAlpha) fields.setUniform(Field::Alpha, float(settings.s));
  if (listSeeds)
    for (Field f : {Field::Beta, Field::Gamma})
      if (fields.has(f)) {
        if (fields.allZero(f)) fields.setUniform(f, 0.0f);
        else writeSeeds(shaders, fields, f);
      }
  fields.setLinksFromPairBits(linkMasks);
  gpu::checkGl("ops/connect.comp");
  return listed;
}

}  // namespace tlab::render
