#pragma once
// SHA-256 of bytes as 64 lower-case hex digits (OpenSSL EVP): the identity of every stimulus
// image in a manifest and of every experiment file and stimulus in the study database.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace tlab::core {

std::string sha256Hex(std::span<const std::uint8_t> bytes);
std::string sha256Hex(std::string_view text);

}  // namespace tlab::core
