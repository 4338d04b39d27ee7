#include "study/run/frame_log.hpp"

#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/sha256.hpp"

namespace tlab::study {

std::string frameInputPart(const char* what, double a, double b) {
  char text[96];
  std::snprintf(text, sizeof text, "%s %.9g,%.9g", what, a, b);
  return text;
}

std::string framePixelsSha256(const Canvas& frame) {
  const std::string head = std::to_string(frame.width()) + "x" + std::to_string(frame.height()) + ":";
  std::vector<std::uint8_t> bytes(head.begin(), head.end());
  bytes.insert(bytes.end(), frame.rgba().begin(), frame.rgba().end());
  return core::sha256Hex(bytes);
}

std::string frameJson(const LiveFrame& frame) {
  nlohmann::ordered_json j;
  j["index"] = frame.index;
  j["camera"] = render::cameraText(frame.camera);
  if (frame.lens) j["lens"] = {frame.lens->x, frame.lens->y};  // floats: nlohmann writes the shortest exact text
  j["input"] = frame.input;
  j["shown_ns"] = frame.shownNs;
  j["sha256"] = frame.sha256;
  if (!frame.encoding.empty()) j["encoding"] = frame.encoding;
  return j.dump();
}

LiveFrame parseFrameJson(const std::string& json) {
  const auto j = nlohmann::json::parse(json, nullptr, false);
  if (j.is_discarded() || !j.is_object()) throw std::invalid_argument("frame: not a JSON object");
  const auto field = [&](const char* name) -> const nlohmann::json& {
    const auto it = j.find(name);
    if (it == j.end()) throw std::invalid_argument(std::string("frame: missing field '") + name + "'");
    return *it;
  };
  LiveFrame f;
  try {
    f.index = field("index").get<int>();
    f.camera = render::parseCamera(field("camera").get<std::string>(), render::Camera{});
    if (const auto lens = j.find("lens"); lens != j.end()) {
      if (!lens->is_array() || lens->size() != 2) throw std::invalid_argument("frame: field 'lens' must be [x, y]");
      f.lens = glm::vec2((*lens)[0].get<float>(), (*lens)[1].get<float>());
    }
    f.input = field("input").get<std::string>();
    f.shownNs = field("shown_ns").get<std::int64_t>();
    f.sha256 = field("sha256").get<std::string>();
    if (const auto encoding = j.find("encoding"); encoding != j.end()) f.encoding = encoding->get<std::string>();
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(std::string("frame: ") + e.what());
  }
  if (f.sha256.size() != 64) throw std::invalid_argument("frame: field 'sha256' must be 64 hex digits");
  return f;
}

}  // namespace tlab::study
