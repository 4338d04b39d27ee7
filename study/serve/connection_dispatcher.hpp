#pragma once
// ConnectionDispatcher: the event-driven front of tlab serve's HTTP server. cpp-httplib alone holds
// a worker thread for every open connection, so idle or half-sent connections (a slow client, a
// slowloris) took every thread and stalled the participants (300 idle connections: a request
// waited 14 s). Here one thread watches every connection with epoll and hands a connection to a
// worker only once a whole request has arrived (its header and the body its Content-Length
// announces, seen with MSG_PEEK); the worker answers that one request and gives the connection
// back. An idle connection costs a file descriptor, never a thread. Limits (DispatchLimits):
//  - a request must arrive whole within `requestTimeout` of its first byte (the header and body
//    read time-out), else the connection is closed;
//  - a keep-alive connection with nothing to say is closed after `idleTimeout`;
//  - at most `perAddress` connections per client address: a new one closes that address's
//    longest-idle connection (a participant's new connection is never the one refused);
//  - at most `queueLimit` whole requests wait for a worker: beyond that, 503 and close.
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace tlab::study {

struct DispatchLimits {
  int workers = 256;  // threads answering requests (a reply waits for the session thread to store it)
  std::size_t perAddress = 2000;
  std::size_t queueLimit = 4096;
  std::chrono::milliseconds requestTimeout{10000};
  std::chrono::milliseconds idleTimeout{120000};
  std::size_t maxHeaderBytes = 16 * 1024;
  std::size_t maxBodyBytes = 64 * 1024;
};

// The first request in `peeked` (the bytes a connection has sent so far): `bytes` 0 while it is
// incomplete. A body over maxBodyBytes counts as its header only, with `bodyLeft` set: the server
// answers 413 without reading it, then closes. nullopt: it can never be a request this server
// takes (a header over maxHeaderBytes, a chunked or unreadable length).
struct RequestExtent {
  std::size_t bytes = 0;
  bool bodyLeft = false;
};
std::optional<RequestExtent> requestExtent(const std::string& peeked, std::size_t maxHeaderBytes, std::size_t maxBodyBytes);

class ConnectionDispatcher {
 public:
  // Answers the one request of `bytes` bytes waiting on socket `fd`; true: keep the connection.
  using Serve = std::function<bool(int fd, std::size_t bytes)>;

  ConnectionDispatcher(DispatchLimits limits, Serve serve);
  ~ConnectionDispatcher();
  ConnectionDispatcher(const ConnectionDispatcher&) = delete;
  ConnectionDispatcher& operator=(const ConnectionDispatcher&) = delete;

  // Binds and listens (port 0: any free one); returns the port; throws with one line.
  int bind(const std::string& host, int port);
  // Serves until stop(); the workers finish the requests they hold.
  void run();
  void stop();

  struct Counts {
    std::size_t open = 0, evicted = 0, timedOut = 0, overloaded = 0;
  };
  Counts counts() const;

 private:
  struct Connection {
    std::string address;
    std::chrono::steady_clock::time_point since;              // accepted, or its last request answered
    std::optional<std::chrono::steady_clock::time_point> started;  // first byte of a request not yet whole
    bool busy = false;                                         // with a worker
  };

  void accept();
  void readable(int fd);
  void sweep();
  void work();
  void closeLocked(int fd);
  void watchLocked(int fd);

  DispatchLimits limits_;
  Serve serve_;
  int listen_ = -1, epoll_ = -1, wake_ = -1;
  mutable std::mutex mutex_;
  std::condition_variable queued_;
  std::map<int, Connection> connections_;
  struct Job {
    int fd = -1;
    RequestExtent request;
  };
  std::deque<Job> queue_;
  std::string peeked_;  // the event thread's peek buffer
  std::vector<std::thread> workers_;
  bool stopping_ = false;
  Counts counts_;
};

}  // namespace tlab::study
