#pragma once
// RoutingServer: cpp-httplib's routing, fed one whole request at a time by the ConnectionDispatcher
// (study/serve/connection_dispatcher.hpp) instead of its own thread-per-connection loop. The
// request's bytes are read off the socket first (they have all arrived: the dispatcher saw them),
// so parsing never waits on a client, and nothing past the request is read: the connection's
// next request stays in the socket for the dispatcher.
#include <cstddef>

#include <httplib.h>

namespace tlab::study {

class RoutingServer : public httplib::Server {
 public:
  // Answers the request of `bytes` bytes waiting on socket `fd`; true: the connection stays open
  // (keep-alive). Writes give up after `writeTimeoutSeconds` without progress.
  bool answer(int fd, std::size_t bytes, int writeTimeoutSeconds);
};

}  // namespace tlab::study
