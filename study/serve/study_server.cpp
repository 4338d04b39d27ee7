#include "study/serve/study_server.hpp"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "core/file_text.hpp"
#include "study/serve/browser_responder.hpp"
#include "study/serve/flow_pages.hpp"
#include "study/serve/request_checks.hpp"
#include "study/serve/server_pages.hpp"
#include "study/serve/web_assets.hpp"

namespace tlab::study {

namespace {

using nlohmann::json;

constexpr const char* kToken = "([0-9a-f]{64})";
constexpr int kIdleSeconds = 120;  // a keep-alive connection with nothing to say is closed after this

void sendJson(httplib::Response& res, int status, const json& body) {
  res.status = status;
  res.set_header("Cache-Control", "no-store");
  res.set_content(jsonText(body), "application/json");
}

void refuse(httplib::Response& res, int status, const std::string& what) {
  std::fprintf(stderr, "serve: %d: %s\n", status, what.c_str());
  sendJson(res, status, {{"error", what}});
}

std::optional<json> parseBody(const httplib::Request& req, httplib::Response& res) {
  json body = json::parse(req.body, nullptr, false);
  if (body.is_discarded() || !body.is_object()) {
    refuse(res, 400, req.path + ": the body is not a JSON object");
    return std::nullopt;
  }
  return body;
}

}  // namespace

StudyServer::StudyServer(ServedStudy study, ServeOptions options, std::string adminToken)
    : study_(std::move(study)),
      options_(std::move(options)),
      adminToken_(std::move(adminToken)),
      dispatcher_(DispatchLimits{options_.threads, options_.connectionsPerAddress, std::size_t(16 * options_.threads), std::chrono::milliseconds(10000),
                                 std::chrono::milliseconds(kIdleSeconds * 1000), 16 * 1024, options_.maxBodyBytes},
                  [this](int fd, std::size_t bytes) { return http_.answer(fd, bytes, 10); }),
      replays_(std::filesystem::read_symlink("/proc/self/exe").string(), study_.store.location(), study_.experiment.id) {
  http_.set_payload_max_length(options_.maxBodyBytes);
  http_.set_keep_alive_timeout(kIdleSeconds);  // what the Keep-Alive header tells the browser: the dispatcher's idle time-out
  http_.set_default_headers({{"X-Content-Type-Options", "nosniff"},
                             {"Referrer-Policy", "no-referrer"},
                             {"X-Frame-Options", "DENY"},
                             {"Content-Security-Policy", "default-src 'self'; img-src 'self' blob:; style-src 'self'; script-src 'self'"}});
  http_.set_exception_handler([this](const httplib::Request& req, httplib::Response& res, std::exception_ptr ep) {
    std::string what = "unknown error";
    try {
      std::rethrow_exception(ep);
    } catch (const std::exception& e) {
      what = e.what();
    } catch (...) {
    }
    if (req.path.rfind("/api/", 0) == 0) return refuse(res, 500, req.method + " " + req.path + ": " + what);
    std::fprintf(stderr, "serve: 500: %s %s: %s\n", req.method.c_str(), req.path.c_str(), what.c_str());
    res.status = 500;  // a page for people: what happened, in words, and what to do
    const ParticipantTexts& t = study_.experiment.texts;
    res.set_content(messagePage(t.text("arrival.try_again_title"), t.text("arrival.try_again"), t.language()), "text/html; charset=utf-8");
  });
  routes();
}

StudyServer::~StudyServer() {
  stop();
  std::lock_guard lock(mutex_);
  for (auto& [token, s] : byToken_) s->stop();
}

int StudyServer::bind() { return options_.port = dispatcher_.bind(options_.host, options_.port); }

void StudyServer::listen() { dispatcher_.run(); }

void StudyServer::stop() { dispatcher_.stop(); }

std::shared_ptr<ParticipantSession> StudyServer::session(const std::string& token) {
  std::lock_guard lock(mutex_);
  const auto it = byToken_.find(token);
  return it == byToken_.end() ? nullptr : it->second;
}

std::shared_ptr<ParticipantSession> StudyServer::admitted(const httplib::Request& req, httplib::Response& res) {
  const auto s = session(req.matches[1]);
  if (!s) {
    refuse(res, 404, "no such session");
    return nullptr;
  }
  if (!s->admit(browserKey(req.get_header_value("Cookie")))) {
    refuse(res, 403, "other browser: this session is open in another browser");
    return nullptr;
  }
  s->channel()->touch();  // only the session's own browser keeps it alive
  return s;
}

bool StudyServer::isAdmin(const httplib::Request& req) const {
  const std::string given = req.has_param("token") ? req.get_param_value("token") : "";
  if (given.size() != adminToken_.size()) return false;
  unsigned diff = 0;  // constant time: the comparison does not tell how many characters matched
  for (std::size_t i = 0; i < given.size(); ++i) diff |= unsigned(given[i] ^ adminToken_[i]);
  return diff == 0;
}

void StudyServer::routes() {
  pageRoutes();
  apiRoutes();
  adminRoutes();
}

// What a browser opens: the static files, the arrival link and the participant page.
void StudyServer::pageRoutes() {
  auto asset = [](const char* name, const char* type) {
    return [name, type](const httplib::Request&, httplib::Response& res) { res.set_content(std::string(webAsset(name)), type); };
  };
  http_.Get("/static/participant.js", asset("participant.js", "text/javascript; charset=utf-8"));
  http_.Get("/static/participant.css", asset("participant.css", "text/css; charset=utf-8"));
  http_.Get("/", [this](const httplib::Request&, httplib::Response& res) {
    res.set_content(messagePage("tlab serve", "Participants start at /s/" + study_.experiment.id + "?" +
                                                  study_.experiment.online.participantParameter + "=THEIR-ID"),
                    "text/html; charset=utf-8");
  });
  http_.Get("/s/([^/]+)", [this](const httplib::Request& req, httplib::Response& res) { arrive(req, res); });
  http_.Get(std::string("/p/") + kToken, [this](const httplib::Request& req, httplib::Response& res) {
    if (!session(req.matches[1])) {
      res.status = 404;
      const ParticipantTexts& t = study_.experiment.texts;
      res.set_content(messagePage(t.text("arrival.not_found_title"), t.text("arrival.no_session"), t.language()), "text/html; charset=utf-8");
      return;
    }
    res.set_header("Cache-Control", "no-store");
    res.set_content(participantPage(study_.experiment.texts), "text/html; charset=utf-8");
  });
}

// The participant page's JSON API: every route is bound to one session token.
void StudyServer::apiRoutes() {
  http_.Get(std::string("/api/") + kToken + "/screen", [this](const httplib::Request& req, httplib::Response& res) {
    const auto s = admitted(req, res);
    if (!s) return;
    sendJson(res, 200, s->channel()->current());
  });
  http_.Get(std::string("/api/") + kToken + "/config", [this](const httplib::Request& req, httplib::Response& res) {
    if (!admitted(req, res)) return;
    const Experiment& e = study_.experiment;
    sendJson(res, 200, {{"title", e.participantTitle.empty() ? e.texts.text("title.page") : e.participantTitle},
                        {"calibrate", e.online.sizeCalibration},
                        {"language", e.texts.language()},
                        {"stimulus_size", {{"mode", e.online.stimulusSize}, {"cm", e.online.stimulusCm},
                                           {"width", e.stimulus.width}, {"height", e.stimulus.height}}},
                        {"devices", e.online.devices}});
  });
  http_.Post(std::string("/api/") + kToken + "/display", [this](const httplib::Request& req, httplib::Response& res) {
    const auto s = admitted(req, res);
    if (!s) return;
    const auto body = parseBody(req, res);
    if (!body) return;
    if (const auto error = checkDisplay(*body)) return refuse(res, 400, "display: " + *error);
    if (const auto refusal = deviceRefusal(study_.experiment, *body)) {  // nothing stored: they may come back on another device
      std::fprintf(stderr, "serve: participant '%s': a %s is not allowed by [online] devices; refused\n", s->participant().c_str(),
                   body->value("device", "").c_str());
      s->release();
      return sendJson(res, 200, *refusal);
    }
    s->start(study_, *body);
    sendJson(res, 200, s->channel()->awaitScreenAfter(0, std::chrono::milliseconds(15000)));
  });
  http_.Post(std::string("/api/") + kToken + "/reply", [this](const httplib::Request& req, httplib::Response& res) {
    const auto s = admitted(req, res);
    if (!s) return;
    reply(*s, req, res);
  });
  http_.Post(std::string("/api/") + kToken + "/view", [this](const httplib::Request& req, httplib::Response& res) {
    const auto s = admitted(req, res);
    if (!s) return;
    view(*s, req, res);
  });
  http_.Get(std::string("/api/") + kToken + "/image/([0-9a-f]{64})\\.png", [this](const httplib::Request& req, httplib::Response& res) {
    const auto s = admitted(req, res);
    if (!s) return;
    const std::string sha = req.matches[2];
    if (!s->channel()->mayFetch(sha)) return refuse(res, 404, "no such image for this session");
    const auto path = study_.worker.imagePath(sha);
    if (!path) return refuse(res, 404, "no such image");
    const auto png = core::readFileText(*path);
    if (!png) return refuse(res, 500, "cannot read " + *path);
    res.set_header("Cache-Control", "private, max-age=86400, immutable");
    res.set_content(*png, "image/png");
  });
}

void StudyServer::adminRoutes() {
  http_.Get("/admin", [this](const httplib::Request& req, httplib::Response& res) { admin(req, res); });
  http_.Get("/admin/status.json", [this](const httplib::Request& req, httplib::Response& res) {
    if (!isAdmin(req)) return refuse(res, 403, "admin: wrong or missing token");
    sendJson(res, 200, status());
  });
  http_.Post("/admin/(drop|extend)", [this](const httplib::Request& req, httplib::Response& res) { adminAction(req, res); });
  http_.Get("/admin/replay", [this](const httplib::Request& req, httplib::Response& res) { adminReplay(req, res); });
  http_.Get("/admin/replays/([0-9a-f]{32})/(.*)", [this](const httplib::Request& req, httplib::Response& res) { replayFile(req, res); });
  http_.Get("/admin/drop", [this](const httplib::Request& req, httplib::Response& res) {  // the confirmation before a drop
    if (!isAdmin(req)) {
      res.status = 403;
      return res.set_content(messagePage("Forbidden", "wrong or missing admin token"), "text/html; charset=utf-8");
    }
    res.set_header("Cache-Control", "no-store");
    res.set_content(dropConfirmationPage(req.has_param("participant") ? req.get_param_value("participant") : "", adminToken_), "text/html; charset=utf-8");
  });
}

void StudyServer::arrive(const httplib::Request& req, httplib::Response& res) {
  const Experiment& e = study_.experiment;
  const ParticipantTexts& t = e.texts;
  auto page = [&res, &t](int status, const std::string& title, const std::string& text) {
    res.status = status;
    res.set_content(messagePage(t.text(title), text, t.language()), "text/html; charset=utf-8");
  };
  if (req.matches[1] != e.id) return page(404, "arrival.not_found_title", t.text("arrival.no_study"));
  const std::string& parameter = e.online.participantParameter;
  const std::string id = req.has_param(parameter.c_str()) ? req.get_param_value(parameter.c_str()) : "";
  if (!validParticipantId(id)) return page(400, "arrival.incomplete_title", t.format("arrival.incomplete", {{"parameter", parameter}}));
  // The store first: a participant who finished (declined, was dropped) in this server's run has a
  // session in memory too, whose walk would be refused by the runner if it started again.
  const auto existing = study_.store.findParticipant(e.id, id);
  if (existing && existing->status == "finished") {  // the code and the link again: the participant may not have copied them
    res.status = 409;
    return res.set_content(
        completionPage(t.text("arrival.completed_title"), t.text("arrival.completed"), e.debrief.completionCode, e.online.completionUrl, t),
        "text/html; charset=utf-8");
  }
  if (existing && existing->status == "declined") return page(409, "arrival.declined_title", t.text("arrival.declined"));
  if (existing && existing->status == "dropped") return page(409, "arrival.ended_title", t.text("arrival.ended"));
  std::shared_ptr<ParticipantSession> s;
  {
    std::lock_guard lock(mutex_);
    if (const auto it = byParticipant_.find(id); it != byParticipant_.end()) s = it->second;
  }
  if (!s) {
    std::vector<std::pair<std::string, std::string>> link;
    for (const std::string& p : {e.online.studyParameter, e.online.sessionParameter})
      if (!p.empty() && req.has_param(p.c_str())) link.emplace_back(p, req.get_param_value(p.c_str()));
    const json arrival = arrivalRecord(id, req.get_header_value("User-Agent"), link);
    const auto timeout = std::chrono::milliseconds(std::int64_t(e.online.timeoutMinutes * 60000.0));
    std::lock_guard lock(mutex_);
    auto& slot = byParticipant_[id];
    if (!slot) {
      slot = std::make_shared<ParticipantSession>(id, newToken(), arrival, timeout);
      byToken_[slot->token()] = slot;
    }
    s = slot;
  }
  res.set_redirect("/p/" + s->token(), 303);
}

void StudyServer::reply(ParticipantSession& session, const httplib::Request& req, httplib::Response& res) {
  const auto body = parseBody(req, res);
  if (!body) return;
  const std::int64_t receivedNs = monotonicNs();
  const auto channel = session.channel();
  const auto seq = body->find("seq");
  if (seq == body->end() || !seq->is_number_integer()) return refuse(res, 400, "reply: 'seq' (the screen's number) is missing");
  std::string error;
  nlohmann::json refusal;
  switch (channel->deliver(seq->get<int>(), *body, receivedNs, error, &refusal)) {
    case SessionChannel::Delivery::Stale: return sendJson(res, 409, {{"error", error}, {"screen", channel->current()}});
    case SessionChannel::Delivery::Refused:
      std::fprintf(stderr, "serve: 400: participant '%s': reply refused, not stored (kept as a refused-reply event): %s\n", session.participant().c_str(),
                   error.c_str());
      return sendJson(res, 400, refusal.is_null() ? nlohmann::json{{"error", error}} : nlohmann::json{{"error", error}, {"refusal", refusal}});
    case SessionChannel::Delivery::Delivered: break;
  }
  const std::string type = body->value("type", "");
  if (type == "onset" || type == "view")  // acknowledged once the session thread stored it
    return sendJson(res, 200, {{"ok", channel->awaitHandled(std::chrono::milliseconds(5000))}});
  // The next screen comes after the runner stored this reply: it is the acknowledgement.
  sendJson(res, 200, channel->awaitScreenAfter(seq->get<int>(), std::chrono::milliseconds(15000)));
}

}  // namespace tlab::study
