// StudyServer's admin side: progress per slot against the target, what each live session shows
// (screen, elapsed and idle time), answered and missing responses, drop (after a confirmation) and
// extend, and the interactive trials with logged frames, each with a link to its replay (rendered
// on demand by a child process, study/serve/replay_jobs.hpp) and the `tlab replay` command that
// makes it on the researcher's machine.
#include <algorithm>
#include <cmath>
#include <cctype>
#include <cstdio>
#include <optional>

#include "analysis/number_format.hpp"
#include "core/file_text.hpp"
#include "study/analyze/replay_listing.hpp"
#include "study/run/session_wording.hpp"

#include "study/serve/server_pages.hpp"
#include "study/serve/study_server.hpp"

namespace tlab::study {

namespace {

// What a live session shows now: the screen's kind, a trial with its place ("trial 3 of 10").
std::string screenText(const nlohmann::json& page) {
  const std::string kind = page.value("kind", "wait");
  if (kind != "trial") return kind;
  const std::string phase = page.value("phase", "") == "training" ? "training " : "trial ";
  return phase + std::to_string(page.value("index", 0)) + " of " + std::to_string(page.value("total", 0));
}

// Per participant: answered and missing responses of test trials stored (training is not analysed).
std::map<std::string, std::pair<int, int>> answeredAndMissing(Store& store, const std::string& experimentId) {
  std::map<std::string, std::pair<int, int>> out;
  for (const auto& r : store.analysisRecords(experimentId, "answered")) {
    auto& [answered, missing] = out[r.participant];
    (r.value != 0.0 ? answered : missing) += 1;
  }
  return out;
}

// The live part of a participant's row: session state, screen, elapsed and idle seconds.
void addLive(nlohmann::json& row, const ParticipantSession* session) {
  if (!session) {
    row.update({{"session", "not connected to this server"}, {"screen", ""}, {"elapsed_s", nullptr}, {"idle_s", nullptr}});
    return;
  }
  const auto channel = session->channel();
  const auto elapsed = session->elapsedSeconds();
  row.update({{"session", session->state()},
              {"screen", screenText(channel->current())},
              {"elapsed_s", elapsed ? nlohmann::json(std::round(*elapsed)) : nlohmann::json()},
              {"idle_s", std::round(channel->idleSeconds())}});
}

// Per participant, the interactive trials whose live frames were logged, with the command that
// replays each on the researcher's machine (the admin page links each to a replay made here by a
// child process at the lowest priority: the server's GL worker serves participants only).
nlohmann::json replays(Store& store, const std::string& experimentId) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& t : replayableTrials(store, experimentId))
    out.push_back({{"participant", t.participant}, {"trial", t.sequence}, {"phase", t.phase}, {"task", t.taskId}, {"frames", t.frames},
                   {"command", replayCommand(store.location(), t)}});
  return out;
}

// "%41%20b": a query parameter's value as a URL carries it.
std::string urlEncoded(const std::string& text) {
  static constexpr char hex[] = "0123456789ABCDEF";
  std::string out;
  for (unsigned char c : text) {
    if (std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == '~') out += char(c);
    else out += {'%', hex[c >> 4], hex[c & 15]};
  }
  return out;
}

// The admin page's link that makes (or finds) a trial's replay and opens it.
std::string replayLink(const nlohmann::json& r, const std::string& adminToken) {
  return "/admin/replay?token=" + adminToken + "&participant=" + urlEncoded(r["participant"].get<std::string>()) +
         "&trial=" + r["trial"].dump();
}

// The admin page's section of replays, placed before the end of its main part.
std::string withReplays(std::string page, const nlohmann::json& replays, const std::string& adminToken) {
  using analysis::escapeHtml;
  std::string section = "<h2>Replays of interactive trials</h2><p>Every frame a participant was shown in an interactive trial is "
                        "logged. <em>replay</em> renders them again here (at the lowest priority, beside the participants' "
                        "frames), checks each against its logged SHA-256 and shows a page with the frames, the inputs, the timing "
                        "and the answer; the command does the same on your machine (add <code>-o replay.webm</code> for a video).</p>"
                        "<table id=\"replays\"><tr><th>participant</th><th>trial</th><th>phase</th><th>task</th><th>frames</th><th>replay</th>"
                        "<th>command</th></tr>";
  for (const auto& r : replays)
    section += "<tr><td>" + escapeHtml(r["participant"].get<std::string>()) + "</td><td>" + r["trial"].dump() + "</td><td>" +
               escapeHtml(r["phase"].get<std::string>()) + "</td><td>" + escapeHtml(r["task"].get<std::string>()) + "</td><td>" +
               r["frames"].dump() + "</td><td><a href=\"" + escapeHtml(replayLink(r, adminToken)) + "\">replay</a></td><td><code>" +
               escapeHtml(r["command"].get<std::string>()) + "</code></td></tr>";
  if (replays.empty()) section += "<tr><td colspan=\"7\">none yet</td></tr>";
  section += "</table>";
  const auto end = page.rfind("</main>");
  return end == std::string::npos ? page : page.insert(end, section);
}

}  // namespace

