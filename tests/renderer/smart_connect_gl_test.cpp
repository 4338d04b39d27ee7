// The connect pass of smart transparency (Carnecky Sec. 4.4, Alg. 2; Sec. 5.3): the bounded
// neighbour search against comparing all pairs, and the image edge, where a missing neighbour is
// unknown rather than "no surface" (issue #20 item 1).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <map>
#include <stdexcept>
#include <tuple>

#include "renderer/scene/scene_source.hpp"
#include "tests/renderer/smart_rig.hpp"
#include "tests/support/gl_fixture.hpp"
#include "tests/support/scoped_env.hpp"

using namespace tlab::render;
using namespace tlab::testing;

// The bounded search finds the same links, flags and initial fields as comparing all pairs.
TEST(NeighborLinks, BoundedSearchEqualsAllPairs) {
  Scene occluder = occluderScene();
  for (const auto& [scene, size] : {std::pair{loadScene("builtin:open-cylinders"), 64}, std::pair{loadScene("builtin:torus"), 64},
                                    std::pair{loadScene("builtin:quad-stack?n=16"), 32},
                                    std::pair{loadScene("builtin:nested-spheres?n=3"), 64}, std::pair{occluder, 48},
                                    std::pair{loadScene("builtin:sphere?segments=8&rings=4"), 24}}) {
    SmartRig rig(scene, size, size, {{"alpha_init", "adaptive"}});
    const auto reference =
        connectFragments(*rig.buffer, rig.shaders, rig.smart, rig.scene.boundingSphere().radius, NeighborSearch::AllPairs);
    EXPECT_EQ(rig.fields->readLinks(), reference->readLinks()) << scene.name;
    EXPECT_EQ(rig.fields->readFlags(), reference->readFlags()) << scene.name;
    EXPECT_EQ(rig.fields->read(Field::Beta), reference->read(Field::Beta)) << scene.name;
    EXPECT_EQ(rig.fields->read(Field::Gamma), reference->read(Field::Gamma)) << scene.name;
  }
}

// The sort pass writes each list's maxStep for the connect pass (which then runs no pass of its
// own over the gradients): the largest |∂z/∂x| and |∂z/∂y| of the list's records, exactly, for
// lists sorted in registers and, on the 20-layer stack, in the order buffer; the slot fill and the
// scatter fill alike.
TEST(NeighborLinks, TheSortWritesEachListsLargestGradientForTheConnectPass) {
  for (const auto& [scene, size] : {std::pair{loadScene("builtin:torus"), 48}, std::pair{loadScene("builtin:quad-stack?n=20"), 16},
                                    std::pair{loadScene("builtin:nested-spheres?n=3"), 40}}) {
    SmartRig rig(scene, size, size);
    const FragmentLayout& layout = rig.buffer->layout();
    ASSERT_TRUE(layout.properties.has(FragmentProperty::DepthGradient));
    const tlab::gpu::Buffer* steps = rig.buffer->listSteps();
    ASSERT_NE(steps, nullptr) << scene.name;
    const std::size_t pixels = std::size_t(size) * size;
    std::vector<glm::vec2> gpuSteps(pixels);
    steps->download(gpuSteps.data(), pixels * sizeof(glm::vec2));
    const auto records = rig.buffer->sortedRecords(0, rig.buffer->fragmentCount());
    std::size_t covered = 0, longest = 0;
    for (std::size_t p = 0; p < pixels; ++p) {
      if (rig.counts[p] == 0) continue;
      ++covered;
      longest = std::max<std::size_t>(longest, rig.counts[p]);
      glm::vec2 expected(0.0f);
      for (std::uint32_t l = 0; l < rig.counts[p]; ++l) {
        const std::size_t g = std::size_t(rig.heads[p] + l) * layout.stride + layout.depthGradientOffset;
        expected = glm::max(expected, glm::abs(glm::vec2(std::bit_cast<float>(records[g]), std::bit_cast<float>(records[g + 1]))));
      }
      ASSERT_EQ(gpuSteps[p], expected) << scene.name << " pixel " << p;
    }
    EXPECT_GT(covered, pixels / 4) << scene.name;
    if (scene.name == "quad-stack") {
      EXPECT_EQ(longest, 20u);  // past the 16 registers
    }
  }
}

