#include "study/serve/load_participant.hpp"

#include <httplib.h>

#include <stdexcept>
#include <thread>

#include "study/serve/load_answers.hpp"

namespace tlab::study {

namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

void sleepMs(double ms) { std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(ms)); }

}  // namespace

std::string LoadParticipant::brief(const std::string& body) { return body.substr(0, std::min<std::size_t>(body.find('\n'), 300)); }

LoadTarget parseLoadTarget(const std::string& url, const std::string& parameter) {
  const std::string scheme = "http://";
  if (url.rfind(scheme, 0) != 0) throw std::invalid_argument("URL: expected http://HOST:PORT/s/EXPERIMENT, got '" + url + "'");
  const auto slash = url.find('/', scheme.size());
  if (slash == std::string::npos || slash == scheme.size() || url.find('?') != std::string::npos)
    throw std::invalid_argument("URL: expected http://HOST:PORT/s/EXPERIMENT (the link without ?" + parameter + "=), got '" + url + "'");
  return {url.substr(0, slash), url.substr(slash), parameter};
}

LoadParticipant::LoadParticipant(LoadTarget target, std::string participant, std::uint64_t seed, LoadBehaviour behaviour,
                                 std::function<void(const AckedTrial&)> onAck)
    : target_(std::move(target)), participant_(std::move(participant)), rng_(seed), behaviour_(behaviour), onAck_(std::move(onAck)) {}

LoadParticipant::~LoadParticipant() = default;

LoadParticipant::Reply LoadParticipant::send(const std::string& method, const std::string& path, const json* body) {
  if (!client_) {
    client_ = std::make_unique<httplib::Client>(target_.origin);
    client_->set_keep_alive(true);
    client_->set_tcp_nodelay(true);  // a browser does not wait for delayed ACKs (Nagle) either
    client_->set_connection_timeout(5, 0);
    client_->set_read_timeout(30, 0);  // a reply waits for the next screen (up to 15 s on the server)
  }
  const auto start = Clock::now();
  const httplib::Result r = method == "GET" ? client_->Get(path.c_str()) : client_->Post(path.c_str(), body ? body->dump() : "{}", "application/json");
  run_.requestMs.push_back(msSince(start));
  if (!r) {
    client_.reset();  // a fresh connection next time
    throw ConnectionLost(method + " " + path + ": " + httplib::to_string(r.error()));
  }
  if (r->status >= 500) throw ConnectionLost(method + " " + path + ": HTTP " + std::to_string(r->status) + " " + brief(r->body));
  return {r->status, r->body, r->get_header_value("Location"), r->get_header_value("Server-Timing")};
}

double LoadParticipant::thinkTime() {
  if (behaviour_.thinkMs <= 0.0) return 0.0;
  // Exponential around the mean, capped so one participant cannot stall a run.
  return std::min(std::exponential_distribution<double>(1.0 / behaviour_.thinkMs)(rng_), 10.0 * behaviour_.thinkMs);
}

void LoadParticipant::think(double ms) { sleepMs(ms); }

// Arrives through the link (a resumed participant gets the same or, after a restart, a new
// token), loads the page as the browser does and reports the display when the session waits
// for it (a new session, or one whose flow stopped on a server error).
json LoadParticipant::arrive() {
  const std::string link = target_.arrivalPath + "?" + target_.parameter + "=" + participant_;
  const Reply a = send("GET", link);
  if (a.status == 409 && arrived_ && a.body.find("Already completed") != std::string::npos) return {{"kind", "end"}, {"seq", 0}};
  if (a.status == 404 && a.body.find("no study") == std::string::npos) throw ConnectionLost("GET " + link + ": 404");
  if (a.status != 303 || a.location.rfind("/p/", 0) != 0)
    throw std::runtime_error("GET " + link + ": HTTP " + std::to_string(a.status) + " (expected 303 to /p/TOKEN)");
  arrived_ = true;
  token_ = a.location.substr(3);
  for (const std::string& page : {a.location, std::string("/static/participant.js"), std::string("/static/participant.css")})
    if (const Reply p = send("GET", page); p.status != 200) throw ConnectionLost("GET " + page + ": HTTP " + std::to_string(p.status));
  const std::string api = "/api/" + token_ + "/";
  if (const Reply c = send("GET", api + "config"); c.status != 200) throw ConnectionLost("GET config: HTTP " + std::to_string(c.status));
  json screen = screenOf(send("GET", api + "screen"), "screen");
  if (screen.value("seq", 0) == 0 || screen.value("kind", "") == "error") {
    const json display{{"screen_width", 1920}, {"screen_height", 1080}, {"window_width", 1600}, {"window_height", 900},
                       {"device_pixel_ratio", 1}, {"user_agent", "tlab loadtest"}, {"refresh_hz", 60}};
    const auto sent = Clock::now();
    screen = screenOf(send("POST", api + "display", &display), "display");
    run_.startMs.push_back(msSince(sent));
  }
  return pastWait(screen);
}

json LoadParticipant::screenOf(const Reply& r, const std::string& what) {
  if (r.status == 404) throw ConnectionLost(what + ": HTTP 404 (the server no longer knows this session)");
  const json body = json::parse(r.body, nullptr, false);
  if (r.status != 200 || !body.is_object())
    throw std::runtime_error(what + ": HTTP " + std::to_string(r.status) + " " + brief(r.body));
  return body;
}

// A "wait" screen is the server storing or preparing: poll as the page does (faster).
json LoadParticipant::pastWait(json screen) {
  while (screen.value("kind", "") == "wait") {
    sleepMs(25);
    screen = screenOf(send("GET", "/api/" + token_ + "/screen"), "screen");
  }
  if (screen.value("kind", "") == "error") throw ConnectionLost("the server shows an error screen: " + screen.value("text", ""));
  return screen;
}

json LoadParticipant::recover(std::string why) {
  const auto until = Clock::now() + std::chrono::duration<double>(behaviour_.retrySeconds);
  double backoffMs = 50.0;
  for (;;) {
    if (behaviour_.retrySeconds <= 0.0 || Clock::now() >= until)
      throw std::runtime_error(why + (behaviour_.retrySeconds > 0.0 ? " (still failing after the retry budget)" : ""));
    sleepMs(backoffMs);
    backoffMs = std::min(backoffMs * 2.0, 1000.0);
    ++run_.reconnects;
    try {
      return arrive();
    } catch (const ConnectionLost& e) {
      why = e.what();
    }
  }
}

ParticipantRun LoadParticipant::walk() {
  try {
    json screen;
    try {
      screen = arrive();
    } catch (const ConnectionLost& e) {
      screen = recover(e.what());
    }
    while (screen.value("kind", "") != "end") {
      try {
        screen = step(screen);
      } catch (const ConnectionLost& e) {
        screen = recover(e.what());
      }
    }
    run_.finished = true;
  } catch (const std::exception& e) {
    run_.error = "participant " + participant_ + ": " + e.what();
  }
  return std::move(run_);
}

}  // namespace tlab::study