nlohmann::json StudyServer::status() {
  const Experiment& e = study_.experiment;
  std::map<std::string, std::shared_ptr<ParticipantSession>> live;
  {
    std::lock_guard lock(mutex_);
    live = byParticipant_;
  }
  const auto counts = answeredAndMissing(study_.store, e.id);
  nlohmann::json slots = nlohmann::json::array();
  int running = 0, idle = 0, finished = 0, answered = 0, missing = 0;
  for (const auto& a : study_.store.assignments(e.id)) {
    int done = 0, total = 0;
    if (const auto p = study_.store.findParticipant(e.id, a.participant))
      for (const auto& t : study_.store.trials(p->id)) {
        ++total;
        done += t.answered ? 1 : 0;
      }
    const auto c = counts.count(a.participant) ? counts.at(a.participant) : std::pair<int, int>{0, 0};
    nlohmann::json row{{"slot", a.slot}, {"participant", a.participant}, {"status", a.status}, {"answered", c.first}, {"missing", c.second},
                       {"trials", std::to_string(done) + "/" + std::to_string(total)}};
    const auto s = live.find(a.participant);
    addLive(row, s == live.end() ? nullptr : s->second.get());
    running += row["session"] == "running";
    idle += row["session"] == "idle";
    finished += a.status == "finished" ? 1 : 0;
    answered += c.first;
    missing += c.second;
    slots.push_back(row);
  }
  // Who arrived but has no slot yet: at the welcome or the consent (a newcomer is enrolled once they agree).
  nlohmann::json arrived = nlohmann::json::array();
  for (const auto& [participant, session] : live) {
    bool assigned = false;
    for (const auto& s : slots) assigned = assigned || s["participant"] == participant;
    if (assigned) continue;
    nlohmann::json row{{"participant", participant}};
    addLive(row, session.get());
    running += row["session"] == "running";
    idle += row["session"] == "idle";
    arrived.push_back(row);
  }
  const int target = std::max(e.participants, 1);
  const std::string summary = countOf(long(slots.size()), "slot", "slots") + " assigned, " + std::to_string(finished) + " of " +
                              countOf(target, "participant", "participants") + " finished (the target); " + std::to_string(running) +
                              " running now, " + std::to_string(idle) + " idle; " + countOf(answered, "answer", "answers") + " and " +
                              countOf(missing, "missing response", "missing responses") + " to test trials stored; " +
                              countOf(long(live.size()), "participant", "participants") + " arrived at this server";
  return {{"experiment", e.id}, {"summary", summary}, {"slots", slots}, {"arrived", arrived}, {"target", target}, {"finished", finished},
          {"running", running}, {"idle", idle}, {"responses", answered + missing}, {"answered", answered}, {"missing", missing},
          {"replays", replays(study_.store, e.id)}};
}

void StudyServer::admin(const httplib::Request& req, httplib::Response& res) {
  if (!isAdmin(req)) {
    res.status = 403;
    res.set_content(messagePage("Forbidden", "The admin page needs the admin token printed when the server started."), "text/html; charset=utf-8");
    return;
  }
  res.set_header("Cache-Control", "no-store");
  const nlohmann::json now = status();
  res.set_content(withReplays(adminPage(now, adminToken_), now["replays"], adminToken_), "text/html; charset=utf-8");
}