// The connect pass settles most links from the layers next to each fragment (the fast path) and
// searches the rest in full; on scenes that need both, the links equal those of comparing all
// pairs (above), and the fields kept by a renderer give the same links frame after frame.
TEST(NeighborLinks, FastPathAndFullSearchTogetherEqualAllPairs) {
  struct Case {
    const char* source;
    int size;
    bool bothPaths;  // some pixels take each path (the 64 close quads send every pixel to the full search)
  };
  for (const auto& [source, size, bothPaths] : {Case{"builtin:torus", 64, true}, Case{"builtin:nested-spheres?n=3", 64, true},
                                                Case{"builtin:quad-stack?n=64", 24, false}}) {
    SmartRig rig(loadScene(source), size, size);
    std::size_t covered = 0;
    for (auto c : rig.counts) covered += c > 0;
    TransparencyFields kept;
    const std::size_t searched =
        connectFragments(*rig.buffer, rig.shaders, rig.smart, rig.scene.boundingSphere().radius, kept);
    EXPECT_LE(searched, 2 * covered) << source;  // pairs of adjacent pixels, both covered
    if (bothPaths) {
      EXPECT_GT(searched, 0u) << source;       // some pixels took the full search
      EXPECT_LT(searched, covered) << source;  // and the fast path settled the others
    }
    const auto reference =
        connectFragments(*rig.buffer, rig.shaders, rig.smart, rig.scene.boundingSphere().radius, NeighborSearch::AllPairs);
    EXPECT_EQ(kept.readLinks(), reference->readLinks()) << source;
    EXPECT_EQ(kept.readFlags(), reference->readFlags()) << source;
    // Once more into the same (kept, no longer zeroed) memory: the same links.
    connectFragments(*rig.buffer, rig.shaders, rig.smart, rig.scene.boundingSphere().radius, kept);
    EXPECT_EQ(kept.readLinks(), reference->readLinks()) << source;
    EXPECT_EQ(kept.read(Field::Beta), reference->read(Field::Beta)) << source;
  }
}

// Three quads seen straight on: two over the whole view (z = 0 and −0.5) and one behind them
// (z = −1) over x < 0 only, each its own component; its edge lies between pixel columns
// width/2 − 1 and width/2, so the lists there hold 3 and 2 layers.
namespace {
Scene backHalfScene() {
  Scene s;
  const auto quad = [](const char* name, glm::vec3 center, float halfWidth) {
    SceneObject o;
    o.name = name;
    o.mesh = makeQuad(center, {halfWidth, 0, 0}, {0, 20, 0});
    o.frontColor = {0.5f, 0.5f, 0.5f, 1};
    return o;
  };
  s.objects = {quad("front", {0, 0, 0}, 20), quad("middle", {0, 0, -0.5f}, 20), quad("back", {-10, 0, -1}, 10)};
  s.camera = Camera{};
  s.camera->eye = {0, 0, 5};
  s.camera->nearPlane = 1;
  s.camera->farPlane = 10;
  return s;
}
}  // namespace

