// POST /api/<token>/view of StudyServer (study_server.hpp): a live trial's input in, its next frame
// out (live_frames.hpp), apart from the other routes.
#include <chrono>
#include <cstdio>
#include <utility>

#include "study/serve/frame_jpeg.hpp"
#include "study/serve/frame_png.hpp"
#include "study/serve/live_frames.hpp"
#include "study/serve/request_checks.hpp"
#include "study/serve/study_server.hpp"

namespace tlab::study {

namespace {

using nlohmann::json;

void sendJson(httplib::Response& res, int status, const json& body) {
  res.status = status;
  res.set_header("Cache-Control", "no-store");
  res.set_content(jsonText(body), "application/json");
}

void refuse(httplib::Response& res, const std::string& what) {  // 400, said on stderr as the server's other refusals
  std::fprintf(stderr, "serve: 400: %s\n", what.c_str());
  sendJson(res, 400, {{"error", what}});
}

// "parse;dur=0.012, wait;dur=0.004, ..." (Server-Timing, milliseconds).
std::string serverTiming(const StageTimes& times) {
  std::string out;
  for (const auto& [name, ms] : times) {
    char entry[64];
    std::snprintf(entry, sizeof entry, "%s%s;dur=%.3f", out.empty() ? "" : ", ", name.c_str(), ms);
    out += entry;
  }
  return out;
}

}  // namespace

// The frame is logged (a "frame" event of the trial: camera, lens, input, pixel SHA-256, how it was
// encoded ([online] frames: PNG, or JPEG at its quality), and as its shown time the server's clock
// when it is handed to the connection) before it is sent; a frame
// of a trial that has ended meanwhile is neither logged nor sent.
void StudyServer::view(ParticipantSession& session, const httplib::Request& req, httplib::Response& res) {
  const auto received = std::chrono::steady_clock::now();
  auto stage = received;
  const auto lap = [&stage] {  // milliseconds since the last lap
    const auto now = std::chrono::steady_clock::now();
    return std::chrono::duration<double, std::milli>(now - std::exchange(stage, now)).count();
  };
  const json parsed = json::parse(req.body, nullptr, false);
  if (parsed.is_discarded() || !parsed.is_object()) return refuse(res, req.path + ": the body is not a JSON object");
  const json* body = &parsed;
  const auto seq = body->find("seq");
  if (seq == body->end() || !seq->is_number_integer()) return refuse(res, "view: 'seq' (the screen's number) is missing");
  ViewInput input;
  try {
    input = parseViewInput(body->contains("input") ? (*body)["input"] : json::object());
  } catch (const std::exception& e) {
    return refuse(res, std::string("view: ") + e.what());
  }
  const auto channel = session.channel();
  const auto trial = channel->liveTrial(seq->get<int>());
  if (!trial) return sendJson(res, 409, {{"error", "view: the screen on show is not this live trial"}, {"screen", channel->current()}});
  StageTimes times{{"parse", lap()}};
  LiveAnswer a = study_.worker.liveFrame({session.token(), trial, input});
  if (a.status == LiveAnswer::Status::Superseded) return sendJson(res, 409, {{"error", "view: superseded by newer input"}, {"superseded", true}});
  lap();
  times.insert(times.end(), a.stagesMs.begin(), a.stagesMs.end());
  // The hash and the PNG here, on this request's thread: the GL worker renders the next frame meanwhile.
  a.frame.sha256 = framePixelsSha256(*a.pixels);
  times.emplace_back("hash", lap());
  const OnlineSpec& online = study_.experiment.online;
  const bool jpeg = online.frames == "jpeg";
  std::string encoded = jpeg ? encodeFrameJpeg(*a.pixels, online.jpegQuality) : encodeFramePng(*a.pixels);
  a.frame.encoding = jpeg ? "jpeg quality=" + std::to_string(online.jpegQuality) : "png";
  times.emplace_back("encode", lap());
  a.frame.shownNs = monotonicNs();
  if (!channel->noteFrame(seq->get<int>(), trial, a.frame.shownNs, frameJson(a.frame)))
    return sendJson(res, 409, {{"error", "view: the trial has ended"}, {"screen", channel->current()}});
  times.emplace_back("log", lap());
  times.emplace_back("total", std::chrono::duration<double, std::milli>(stage - received).count());
  res.set_header("Cache-Control", "no-store");
  res.set_header("Server-Timing", serverTiming(times));
  res.set_header("X-Frame-Index", std::to_string(a.frame.index));
  res.set_header("X-Frame-Sha256", a.frame.sha256);
  res.set_header("X-Frame-Encoding", a.frame.encoding);
  res.set_content(std::move(encoded), jpeg ? "image/jpeg" : "image/png");
}

}  // namespace tlab::study
