#pragma once
// SHA-256 (FIPS 180-4) of a byte string, as 64 lowercase hex digits: the identity of a stimulus
// image and of an experiment file in the study database.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace tlab::study {

std::string sha256Hex(std::span<const std::uint8_t> bytes);
std::string sha256Hex(std::string_view text);

}  // namespace tlab::study