// Each pair of adjacent pixels is connected once (ops/connect.comp, phase 1): every link points
// into the list of the adjacent pixel in its direction, the fragment there links back, and no
// link leaves the image — on sizes with odd rows and columns, lists of different lengths, several
// components, and the same for the links of comparing all pairs.
TEST(NeighborLinks, EveryLinkIsReturnedFromTheAdjacentPixel) {
  const std::array<glm::ivec2, 4> directions = {  // kDirections of ops/connect.comp
     glm::ivec2(-1, 0), glm::ivec2(1, 0), glm::ivec2(0, -1), glm::ivec2(0, 1)};
  for (const auto& [scene, w, h] : {std::tuple{backHalfScene(), 40, 31}, std::tuple{occluderScene(), 33, 27},
                                    std::tuple{loadScene("builtin:nested-spheres?n=3"), 45, 37},
                                    std::tuple{loadScene("builtin:torus"), 63, 47}}) {
    SmartRig rig(scene, w, h);
    const auto reference =
        connectFragments(*rig.buffer, rig.shaders, rig.smart, rig.scene.boundingSphere().radius, NeighborSearch::AllPairs);
    const auto links = rig.fields->readLinks();
    EXPECT_EQ(links, reference->readLinks()) << scene.name;
    std::size_t linked = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const std::size_t p = std::size_t(y) * w + x;
        for (std::uint32_t layer = 0; layer < rig.counts[p]; ++layer) {
          const std::uint32_t f = rig.heads[p] + layer;
          for (int k = 0; k < 4; ++k) {
            const std::uint32_t j = links[f][k];
            if (j == kNone) continue;
            ++linked;
            const glm::ivec2 q = glm::ivec2(x, y) + directions[k];
            ASSERT_TRUE(q.x >= 0 && q.y >= 0 && q.x < w && q.y < h) << scene.name << " " << x << "," << y << " k " << k;
            const std::size_t qp = std::size_t(q.y) * w + q.x;
            ASSERT_GE(j, rig.heads[qp]) << scene.name << " " << x << "," << y << " k " << k;
            ASSERT_LT(j, rig.heads[qp] + rig.counts[qp]) << scene.name << " " << x << "," << y << " k " << k;
            ASSERT_EQ(links[j][k ^ 1], f) << scene.name << " " << x << "," << y << " k " << k;
          }
        }
      }
    EXPECT_GT(linked, std::size_t(w * h)) << scene.name;
  }
}

// A pair split between the fast path and the full search: beside the back quad's edge, layers 0
// and 1 of both lists match layer for layer (the fast path settles them), while layer 2 of the
// 3-layer list has no counterpart (it is searched in full, finds none in the other component, and
// the pair is listed). The result is the same as comparing all pairs, and the links by hand.
TEST(NeighborLinks, PairSplitBetweenFastPathAndFullSearch) {
  constexpr int w = 40, h = 31;
  SmartRig rig(backHalfScene(), w, h);
  TransparencyFields fields;
  const std::size_t searched = connectFragments(*rig.buffer, rig.shaders, rig.smart, rig.scene.boundingSphere().radius, fields);
  const auto links = fields.readLinks();
  EXPECT_GE(searched, std::size_t(h));    // every pair across the edge
  EXPECT_LT(searched, std::size_t(w * h));  // not all of them
  for (int y = 0; y < h; ++y) {
    ASSERT_EQ(rig.counts[std::size_t(y) * w + w / 2 - 1], 3u) << y;
    ASSERT_EQ(rig.counts[std::size_t(y) * w + w / 2], 2u) << y;
    for (int layer = 0; layer < 2; ++layer) {
      EXPECT_EQ(links[rig.fragment(w / 2 - 1, y, layer)][1], rig.fragment(w / 2, y, layer)) << y;
      EXPECT_EQ(links[rig.fragment(w / 2, y, layer)][0], rig.fragment(w / 2 - 1, y, layer)) << y;
    }
    EXPECT_EQ(links[rig.fragment(w / 2 - 1, y, 2)][1], kNone) << y;
    if (y + 1 < h) {
      EXPECT_EQ(links[rig.fragment(w / 2 - 1, y, 2)][3], rig.fragment(w / 2 - 1, y + 1, 2)) << y;
    }
  }
  const auto reference =
      connectFragments(*rig.buffer, rig.shaders, rig.smart, rig.scene.boundingSphere().radius, NeighborSearch::AllPairs);
  EXPECT_EQ(links, reference->readLinks());
  EXPECT_EQ(fields.readFlags(), reference->readFlags());
  EXPECT_EQ(fields.read(Field::Beta), reference->read(Field::Beta));
  EXPECT_EQ(fields.read(Field::Gamma), reference->read(Field::Gamma));
}

