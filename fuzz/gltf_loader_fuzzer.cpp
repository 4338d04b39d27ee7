// Fuzz target: glTF bytes → Scene, through tinygltf and our conversion. The first byte selects
// .glb (odd) or .gltf (even). Rejections must be std::runtime_error; external buffers/images are
// looked up in an empty directory so the fuzzer never reads files it did not write.
// fuzz-sources: renderer/scene/gltf_loader.cpp
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "renderer/scene/gltf_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const bool binary = (data[0] & 1) != 0;
  const std::vector<unsigned char> bytes(data + 1, data + size);
  try {
    tlab::render::loadGltfFromMemory(bytes, binary ? "fuzz.glb" : "fuzz.gltf", binary, "/nonexistent-tlab-fuzz");
  } catch (const std::runtime_error&) {
  }
  return 0;
}
