// StudyServer's admin side: progress per slot, live counts, drop and extend.
#include <cstdio>

#include "study/serve/server_pages.hpp"
#include "study/serve/study_server.hpp"

namespace tlab::study {

nlohmann::json StudyServer::status() {
  const Experiment& e = study_.experiment;
  std::map<std::string, std::shared_ptr<ParticipantSession>> live;
  {
    std::lock_guard lock(mutex_);
    live = byParticipant_;
  }
  nlohmann::json slots = nlohmann::json::array();
  int running = 0, finished = 0, answered = 0;
  for (const auto& a : study_.store.assignments(e.id)) {
    int done = 0, total = 0;
    if (const auto p = study_.store.findParticipant(e.id, a.participant))
      for (const auto& t : study_.store.trials(p->id)) {
        ++total;
        done += t.answered ? 1 : 0;
      }
    const auto s = live.find(a.participant);
    const std::string session = s == live.end() ? "not connected to this server" : s->second->state();
    running += session == "running" ? 1 : 0;
    finished += a.status == "finished" ? 1 : 0;
    answered += done;
    slots.push_back({{"slot", a.slot}, {"participant", a.participant}, {"status", a.status}, {"answered", std::to_string(done) + "/" + std::to_string(total)},
                     {"session", session}});
  }
  // Who arrived but has no slot yet: at the welcome or the consent (a newcomer is enrolled once they agree).
  nlohmann::json arrived = nlohmann::json::array();
  for (const auto& [participant, session] : live) {
    bool assigned = false;
    for (const auto& s : slots) assigned = assigned || s["participant"] == participant;
    if (assigned) continue;
    const std::string state = session->state();
    running += state == "running" ? 1 : 0;
    arrived.push_back({{"participant", participant}, {"session", state}});
  }
  char summary[200];
  std::snprintf(summary, sizeof summary, "%zu slots assigned, %d running now, %d finished, %d responses stored; %zu participants arrived at this server",
                slots.size(), running, finished, answered, live.size());
  return {{"experiment", e.id}, {"summary", summary}, {"slots", slots}, {"arrived", arrived},
          {"running", running}, {"finished", finished}, {"responses", answered}};
}

void StudyServer::admin(const httplib::Request& req, httplib::Response& res) {
  if (!isAdmin(req)) {
    res.status = 403;
    res.set_content(messagePage("Forbidden", "The admin page needs the admin token printed when the server started."), "text/html; charset=utf-8");
    return;
  }
  res.set_header("Cache-Control", "no-store");
  res.set_content(adminPage(status(), adminToken_), "text/html; charset=utf-8");
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