// Phases 1 and 2 run for the pixels that hold a fragment only (issue #29): a pixel next to an
// empty one writes its own link towards it. Into fields whose every word held garbage, the pass
// writes every link, flag and field value as into fresh fields, and a link towards an empty pixel
// (or beyond the edge) is none — on scenes with background inside and around them, the links
// kept as words and as pair bits alike.
TEST(NeighborLinks, EveryLinkIsWrittenWhereTheAdjacentPixelIsEmpty) {
  for (const char* source : {"builtin:torus", "builtin:nested-spheres?n=3", "builtin:open-cylinders"}) {
    SCOPED_TRACE(source);
    SmartRig rig(loadScene(source), 64, 48);
    const auto fresh = rig.fields->readLinks();
    const auto freshFlags = rig.fields->readFlags();
    const auto freshBeta = rig.fields->read(Field::Beta);
    const std::uint32_t garbage = 0x5A5A5A5Au;
    for (NeighborSearch search : {NeighborSearch::Bounded, NeighborSearch::BoundedBits}) {  // words, then pair bits
      for (const tlab::gpu::Buffer* b : {&rig.fields->links(), &rig.fields->flags(),
                                         static_cast<const tlab::gpu::Buffer*>(&rig.fields->connectPairs(rig.buffer->pixels()))})
        glClearNamedBufferData(b->id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &garbage);
      connectFragments(*rig.buffer, rig.shaders, rig.smart, rig.scene.boundingSphere().radius, *rig.fields, search);
      EXPECT_EQ(rig.fields->linksFromPairBits(), search == NeighborSearch::BoundedBits);
      EXPECT_EQ(rig.fields->readLinks(), fresh);
      EXPECT_EQ(rig.fields->readFlags(), freshFlags);
      EXPECT_EQ(rig.fields->read(Field::Beta), freshBeta);
    }
    const glm::ivec2 kDirections[4] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
    std::size_t towardsEmpty = 0;
    for (int y = 0; y < rig.height; ++y)
      for (int x = 0; x < rig.width; ++x)
        for (std::uint32_t layer = 0; layer < rig.counts[std::size_t(y) * rig.width + x]; ++layer)
          for (int k = 0; k < 4; ++k) {
            const glm::ivec2 q = glm::ivec2(x, y) + kDirections[k];
            const bool inside = q.x >= 0 && q.y >= 0 && q.x < rig.width && q.y < rig.height;
            if (inside && rig.counts[std::size_t(q.y) * rig.width + q.x] > 0) continue;
            ++towardsEmpty;
            EXPECT_EQ(fresh[rig.fragment(x, y, int(layer))][k], 0xFFFFFFFFu) << x << "," << y << " layer " << layer << " direction " << k;
          }
    EXPECT_GT(towardsEmpty, 100u) << "fragments beside an empty pixel";
  }
}

// Where every list is at most 32 layers long, phase 1 can keep the links it settles as one bit
// per layer of each pixel's pairs, and phase 2 write the links from them (TLAB_LINK_MASKS; issue
// #29): the same links, flags and fields as writing every link word in phase 1 — with pairs
// listed for the full search beside them (the back quad's edge), background around the lists,
// lists past the first frame's 8 slots (the stack), and past 32 layers, where the words are kept.
// The default takes the bits for lists longer than 8 only.
TEST(NeighborLinks, PairBitsGiveTheLinksOfWritingEveryWord) {
  struct Case {
    Scene scene;
    int w, h;
    bool bits, byDefault;  // every list within 32 layers; and longer than 8 somewhere
  };
  for (const auto& [scene, w, h, bits, byDefault] :
       {Case{backHalfScene(), 40, 31, true, false}, Case{loadScene("builtin:torus"), 63, 47, true, false},
        Case{loadScene("builtin:nested-spheres?n=3"), 45, 37, true, false},
        Case{loadScene("builtin:open-cylinders"), 48, 40, true, false}, Case{loadScene("builtin:quad-stack?n=16"), 24, 20, true, true},
        Case{loadScene("builtin:quad-stack?n=40"), 12, 10, false, false}}) {
    SCOPED_TRACE(scene.name);
    SmartRig rig(scene, w, h, {{"alpha_init", "adaptive"}});
    EXPECT_EQ(rig.fields->linksFromPairBits(), byDefault);
    const float radius = rig.scene.boundingSphere().radius;
    const auto words = connectFragments(*rig.buffer, rig.shaders, rig.smart, radius, NeighborSearch::BoundedWords);
    EXPECT_FALSE(words->linksFromPairBits());
    const auto pairBits = connectFragments(*rig.buffer, rig.shaders, rig.smart, radius, NeighborSearch::BoundedBits);
    EXPECT_EQ(pairBits->linksFromPairBits(), bits);
    for (const TransparencyFields* fields : {rig.fields.get(), pairBits.get()}) {
      EXPECT_EQ(fields->readLinks(), words->readLinks());
      EXPECT_EQ(fields->readFlags(), words->readFlags());
      for (Field f : {Field::Alpha, Field::Beta, Field::Gamma}) EXPECT_EQ(fields->read(f), words->read(f));
    }
  }
}

