#pragma once
// StudyServer: `tlab serve` — one experiment served over HTTP (cpp-httplib's routing behind an
// epoll ConnectionDispatcher, so idle connections hold no thread) to participants'
// browsers. Participants arrive at /s/<experiment id>?<participant parameter>=ID (Prolific's
// PROLIFIC_PID, or "pid"), get an unguessable token and the participant page (/p/<token>), whose
// script walks the session flow through the JSON API under /api/<token>/. Every request is bound
// to one token: a token reads and writes only its own participant's screens and images. Images
// are served by SHA-256 name only, and only those this participant's screens named. The admin
// page (/admin) needs the admin token printed at start.
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include <httplib.h>

#include "study/serve/connection_dispatcher.hpp"
#include "study/serve/participant_session.hpp"
#include "study/serve/replay_jobs.hpp"
#include "study/serve/routing_server.hpp"

namespace tlab::study {

struct ServeOptions {
  std::string host = "127.0.0.1";
  int port = 8080;
  std::size_t maxBodyBytes = 64 * 1024;
  int threads = 256;  // HTTP worker threads: one per request being answered (a reply waits for the session thread)
  std::size_t connectionsPerAddress = 2000;  // beyond: the address's longest-idle connection is closed
};

class StudyServer {
 public:
  StudyServer(ServedStudy study, ServeOptions options, std::string adminToken);
  ~StudyServer();

  // Binds (throws with one line when the port is taken); returns the port bound.
  int bind();
  // Serves until stop() (from a signal or another thread).
  void listen();
  void stop();

  const std::string& adminToken() const { return adminToken_; }

 private:
  void routes();
  void pageRoutes();
  void apiRoutes();
  void adminRoutes();
  void arrive(const httplib::Request& req, httplib::Response& res);
  void reply(ParticipantSession& session, const httplib::Request& req, httplib::Response& res);
  // POST /api/<token>/view of a live trial: the page's input in, the next frame (PNG) out.
  void view(ParticipantSession& session, const httplib::Request& req, httplib::Response& res);
  void admin(const httplib::Request& req, httplib::Response& res);
  void adminAction(const httplib::Request& req, httplib::Response& res);
  // GET /admin/replay?participant=P&trial=N: starts (or finds) the trial's replay and sends the
  // browser to it; GET /admin/replays/<key>/...: its progress, its page and its frames.
  void adminReplay(const httplib::Request& req, httplib::Response& res);
  void replayFile(const httplib::Request& req, httplib::Response& res);
  nlohmann::json status();
  std::shared_ptr<ParticipantSession> session(const std::string& token);
  // The session of an API request (its token in the path), when its browser may act on it; else
  // nullptr with the refusal written into `res` (404: no such session; 403: another browser's).
  std::shared_ptr<ParticipantSession> admitted(const httplib::Request& req, httplib::Response& res);
  bool isAdmin(const httplib::Request& req) const;

  ServedStudy study_;
  ServeOptions options_;
  std::string adminToken_;
  RoutingServer http_;               // the routes, fed one whole request at a time by
  ConnectionDispatcher dispatcher_;  // the event loop that holds every connection
  std::mutex mutex_;
  std::map<std::string, std::shared_ptr<ParticipantSession>> byToken_, byParticipant_;
  ReplayJobs replays_;  // the admin page's replays, rendered by child processes
};

}  // namespace tlab::study
