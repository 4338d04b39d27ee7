#pragma once
// The connect pass (Carnecky Sec. 4.4, 5.2, 5.3): geodesic neighbour links by the mutual-best
// continuity test (Alg. 2, Eqs. 1-3), initial α (Eqs. 4-5), and the boundary conditions of
// Sec. 5.3 — one full-screen compute pass (ops/connect.comp).
#include <memory>

#include "renderer/ops/smart_settings.hpp"
#include "renderer/ops/transparency_fields.hpp"
#include "renderer/buffer/fragment_buffer.hpp"
#include "renderer/frame/frame_context.hpp"
#include "renderer/frame/pass_timer.hpp"

namespace tlab::render {

// How a fragment's neighbour is found in the adjacent list: by binary search from the predicted
// depth with a bound on ε (the default), or by comparing all pairs (the reference for tests).
// The bounded search keeps the links the fast path settles either as words, written as phase 1
// goes, or as bits of each pixel's pairs, written out as links by phase 2 (ops/connect.comp
// TLAB_LINK_MASKS; every list at most 32 layers long, FragmentBuffer::longestListBound). Bounded
// picks the bits for lists longer than 8 (issue #29: on the 16-layer stack the pass took about a
// tenth less time; on the torus, lists of at most 8, a twentieth more: the bits cost per pixel
// what they save per layer); BoundedWords and BoundedBits choose (tests compare the two).
enum class NeighborSearch { Bounded, BoundedWords, BoundedBits, AllPairs };

// What the pass must leave in the fields. Everything: the links, the flags and every field, for
// whoever reads them (tests, a style file's stages). WhatTheFrameReads: smart transparency's own
// frame, which reads the links and flags only to spread from seeds (or to diffuse Eq. 5's α):
// where the links kept as bits join every fragment to the same layer of all its adjacent pixels,
// there is no seed, and phase 2 is left out — the flags are all free, β and γ are 0 and α is s,
// kept as numbers (TransparencyFields::setUniform), and the links are not stored (issue #29).
enum class ConnectOutput { Everything, WhatTheFrameReads };

// Runs the pass into `fields`, resized for the buffer's fragments (kept memory is reused).
// Returns how many pairs of adjacent pixels needed the full neighbour search (the rest took the
// fast path). With a timer, each phase's dispatch is a part of the running pass ("connect phase N").
std::size_t connectFragments(const FragmentBuffer& buffer, gpu::ShaderCache& shaders, const SmartSettings& settings,
                             float objectRadius, TransparencyFields& fields, NeighborSearch search = NeighborSearch::Bounded,
                             ConnectOutput output = ConnectOutput::Everything, PassTimer* timer = nullptr);

// Allocates the fields for the buffer's fragments and runs the pass.
std::unique_ptr<TransparencyFields> connectFragments(const FragmentBuffer& buffer, gpu::ShaderCache& shaders,
                                                     const SmartSettings& settings, float objectRadius,
                                                     NeighborSearch search = NeighborSearch::Bounded);

}  // namespace tlab::render