// A renderer keeps smart transparency's fields (their memory) across frames: a frame after a
// larger one, in memory holding that frame's values, is the picture a fresh renderer draws.
TEST(SmartTransparency, KeptFieldsGiveTheFreshRenderersPicture) {
  const Scene torus = loadScene("builtin:torus");
  RenderRequest large, small;
  large.style = small.style = "smart";
  large.width = large.height = 96;
  small.width = 64;
  small.height = 48;
  Renderer kept(torus);
  const auto first = kept.render(small);
  kept.render(large);
  const auto again = kept.render(small);
  Renderer fresh(torus);
  const auto reference = fresh.render(small);
  EXPECT_EQ(first.pixels, reference.pixels);
  EXPECT_EQ(again.pixels, reference.pixels);
}

// A surface cut by the image edge: the missing neighbour beyond the edge is unknown, not "no
// surface" — no β = 1 frame, and the border fragments stay free (Carnecky Sec. 5.3 on what
// the image shows; issue #20 item 1).
TEST(BoundaryConditions, ImageEdgeStartsNoSilhouette) {
  SmartRig rig(loadScene("builtin:quad-stack?n=1"), 40, 30, {{"iterations", "0"}});
  const auto beta = rig.fields->read(Field::Beta), gamma = rig.fields->read(Field::Gamma);
  const auto flags = rig.fields->readFlags();
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x) {
      const auto f = rig.fragment(x, y, 0);
      ASSERT_EQ(beta[f], 0.0f) << x << "," << y;
      ASSERT_EQ(gamma[f], 0.0f) << x << "," << y;
      ASSERT_EQ(flags[f], 7u) << x << "," << y;
    }
}

// The picture of the issue: a sphere filling a zoomed-in view. The outer 3 pixels used to be 61
// grey levels darker than the band just inside; now the frame shows the surface as it continues.
TEST(SmartTransparency, ZoomedInViewHasNoDarkFrame) {
  Scene sphere = loadScene("builtin:sphere");
  sphere.camera = Camera{};
  sphere.camera->eye = {0, 0, 2.2f};
  sphere.camera->fovyDegrees = 40;
  Renderer renderer(sphere);
  RenderRequest r;
  r.width = r.height = 128;
  r.style = "smart";
  const tlab::core::Image img = renderer.render(r);
  // Mean grey over the pixels at distance [from, to) from the edge, along the middle half of each
  // side (the corners see the sphere's real silhouette).
  const auto band = [&](int from, int to) {
    double sum = 0;
    int count = 0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) {
        const int d = std::min({x, y, img.width - 1 - x, img.height - 1 - y});
        const bool middle = std::abs(2 * x - img.width) < img.width / 2 || std::abs(2 * y - img.height) < img.height / 2;
        if (d < from || d >= to || !middle) continue;
        const auto& p = img.pixels[std::size_t(y) * img.width + x];
        sum += (p[0] + p[1] + p[2]) / 3.0 * 255.0;
        ++count;
      }
    return sum / count;
  };
  EXPECT_NEAR(band(0, 3), band(3, 6), 3.0);
}