void StudyServer::adminReplay(const httplib::Request& req, httplib::Response& res) {
  const auto page = [&](int status, const std::string& title, const std::string& text) {
    res.status = status;
    res.set_content(messagePage(title, text), "text/html; charset=utf-8");
  };
  if (!isAdmin(req)) return page(403, "Forbidden", "wrong or missing admin token");
  const std::string participant = req.has_param("participant") ? req.get_param_value("participant") : "";
  const std::string trial = req.has_param("trial") ? req.get_param_value("trial") : "";
  std::optional<ReplayableTrial> found;
  for (const auto& t : replayableTrials(study_.store, study_.experiment.id))
    if (t.participant == participant && std::to_string(t.sequence) == trial) found = t;
  if (!found) return page(404, "No such replay", "participant '" + participant + "' has no trial " + trial + " with live frames logged");
  try {
    const std::string key = replays_.request(found->participant, found->sequence, found->frames);
    res.set_redirect("/admin/replays/" + key + "/", 303);
  } catch (const ReplayBusy& busy) {
    res.set_header("Retry-After", "5");
    page(503, "Replays busy", busy.what());
  }
}

void StudyServer::replayFile(const httplib::Request& req, httplib::Response& res) {
  const std::string key = req.matches[1], name = req.matches[2];
  const auto notFound = [&](const std::string& what) {
    res.status = 404;
    res.set_content(messagePage("Not found", what), "text/html; charset=utf-8");
  };
  const auto state = replays_.state(key);
  if (!state) return notFound("no such replay");
  res.set_header("Cache-Control", "no-store");
  if (name.empty()) {  // the replay's own address: its progress until its page is there
    const std::string what = "trial " + std::to_string(state->sequence) + " of participant '" + state->participant + "' (" +
                             std::to_string(state->frames) + " frames)";
    switch (state->kind) {
      case ReplayJobState::Kind::Rendering:
        res.set_header("Refresh", "2");
        return res.set_content(messagePage("Rendering the replay", "Rendering " + what + " again at the lowest priority; this page "
                                           "opens the replay when it is done."), "text/html; charset=utf-8");
      case ReplayJobState::Kind::Failed:
        res.status = 500;
        return res.set_content(messagePage("The replay failed", "The replay of " + what + " failed: " + state->message), "text/html; charset=utf-8");
      case ReplayJobState::Kind::Done:
        return res.set_redirect("replay.html", 303);
    }
  }
  const auto path = replays_.file(key, name);
  const auto content = path ? core::readFileText(path->string()) : std::nullopt;
  if (!content) return notFound("no such file of this replay");
  const bool html = name == "replay.html";
  if (html) {  // the replay page's player and its style are inline; it loads only its own frames
    res.headers.erase("Content-Security-Policy");
    res.set_header("Content-Security-Policy", "default-src 'none'; img-src 'self'; style-src 'unsafe-inline'; script-src 'unsafe-inline'");
  }
  res.set_content(*content, html ? "text/html; charset=utf-8" : "image/png");
}

void StudyServer::adminAction(const httplib::Request& req, httplib::Response& res) {
  if (!isAdmin(req)) {
    res.status = 403;
    res.set_content(messagePage("Forbidden", "wrong or missing admin token"), "text/html; charset=utf-8");
    return;
  }
  const std::string action = req.matches[1];
  const std::string participant = req.has_param("participant") ? req.get_param_value("participant") : "";
  std::shared_ptr<ParticipantSession> s;
  {
    std::lock_guard lock(mutex_);
    if (const auto it = byParticipant_.find(participant); it != byParticipant_.end()) s = it->second;
  }
  if (action == "drop") {
    if (s) s->drop(study_, "dropped by the researcher");
    else study_.store.dropParticipant(study_.experiment.id, participant, "dropped by the researcher");
    std::fprintf(stderr, "serve: admin dropped participant '%s'; the slot is free again\n", participant.c_str());
  } else {
    const std::string minutes = req.has_param("minutes") ? req.get_param_value("minutes") : "";
    char* end = nullptr;
    const double m = std::strtod(minutes.c_str(), &end);
    if (!s || end == minutes.c_str() || *end != '\0' || !(m > 0 && m <= 7 * 24 * 60)) {
      res.status = 400;
      res.set_content(messagePage("Not extended", "extend needs a participant connected to this server and minutes in (0, 10080]"), "text/html; charset=utf-8");
      return;
    }
    s->channel()->extend(std::chrono::milliseconds(std::int64_t(m * 60000.0)));
    std::fprintf(stderr, "serve: admin gave participant '%s' %g more minutes\n", participant.c_str(), m);
  }
  res.set_redirect("/admin?token=" + adminToken_, 303);
}

}  // namespace tlab::study
