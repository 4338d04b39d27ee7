#pragma once
// LoadParticipant: one simulated participant of `tlab loadtest` — a browser walking a whole
// session of `tlab serve` over HTTP (keep-alive), as study/serve/web/participant.js does: arrive
// through the participants' link, report the display, fetch each screen's images, report the
// onset, think, answer. An answer counts as acknowledged only when the server's reply is the next
// screen (it comes after the answer was stored). On a lost connection or a server error the
// participant re-arrives through the link (tokens live in the server's memory only, so after a
// restart this resumes the participant) and carries on from the screen the server shows, until
// the retry budget of one outage is spent.
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace httplib {
class Client;
}

namespace tlab::study {

// Where the participants' link points: "http://127.0.0.1:8080" and "/s/tiny", parameter "pid".
struct LoadTarget {
  std::string origin;
  std::string arrivalPath;
  std::string parameter = "pid";
};

// Splits a participants' link base ("http://HOST:PORT/s/ID"); throws std::invalid_argument.
LoadTarget parseLoadTarget(const std::string& url, const std::string& parameter);

struct LoadBehaviour {
  double thinkMs = 200.0;     // mean think time (exponential), before every button press and answer
  double retrySeconds = 0.0;  // how long one outage may last before the participant fails (0: never retry)
  // Live trials (orbit, walk): explored this long (0: for the think time) by sending input as fast as
  // frames come back, one request at a time, as the page does — orbiting drags, walking steps and turns.
  double liveSeconds = 0.0;
};

// A trial the server acknowledged: its phase, its position among that phase's trials (the page's
// "index": training and test count from 1 each) and the answer sent (JSON).
struct AckedTrial {
  std::string participant;
  std::string phase;
  int index = 0;
  std::string answer;
};

struct ParticipantRun {
  bool finished = false;
  std::string error;  // why the participant failed ("" when finished)
  std::vector<AckedTrial> acked;
  std::vector<double> ackMs, requestMs;  // answer → acknowledgement; every request
  std::vector<double> startMs;           // display report → first screen (the server enrols and plans the session)
  std::vector<double> frameMs;           // live trials: input sent → its frame received
  std::vector<double> firstFrameMs;      // live trials: the start view of each trial (its first frame)
  // live trials: each stage of a frame on the server (Server-Timing: "wait", "render", "hash",
  // "encode", "total", ...), in the order the server names them
  std::vector<std::pair<std::string, std::vector<double>>> stageMs;
  double liveSeconds = 0.0;              // time spent exploring live trials (frames / liveSeconds: frames a second)
  int reconnects = 0;
};

class LoadParticipant {
 public:
  LoadParticipant(LoadTarget target, std::string participant, std::uint64_t seed, LoadBehaviour behaviour,
                  std::function<void(const AckedTrial&)> onAck);
  ~LoadParticipant();
  ParticipantRun walk();

 private:
  // What a browser survives by retrying: no connection, a server that restarted (the token is
  // unknown: 404), a server error (5xx) or an error screen. Anything else ends the participant.
  struct ConnectionLost : std::runtime_error {
    using std::runtime_error::runtime_error;
  };
  struct Reply {
    int status = 0;
    std::string body;
    std::string location;
    std::string timing;  // the Server-Timing header (a live frame's render, hash and encode times)
  };
  Reply send(const std::string& method, const std::string& path, const nlohmann::json* body = nullptr);
  nlohmann::json arrive();
  nlohmann::json recover(std::string why);
  nlohmann::json step(const nlohmann::json& screen);
  nlohmann::json trial(const nlohmann::json& screen);
  // A live trial's views for `ms`: input after input, each sent when the previous frame arrived.
  void explore(const nlohmann::json& screen, double ms);
  void noteStages(const std::string& timing);  // a live frame's Server-Timing into run_.stageMs
  // Sends a reply that ends `screen`; returns the next screen. `acknowledged`: the server took the
  // reply (200) and moved on to a later screen, which it does only after storing the reply.
  nlohmann::json finishing(const nlohmann::json& screen, nlohmann::json body, bool* acknowledged = nullptr);
  nlohmann::json screenOf(const Reply& r, const std::string& what);
  nlohmann::json pastWait(nlohmann::json screen);
  void fetchImages(const nlohmann::json& screen);
  void think(double ms);
  double thinkTime();
  static std::string brief(const std::string& body);  // the first line of a body, for a message

  LoadTarget target_;
  std::string participant_, token_;
  std::mt19937_64 rng_;
  LoadBehaviour behaviour_;
  std::function<void(const AckedTrial&)> onAck_;
  std::unique_ptr<httplib::Client> client_;
  std::set<std::string> fetched_;  // images the browser has cached
  bool arrived_ = false;
  ParticipantRun run_;
};

}  // namespace tlab::study