// Smart's own frame leaves out phase 2 where the links kept as bits join every fragment to the
// same layer of all its adjacent pixels in the image (issue #29): the full-screen stack. What
// phase 2 would have written is then known — the flags all free, β and γ 0, α = s — and the pass
// that writes everything (the default) confirms it, link by link. Anywhere else (a list shorter,
// a silhouette, Eq. 5's α, Eq. 8 spreading, links kept as words) phase 2 runs, with the same
// results as the default.
TEST(NeighborLinks, PhaseTwoIsLeftOutWhereEveryFragmentIsLinkedAllRound) {
  struct Case {
    const char* source;
    int size;
    std::map<std::string, std::string> settings;
    bool leftOut;
    bool atTheCorner = false;  // seen from above the quads' corner: they fill the view's upper right
  };
  const Case cases[] = {
      {"builtin:quad-stack?n=16", 32, {}, true},
      {"builtin:quad-stack?n=16", 32, {{"halos", "off"}, {"silhouettes", "off"}}, true},
      {"builtin:quad-stack?n=16", 32, {{"alpha_init", "adaptive"}}, false},
      {"builtin:quad-stack?n=16", 32, {{"spread", "diffusion"}}, false},
      {"builtin:nested-spheres?n=6", 48, {}, false},  // lists up to 12 (bits), silhouettes
      {"builtin:torus", 48, {}, false},                // lists up to 4: words
      // Whole lists all round but to the left and below the corner, where no pair is settled.
      {"builtin:quad-stack?n=16", 32, {}, false, true},
  };
  for (const auto& c : cases) {
    const std::string what = std::string(c.source) + " with " + std::to_string(c.settings.size()) + " setting(s)";
    SCOPED_TRACE(what);
    Scene scene = loadScene(c.source);
    if (c.atTheCorner) {
      Camera corner;  // the quads' edges x = -20 and y = -20 through the eye: at the view's centre lines
      corner.eye = {-20.0f, -20.0f, 12.0f};
      corner.target = {-20.0f, -20.0f, 0.0f};
      scene.camera = corner;
    }
    SmartRig rig(scene, c.size, c.size, c.settings);
    if (c.atTheCorner) {
      EXPECT_EQ(rig.counts[std::size_t(c.size - 1) * c.size + c.size - 1], 16u);  // the top right: all 16
      EXPECT_EQ(rig.counts[0], 0u);                                             // the bottom left: none
    }
    TransparencyFields frame;
    connectFragments(*rig.buffer, rig.shaders, rig.smart, rig.scene.boundingSphere().radius, frame, NeighborSearch::Bounded,
                     ConnectOutput::WhatTheFrameReads);
    EXPECT_EQ(frame.linksStored(), !c.leftOut);
    EXPECT_EQ(frame.readFlags(), rig.fields->readFlags());
    for (Field f : {Field::Alpha, Field::Beta, Field::Gamma})
      if (frame.has(f)) { EXPECT_EQ(frame.read(f), rig.fields->read(f)) << int(f); }
    if (!c.leftOut) {
      EXPECT_EQ(frame.readLinks(), rig.fields->readLinks());
      continue;
    }
    EXPECT_THROW(frame.readLinks(), std::logic_error);
    EXPECT_THROW(frame.bindCurrent(), std::logic_error);
    EXPECT_EQ(frame.readFlags(), std::vector<std::uint32_t>(rig.buffer->fragmentCount(), 7u));
    // Every link the default pass wrote joins the same layer of the adjacent pixel (none beyond the image).
    const auto links = rig.fields->readLinks();
    const glm::ivec2 kDirections[4] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
    std::size_t checked = 0;
    for (int y = 0; y < c.size; ++y)
      for (int x = 0; x < c.size; ++x) {
        const std::size_t p = std::size_t(y) * c.size + x;
        for (std::uint32_t layer = 0; layer < rig.counts[p]; ++layer)
          for (int k = 0; k < 4; ++k) {
            const glm::ivec2 q = glm::ivec2(x, y) + kDirections[k];
            const bool inside = q.x >= 0 && q.y >= 0 && q.x < c.size && q.y < c.size;
            const std::uint32_t expected = inside ? rig.heads[std::size_t(q.y) * c.size + q.x] + layer : kNone;
            ASSERT_EQ(links[rig.heads[p] + layer][k], expected) << x << "," << y << " layer " << layer << " direction " << k;
            ++checked;
          }
      }
    EXPECT_EQ(checked, 4 * rig.buffer->fragmentCount());
  }
  // Smart's picture with phase 2 left out: α = s and β = γ = 0 make its compose (Alg. 3) constant's
  // front-to-back blend at alpha = s.
  Renderer renderer(loadScene("builtin:quad-stack?n=16"));
  RenderRequest r;
  r.width = r.height = 32;
  r.style = "smart";
  r.settings = {{"s", "0.45"}};
  const tlab::core::Image smart = renderer.render(r);
  EXPECT_FALSE(renderer.transparencyFields().linksStored());
  r.style = "constant";
  r.settings = {{"alpha", "0.45"}};
  EXPECT_EQ(renderer.render(r).pixels, smart.pixels);
}

