#pragma once
// The per-fragment state of smart transparency on the GPU (Carnecky Sec. 5.1): neighbour links
// (Sec. 4.4), the fields α, β, γ with ping-pong copies (fragData/fragData2 of Sec. 4.5), and the
// b flags. β exists only with silhouettes on, γ only with halos on.
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/gpu/gl_objects.hpp"
#include "renderer/gpu/shader_program.hpp"
#include "renderer/ops/fast_links.hpp"

namespace tlab::render {

enum class Field { Alpha, Beta, Gamma };

class TransparencyFields {
 public:
  TransparencyFields() = default;  // no fragments yet: call resize
  TransparencyFields(std::size_t fragments, bool withBeta, bool withGamma);
  // For a frame of `fragments` fragments: keeps every buffer that is large enough (a frame's
  // passes write every element they later read, so nothing needs clearing) and grows the others,
  // so that frames of a kept renderer allocate (and the GL zeroes) no memory.
  void resize(std::size_t fragments, bool withBeta, bool withGamma);
  std::size_t fragments() const { return fragments_; }
  bool hasBeta() const { return withBeta_; }
  bool hasGamma() const { return withGamma_; }
  bool has(Field field) const { return field == Field::Alpha || (field == Field::Beta ? withBeta_ : withGamma_); }
  gpu::ShaderDefines defines() const;  // TLAB_HAS_BETA / TLAB_HAS_GAMMA

  // Binds links, flags, and the current value of each field as *_IN (and its other copy *_OUT).
  void bindCurrent() const;
  // Binds `field`'s current copy as input and the other as output at the given binding points.
  void bindPair(Field field, unsigned inBinding, unsigned outBinding) const;
  // Binds `field`'s current copy alone, for a pass that reads it (the compose).
  void bindInput(Field field, unsigned binding) const;
  // After a pass wrote `field`'s output copy: that copy becomes current.
  void swap(Field field);
  // The output copy of `field` (the connect pass writes initial values there, then swaps).
  const gpu::Buffer& output(Field field) const;
  const gpu::Buffer& current(Field field) const;

  // A field that holds one value at every fragment, which no buffer holds yet (issue #29: the
  // connect pass does not store Eq. 4's α = s, nor β or γ without a seed, for every fragment).
  // Whatever binds the field or asks for its current copy (bindCurrent, bindPair, bindInput,
  // current) gets a buffer cleared to that value first; read() returns it without writing one. A
  // pass that needs only the number asks uniformValue (the compose: α as a uniform). Reset by
  // resize, as the fields of each frame start anew.
  void setUniform(Field field, float value);
  std::optional<float> uniformValue(Field field) const { return unstored_[int(field)]; }
  // Flags kept likewise as one value (all free where the connect pass left out its phase 2).
  void setFlagsUniform(std::uint32_t value) { unstoredFlags_ = value; }
  // Whether the links are stored: not where the connect pass left out phase 2 for a frame that
  // reads no link (ConnectOutput::WhatTheFrameReads); links(), bindCurrent() and readLinks()
  // then throw std::logic_error, as no pass may read them. Reset by resize.
  void setLinksStored(bool stored) { linksStored_ = stored; }
  bool linksStored() const { return linksStored_; }
  const gpu::Buffer& links() const;
  const gpu::Buffer& flags() const;
  gpu::Buffer& scratch() { return alphaOld_; }
  // The connect pass's work list (a count, a flag, then up to 2 × `pixels` pairs of adjacent pixels), kept likewise.
  gpu::Buffer& connectWork(std::size_t pixels);
  gpu::Buffer& connectPairs(std::size_t pixels);  // the connect pass's pair bits, a uvec4 a pixel
  std::vector<FastLinkRows>& fastLinkRows() { return fastLinkRows_; }  // phase 1 as host code's, a thread each
  // Whether the last connect pass kept its settled links as pair bits (written out by its phase 2).
  void setLinksFromPairBits(bool on) { linksFromPairBits_ = on; }
  bool linksFromPairBits() const { return linksFromPairBits_; }

  // Sparse Eq. 9 spreading (ops/spread_frontier.comp): fragment lists, each a dispatch header
  // (groups, 1, 1, count) then up to `fragments` indices. frontier(Beta) and frontier(Gamma) are
  // where the connect pass lists each field's seeds, frontier(Alpha) a spare list.
  gpu::Buffer& frontier(Field field);
  static void clearList(const gpu::Buffer& list);  // no entries (and no groups to dispatch)
  // The header and `items` written from the host (the connect pass's phase 2 as host code).
  static void writeList(const gpu::Buffer& list, const std::vector<std::uint32_t>& items);
  std::uint32_t listCount(const gpu::Buffer& list) const;
  // Reads up to 16 bytes of a large buffer the passes just wrote (a list's count, the connect
  // pass's work header) through a small staging buffer (gpu::Buffer::downloadThrough). On an
  // H200 with NVIDIA's driver, reading them straight from the list (and writing a list's header
  // from the host) cost time in proportion to the buffer's size: 2.2 ms a solve step at 2048²,
  // 68 ms of the torus's solve, 1.4 ms since (README, "On a GPU").
  void readSmall(const gpu::Buffer& from, void* data, std::size_t bytes, std::size_t offset = 0) const;
  // Runs `program` over the entries of `list` (its header is the indirect dispatch), then the
  // barriers for what reads its results.
  static void dispatchOnList(const gpu::ShaderProgram& program, const gpu::Buffer& list);
  // Whether the seed lists describe the current β and γ (set by the connect pass): true once,
  // for the solve that spreads from them. Listing also settles allZero (below).
  void setSeedsListed(bool listed);
  bool takeSeedsListed() { return std::exchange(seedsListed_, false); }
  bool seedsListed() const { return seedsListed_; }
  std::vector<std::uint32_t> readList(Field field);  // the fragments of frontier(field), as listed
  // Whether β (or γ) is 0 at every fragment for the rest of the frame: its seeds were listed and
  // there are none (no fragment starts above 0), and Eq. 9's max-propagation keeps a field of
  // zeros so. The solve then spreads nothing and the compose reads nothing of it (issue #29: a
  // stack without silhouettes). False unless the seeds are listed, and after resize.
  bool allZero(Field field) const { return allZero_[int(field)]; }

  // Read-backs for tests, inspection and the diffusion benchmark.
  std::vector<float> read(Field field) const;
  std::vector<glm::uvec4> readLinks() const;
  std::vector<std::uint32_t> readFlags() const;

 private:
  struct PingPong {
    gpu::Buffer copies[2];
    int current = 0;
  };
  PingPong& pair(Field f);
  const PingPong& pair(Field f) const;
  void storeUniform(Field f) const;  // clears the current copy to the unstored value, if any

  std::size_t fragments_ = 0;
  bool withBeta_ = false, withGamma_ = false;
  gpu::Buffer links_, flags_, alphaOld_, connectWork_, connectPairs_;
  std::vector<FastLinkRows> fastLinkRows_;
  bool linksFromPairBits_ = false;
  PingPong alpha_, beta_, gamma_;
  gpu::Buffer frontier_[3];  // by Field
  mutable gpu::Buffer staging_;  // 16 bytes, made on first use (readSmall)
  bool seedsListed_ = false;
  bool allZero_[3] = {false, false, false};  // by Field
  // By Field: the value of a field no buffer holds yet (storeUniform writes it when a pass needs it).
  mutable std::optional<float> unstored_[3];
  mutable std::optional<std::uint32_t> unstoredFlags_;
  bool linksStored_ = true;
};

}  // namespace tlab::render
