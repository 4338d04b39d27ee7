#pragma once
// SHA-256 of a byte string as 64 lower-case hex digits (OpenSSL EVP), for the manifest.
#include <cstdint>
#include <string>
#include <vector>

namespace tlab::stimuli {

std::string sha256Hex(const std::vector<std::uint8_t>& bytes);

}  // namespace tlab::stimuli