// A scene at a size with a neighbour search: the host passes' tests run each both ways.
struct HostCase {
  Scene scene;
  int w, h;
  NeighborSearch search;
};

// Phase 2 as host code (ops/boundary_conditions.hpp: the default where the GL runs on the CPU) and
// as the shader (TLAB_HOST_PASSES=off) leave the same links, flags and fields, and list the same
// seeds (in any order, as the shader's atomics do): links kept as words and as pair bits (lists of
// 9 to 16, and pairs the fast path could not settle), the seeds listed (Eq. 9) or stored as β and
// γ values (Eq. 8 spreading), and a stack linked all round (phase 2 run for every field's reader).
TEST(NeighborLinks, PhaseTwoAsHostCodeLeavesTheShadersFields) {
  const std::vector<HostCase> cases = {{backHalfScene(), 40, 31, NeighborSearch::Bounded},
                                       {loadScene("builtin:torus"), 63, 47, NeighborSearch::Bounded},
                                       {loadScene("builtin:torus"), 63, 47, NeighborSearch::BoundedBits},
                                       {loadScene("builtin:nested-spheres?n=6"), 45, 37, NeighborSearch::Bounded},
                                       {loadScene("builtin:open-cylinders"), 48, 40, NeighborSearch::BoundedWords},
                                       {loadScene("builtin:quad-stack?n=16"), 24, 20, NeighborSearch::Bounded},
                                       {loadScene("builtin:torus"), 40, 30, NeighborSearch::AllPairs}};
  int withSeeds = 0, withBits = 0;
  for (const auto& c : cases) {
    for (const char* spread : {"max", "diffusion"}) {
      SCOPED_TRACE(c.scene.name + " " + std::to_string(int(c.search)) + " " + spread);
      SmartRig rig(c.scene, c.w, c.h, {{"spread", spread}});
      const float radius = rig.scene.boundingSphere().radius;
      std::unique_ptr<TransparencyFields> fields[2];  // host code, shader
      for (const bool onHost : {true, false}) {
        const ScopedEnv passes("TLAB_HOST_PASSES", onHost ? "on" : "off");
        fields[onHost ? 0 : 1] = std::make_unique<TransparencyFields>();
        connectFragments(*rig.buffer, rig.shaders, rig.smart, radius, *fields[onHost ? 0 : 1], c.search);
      }
      const TransparencyFields &host = *fields[0], &shader = *fields[1];
      EXPECT_EQ(host.linksFromPairBits(), shader.linksFromPairBits());
      withBits += host.linksFromPairBits();
      EXPECT_EQ(host.readLinks(), shader.readLinks());
      EXPECT_EQ(host.readFlags(), shader.readFlags());
      for (Field f : {Field::Alpha, Field::Beta, Field::Gamma}) EXPECT_EQ(host.read(f), shader.read(f));
      EXPECT_EQ(host.seedsListed(), std::string(spread) == "max");
      EXPECT_EQ(shader.seedsListed(), host.seedsListed());
      if (host.seedsListed())
        for (Field f : {Field::Beta, Field::Gamma}) {
          auto a = fields[0]->readList(f), b = fields[1]->readList(f);
          withSeeds += !a.empty();
          std::sort(a.begin(), a.end());
          std::sort(b.begin(), b.end());
          EXPECT_EQ(a, b);
          EXPECT_EQ(std::adjacent_find(a.begin(), a.end()), a.end()) << "each seed listed once";
        }
    }
  }
  EXPECT_GT(withSeeds, 4);
  EXPECT_GT(withBits, 2);
}

