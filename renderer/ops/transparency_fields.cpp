#include "renderer/ops/transparency_fields.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>

namespace tlab::render {

namespace {
// Binding points of ops/field_bindings.glsl.
constexpr GLuint kLinks = 10, kAlphaIn = 11, kAlphaOut = 12, kBetaIn = 13, kBetaOut = 14, kGammaIn = 15,
                 kGammaOut = 16, kFlags = 17, kAlphaOld = 18;

// Keeps `b` where it holds `bytes` already, else allocates it anew (contents undefined).
void fit(gpu::Buffer& b, std::size_t bytes) {
  if (!b || b.size() < bytes) b = gpu::Buffer(bytes);
}
}  // namespace

TransparencyFields::TransparencyFields(std::size_t fragments, bool withBeta, bool withGamma) {
  resize(fragments, withBeta, withGamma);
}

void TransparencyFields::resize(std::size_t fragments, bool withBeta, bool withGamma) {
  fragments_ = fragments;
  withBeta_ = withBeta;
  withGamma_ = withGamma;
  const std::size_t floats = fragments * sizeof(float);
  fit(links_, fragments * sizeof(glm::uvec4));
  fit(flags_, fragments * 4);
  fit(alphaOld_, floats);
  for (auto& b : alpha_.copies) fit(b, floats);
  if (withBeta)
    for (auto& b : beta_.copies) fit(b, floats);
  if (withGamma)
    for (auto& b : gamma_.copies) fit(b, floats);
  seedsListed_ = false;
  for (bool& zero : allZero_) zero = false;
  for (auto& value : unstored_) value.reset();
  unstoredFlags_.reset();
  linksStored_ = true;
  if (!withBeta && !withGamma) return;
  const std::size_t list = (fragments + 4) * 4;
  fit(frontier_[int(Field::Alpha)], list);
  if (withBeta) fit(frontier_[int(Field::Beta)], list);
  if (withGamma) fit(frontier_[int(Field::Gamma)], list);
}

gpu::Buffer& TransparencyFields::frontier(Field field) {
  gpu::Buffer& list = frontier_[int(field)];
  if (!list) throw std::logic_error("no frontier lists: the fields have neither beta nor gamma");
  return list;
}

void TransparencyFields::clearList(const gpu::Buffer& list) {
  list.setFirstQuad({0, 1, 1, 0});  // groups, 1, 1, count; written by the GL, not the host (see readSmall)
}

void TransparencyFields::writeList(const gpu::Buffer& list, const std::vector<std::uint32_t>& items) {
  constexpr std::uint32_t kGroup = 64, kMaxGroups = 65535;  // FRONTIER_GROUP, FRONTIER_MAX_GROUPS of ops/field_bindings.glsl
  const auto count = static_cast<std::uint32_t>(items.size());
  const std::uint32_t header[4] = {std::min((count + kGroup - 1) / kGroup, kMaxGroups), 1, 1, count};
  list.upload(header, sizeof header);
  list.upload(items.data(), items.size() * 4, sizeof header);
}

void TransparencyFields::setSeedsListed(bool listed) {
  seedsListed_ = listed;
  allZero_[int(Field::Beta)] = listed && hasBeta() && listCount(frontier(Field::Beta)) == 0;
  allZero_[int(Field::Gamma)] = listed && hasGamma() && listCount(frontier(Field::Gamma)) == 0;
}

void TransparencyFields::dispatchOnList(const gpu::ShaderProgram& program, const gpu::Buffer& list) {
  program.use();
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, list.id());
  glDispatchComputeIndirect(0);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT |
                  GL_TEXTURE_FETCH_BARRIER_BIT);
}

std::uint32_t TransparencyFields::listCount(const gpu::Buffer& list) const {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::uint32_t count = 0;
  readSmall(list, &count, sizeof count, 3 * sizeof count);
  return count;
}

void TransparencyFields::readSmall(const gpu::Buffer& from, void* data, std::size_t bytes, std::size_t offset) const {
  if (!staging_) staging_ = gpu::Buffer(16);
  from.downloadThrough(staging_, data, bytes, offset);
}

std::vector<std::uint32_t> TransparencyFields::readList(Field field) {
  const gpu::Buffer& list = frontier(field);
  std::vector<std::uint32_t> items(listCount(list));
  list.download(items.data(), items.size() * 4, 4 * 4);
  return items;
}

