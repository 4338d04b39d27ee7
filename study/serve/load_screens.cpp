// LoadParticipant's answers to each kind of screen (study/serve/load_participant.hpp): what a
// participant does on a message, consent, form, break and trial screen.
#include <httplib.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <thread>

#include "study/serve/load_answers.hpp"
#include "study/serve/load_participant.hpp"

namespace tlab::study {

using nlohmann::json;

json LoadParticipant::step(const json& screen) {
  const std::string kind = screen.value("kind", "");
  if (kind == "trial") return trial(screen);
  if (kind == "message" || kind == "feedback") {
    fetchImages(screen);
    think(thinkTime());
    return finishing(screen, {{"type", "continue"}});
  }
  if (kind == "break") {  // the server ignores a press before the break's minimum, as the page's disabled button does
    think(screen.value("min_seconds", 0.0) * 1000.0 + 300.0 + thinkTime());
    return finishing(screen, {{"type", "continue"}});
  }
  if (kind == "consent") {
    think(thinkTime());
    return finishing(screen, {{"type", "consent"}, {"accepted", true}});
  }
  if (kind == "form") {
    think(thinkTime());
    return finishing(screen, loadFormValues(screen, rng_));
  }
  if (kind == "calibration") {  // a card sized with a few adjustments on a 1x screen of 96 dpi
    think(thinkTime());
    return finishing(screen, {{"type", "calibration"}, {"skipped", false}, {"px_per_cm", 37.8}, {"card_css_px", 323.6},
                              {"device_pixel_ratio", 1}, {"adjustments", 3}});
  }
  throw std::runtime_error("unexpected screen kind '" + kind + "': " + screen.dump().substr(0, 200));
}

void LoadParticipant::fetchImages(const json& screen) {
  for (const std::string& sha : pageImages(screen)) {
    if (fetched_.count(sha)) continue;
    const Reply r = send("GET", "/api/" + token_ + "/image/" + sha + ".png");
    if (r.status == 404) screenOf(send("GET", "/api/" + token_ + "/screen"), "screen");  // a restarted server does not know the token
    if (r.status != 200 || r.body.empty()) throw std::runtime_error("image " + sha + ": HTTP " + std::to_string(r.status));
    fetched_.insert(sha);
  }
}

// Sends a reply that ends the screen; returns the next one (the acknowledgement). A stale screen
// (409) is not an error: the server says which screen is current.
json LoadParticipant::finishing(const json& screen, json body, bool* acknowledged) {
  body["seq"] = screen.value("seq", 0);
  const Reply r = send("POST", "/api/" + token_ + "/reply", &body);
  if (r.status == 200 && acknowledged) {
    const json next = pastWait(screenOf(r, "reply"));  // an error screen (not stored) throws here
    *acknowledged = next.value("seq", 0) > body.value("seq", 0);
    return next;
  }
  if (r.status == 409) {
    const json stale = json::parse(r.body, nullptr, false);
    if (stale.is_object() && stale.contains("screen") && stale["screen"].is_object()) return pastWait(stale["screen"]);
  }
  if (r.status == 400) throw std::runtime_error("reply refused (" + brief(r.body) + "): " + body.dump().substr(0, 200));
  return pastWait(screenOf(r, "reply"));
}

// Server-Timing: "NAME;dur=MS, NAME;dur=MS, ..." (each stage of a live frame on the server).
void LoadParticipant::noteStages(const std::string& timing) {
  std::size_t at = 0;
  while (at < timing.size()) {
    const std::size_t end = std::min(timing.find(',', at), timing.size());
    const std::string entry = timing.substr(at, end - at);
    const std::size_t dur = entry.find(";dur=");
    if (dur != std::string::npos) {
      const std::string name = entry.substr(entry.find_first_not_of(' '), dur - entry.find_first_not_of(' '));
      auto stage = std::find_if(run_.stageMs.begin(), run_.stageMs.end(), [&](const auto& s) { return s.first == name; });
      if (stage == run_.stageMs.end()) stage = run_.stageMs.insert(run_.stageMs.end(), {name, {}});
      stage->second.push_back(std::atof(entry.c_str() + dur + 5));
    }
    at = end + 1;
  }
}

// Orbiting: a drag of 8 picture pixels (2.4°) right and 1 up per frame; walking: a step forward,
// then a drag to look right, in turn. The first request has no input: the start view.
void LoadParticipant::explore(const json& screen, double ms) {
  const bool walking = screen["live"].value("navigation", "") == "walk";
  const std::string path = "/api/" + token_ + "/view";
  const auto start = std::chrono::steady_clock::now();
  const auto elapsedMs = [&start] { return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count(); };
  for (int n = 0; n == 0 || elapsedMs() < ms; ++n) {
    json input = json::object();
    if (n > 0 && walking && n % 2 == 1) input = {{"forward", 1}};
    else if (n > 0 && walking) input = {{"dx", 8}};
    else if (n > 0) input = {{"dx", 8}, {"dy", -1}};
    const json body{{"seq", screen.value("seq", 0)}, {"input", input}};
    const auto sent = std::chrono::steady_clock::now();
    const Reply r = send("POST", path, &body);
    if (r.status == 200) {
      run_.frameMs.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - sent).count());
      if (n == 0) run_.firstFrameMs.push_back(run_.frameMs.back());
      noteStages(r.timing);
      continue;
    }
    if (r.status == 409 && r.body.find("superseded") != std::string::npos) continue;
    if (r.status == 409) break;  // the trial is gone (its time ran out)
    throw std::runtime_error("view refused: HTTP " + std::to_string(r.status) + " " + brief(r.body));
  }
  run_.liveSeconds += elapsedMs() / 1000.0;
}

json LoadParticipant::trial(const json& screen) {
  fetchImages(screen);
  const std::string reply = "/api/" + token_ + "/reply";
  const json onset{{"seq", screen.value("seq", 0)}, {"type", "onset"}, {"painted_ms", 16.7}};
  if (const Reply r = send("POST", reply, &onset); r.status == 409) {
    return pastWait(json::parse(r.body, nullptr, false).value("screen", json::object()));  // the trial is gone (timed out)
  } else if (r.status != 200) {
    screenOf(r, "onset");  // 404: the server restarted
    throw std::runtime_error("onset refused: HTTP " + std::to_string(r.status) + " " + brief(r.body));
  }
  const double rt = thinkTime();
  if (screen.contains("turntable")) {  // one drag to the next view, half-way through the think time
    think(rt / 2.0);
    const json& t = screen["turntable"];
    const json view{{"seq", screen.value("seq", 0)}, {"type", "view"}, {"azimuth", (t["start"][0].get<int>() + 1) % t.value("azimuths", 1)},
                    {"elevation", t["start"][1].get<int>()}, {"t_ms", rt / 2.0}};
    send("POST", reply, &view);
    think(rt / 2.0);
  } else if (screen.contains("live")) {
    explore(screen, behaviour_.liveSeconds > 0.0 ? behaviour_.liveSeconds * 1000.0 : rt);
  } else {
    think(rt);
  }
  const json answer = loadAnswer(screen, rt, rng_);
  const auto sent = std::chrono::steady_clock::now();
  bool acknowledged = false;
  json next = finishing(screen, answer, &acknowledged);
  if (acknowledged) {
    run_.ackMs.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - sent).count());
    run_.acked.push_back({participant_, screen.value("phase", ""), screen.value("index", 0), answer.value("answer", json()).dump()});
    if (onAck_) onAck_(run_.acked.back());
  }
  return next;
}

}  // namespace tlab::study