// Phase 1 as host code (ops/fast_links.hpp: the default where the GL runs on the CPU) and as the
// shader (TLAB_HOST_PASSES=off) write the same words: the pairs listed for the full search (in pixel
// order on the host, in any order by the shader's atomics), `partial`, each covered pixel's pair
// bits, and after phases 3 and 2 the same links and flags. Lists of 2 to 40 layers (the bits up to
// 32, the words past them), several components, pairs the fast path cannot settle, and a larger
// torus for more pairs near a tie.
TEST(NeighborLinks, PhaseOneAsHostCodeWritesTheShadersWords) {
  const std::vector<HostCase> cases = {{backHalfScene(), 40, 31, NeighborSearch::Bounded},
                                       {occluderScene(), 48, 40, NeighborSearch::Bounded},
                                       {loadScene("builtin:torus"), 200, 150, NeighborSearch::Bounded},
                                       {loadScene("builtin:torus"), 63, 47, NeighborSearch::BoundedBits},
                                       {loadScene("builtin:nested-spheres?n=6"), 45, 37, NeighborSearch::Bounded},
                                       {loadScene("builtin:open-cylinders"), 48, 40, NeighborSearch::BoundedWords},
                                       {loadScene("builtin:quad-stack?n=16"), 24, 20, NeighborSearch::Bounded},
                                       {loadScene("builtin:quad-stack?n=40"), 17, 13, NeighborSearch::Bounded}};
  std::size_t listedPairs = 0, withBits = 0, partial = 0;
  for (const auto& c : cases) {
    SCOPED_TRACE(c.scene.name + " " + std::to_string(c.w) + " " + std::to_string(int(c.search)));
    SmartRig rig(c.scene, c.w, c.h);
    const float radius = rig.scene.boundingSphere().radius;
    const std::size_t pixels = std::size_t(c.w) * c.h;
    struct Words {
      std::vector<std::uint32_t> work;
      std::vector<glm::uvec4> pairs, links;
      std::vector<std::uint32_t> flags;
      bool bits = false;
    } words[2];  // host code, shader
    for (const bool onHost : {true, false}) {
      const ScopedEnv passes("TLAB_HOST_PASSES", onHost ? "on" : "off");
      TransparencyFields fields;
      connectFragments(*rig.buffer, rig.shaders, rig.smart, radius, fields, c.search);
      Words& w = words[onHost ? 0 : 1];
      std::uint32_t header[2];
      fields.connectWork(pixels).download(header, sizeof header);
      w.work.assign(header, header + 2);
      std::vector<std::uint32_t> listed(header[0]);
      if (!listed.empty()) fields.connectWork(pixels).download(listed.data(), listed.size() * 4, 8);
      std::sort(listed.begin(), listed.end());
      w.work.insert(w.work.end(), listed.begin(), listed.end());
      w.bits = fields.linksFromPairBits();
      if (w.bits) {
        std::vector<glm::uvec4> all(pixels);
        fields.connectPairs(pixels).download(all.data(), pixels * sizeof(glm::uvec4));
        for (std::size_t p = 0; p < pixels; ++p)
          if (rig.counts[p] > 0) w.pairs.push_back(all[p]);  // the words phase 1 writes
      }
      w.links = fields.readLinks();
      w.flags = fields.readFlags();
    }
    EXPECT_EQ(words[0].bits, words[1].bits);
    EXPECT_EQ(words[0].work, words[1].work);
    EXPECT_EQ(words[0].pairs, words[1].pairs);
    EXPECT_EQ(words[0].links, words[1].links);
    EXPECT_EQ(words[0].flags, words[1].flags);
    listedPairs += words[1].work.size() - 2;
    withBits += words[1].bits;
    partial += words[1].bits && words[1].work[1] != 0;
  }
  EXPECT_GT(listedPairs, 10u);  // the full search had pairs to take over
  EXPECT_GE(withBits, 2u);
  EXPECT_GE(partial, 1u);
}