gpu::Buffer& TransparencyFields::connectWork(std::size_t pixels) {
  fit(connectWork_, (2 * pixels + 2) * 4);  // count, partial, pairs
  return connectWork_;
}

gpu::Buffer& TransparencyFields::connectPairs(std::size_t pixels) {
  fit(connectPairs_, pixels * 16);
  return connectPairs_;
}

gpu::ShaderDefines TransparencyFields::defines() const {
  gpu::ShaderDefines d;
  if (withBeta_) d.emplace_back("TLAB_HAS_BETA", "1");
  if (withGamma_) d.emplace_back("TLAB_HAS_GAMMA", "1");
  return d;
}

TransparencyFields::PingPong& TransparencyFields::pair(Field f) {
  return f == Field::Alpha ? alpha_ : f == Field::Beta ? beta_ : gamma_;
}
const TransparencyFields::PingPong& TransparencyFields::pair(Field f) const {
  return f == Field::Alpha ? alpha_ : f == Field::Beta ? beta_ : gamma_;
}

const gpu::Buffer& TransparencyFields::links() const {
  if (!linksStored_)
    throw std::logic_error("the connect pass stored no links for this frame (ConnectOutput::WhatTheFrameReads)");
  return links_;
}

const gpu::Buffer& TransparencyFields::flags() const {
  if (unstoredFlags_) {
    flags_.fillWords(*unstoredFlags_, fragments_);
    unstoredFlags_.reset();
  }
  return flags_;
}

void TransparencyFields::bindCurrent() const {
  links().bindBase(GL_SHADER_STORAGE_BUFFER, kLinks);
  flags().bindBase(GL_SHADER_STORAGE_BUFFER, kFlags);
  alphaOld_.bindBase(GL_SHADER_STORAGE_BUFFER, kAlphaOld);
  bindPair(Field::Alpha, kAlphaIn, kAlphaOut);
  if (withBeta_) bindPair(Field::Beta, kBetaIn, kBetaOut);
  if (withGamma_) bindPair(Field::Gamma, kGammaIn, kGammaOut);
}

void TransparencyFields::setUniform(Field field, float value) { unstored_[int(field)] = value; }

void TransparencyFields::storeUniform(Field field) const {
  std::optional<float>& value = unstored_[int(field)];
  if (!value) return;
  const PingPong& p = pair(field);
  p.copies[p.current].fillWords(std::bit_cast<std::uint32_t>(*value), fragments_);
  value.reset();
}

void TransparencyFields::bindInput(Field field, unsigned binding) const {
  current(field).bindBase(GL_SHADER_STORAGE_BUFFER, binding);
}

void TransparencyFields::bindPair(Field field, unsigned in, unsigned out) const {
  storeUniform(field);
  const PingPong& p = pair(field);
  p.copies[p.current].bindBase(GL_SHADER_STORAGE_BUFFER, in);
  p.copies[1 - p.current].bindBase(GL_SHADER_STORAGE_BUFFER, out);
}

void TransparencyFields::swap(Field field) {
  pair(field).current ^= 1;
  unstored_[int(field)].reset();  // a pass wrote the output copy, now current
}

const gpu::Buffer& TransparencyFields::output(Field field) const {
  const PingPong& p = pair(field);
  return p.copies[1 - p.current];
}

const gpu::Buffer& TransparencyFields::current(Field field) const {
  storeUniform(field);
  const PingPong& p = pair(field);
  return p.copies[p.current];
}

std::vector<float> TransparencyFields::read(Field field) const {
  if ((field == Field::Beta && !withBeta_) || (field == Field::Gamma && !withGamma_))
    throw std::logic_error("that transparency field is switched off");
  if (const auto value = uniformValue(field)) return std::vector<float>(fragments_, *value);
  std::vector<float> v(fragments_);
  current(field).download(v.data(), v.size() * sizeof(float));
  return v;
}

std::vector<glm::uvec4> TransparencyFields::readLinks() const {
  std::vector<glm::uvec4> v(fragments_);
  links().download(v.data(), v.size() * sizeof(glm::uvec4));
  return v;
}

std::vector<std::uint32_t> TransparencyFields::readFlags() const {
  if (unstoredFlags_) return std::vector<std::uint32_t>(fragments_, *unstoredFlags_);
  std::vector<std::uint32_t> v(fragments_);
  flags_.download(v.data(), v.size() * 4);
  return v;
}

}  // namespace tlab::render
