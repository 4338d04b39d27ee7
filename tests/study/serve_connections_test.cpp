// tlab serve's connection handling (study/serve/connection_dispatcher.hpp): where a request ends
// in what a connection has sent so far, and, end to end, that idle connections hold no worker
// thread (a participant is answered while more idle connections are held than there are
// workers, and none of them had to be closed for it) and that one address's connections are
// capped by closing its longest-idle ones, which never touches another address.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "study/serve/connection_dispatcher.hpp"
#include "tests/study/served_study.hpp"

namespace tlab::testing {
namespace {

using study::requestExtent;

TEST(ServeRequestExtent, AWholeRequestIsItsHeaderAndTheBodyItsLengthAnnounces) {
  const std::string get = "GET /api/x/screen HTTP/1.1\r\nHost: a\r\n\r\n";
  EXPECT_EQ(requestExtent(get, 1024, 64)->bytes, get.size());
  EXPECT_EQ(requestExtent(get + "GET /next", 1024, 64)->bytes, get.size()) << "the next request stays for later";
  EXPECT_EQ(requestExtent("GET / HTTP/1.1\r\nHost: a\r\n", 1024, 64)->bytes, 0u) << "the header is not complete";
  const std::string post = "POST /r HTTP/1.1\r\ncontent-LENGTH:  5 \r\n\r\n";
  EXPECT_EQ(requestExtent(post + "ab", 1024, 64)->bytes, 0u) << "the body is not complete";
  EXPECT_EQ(requestExtent(post + "abcde", 1024, 64)->bytes, post.size() + 5);
  const auto big = requestExtent("POST /r HTTP/1.1\r\nContent-Length: 65\r\n\r\n", 1024, 64);
  EXPECT_EQ(big->bytes, 40u);
  EXPECT_TRUE(big->bodyLeft) << "a body over the limit is not waited for";
  EXPECT_FALSE(requestExtent(std::string(1025, 'a'), 1024, 64)) << "a header over the limit";
  EXPECT_FALSE(requestExtent("POST /r HTTP/1.1\r\nTransfer-Encoding: chunked\r\n\r\n", 1024, 64));
  EXPECT_FALSE(requestExtent("POST /r HTTP/1.1\r\nContent-Length: -1\r\n\r\n", 1024, 64));
}

// A TCP connection to the server from a loopback address (127.0.0.1 or another 127.x).
int connectFrom(const char* source, int port) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in from{};
  from.sin_family = AF_INET;
  ::inet_pton(AF_INET, source, &from.sin_addr);
  sockaddr_in to{};
  to.sin_family = AF_INET;
  to.sin_port = htons(std::uint16_t(port));
  ::inet_pton(AF_INET, "127.0.0.1", &to.sin_addr);
  if (fd < 0 || ::bind(fd, reinterpret_cast<sockaddr*>(&from), sizeof from) != 0 || ::connect(fd, reinterpret_cast<sockaddr*>(&to), sizeof to) != 0)
    throw std::runtime_error(std::string("cannot connect from ") + source);
  return fd;
}

// GET `path` from `source` (Connection: close); the whole reply, or "" when none came within 60 s.
std::string request(const char* source, int port, const std::string& path) {
  const int fd = connectFrom(source, port);
  const std::string text = "GET " + path + " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n";
  ::send(fd, text.data(), text.size(), MSG_NOSIGNAL);
  std::string reply;
  char buffer[4096];
  for (int reads = 0; reads < 10000; ++reads) {
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, 60000) <= 0) break;  // a generous limit: the server answers or the test fails
    const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
    if (n <= 0) break;
    reply.append(buffer, std::size_t(n));
  }
  ::close(fd);
  return reply;
}

// Whether the server closed `fd`: waits up to `waitMs` for its end of stream.
bool closedByServer(int fd, int waitMs) {
  pollfd p{fd, POLLIN, 0};
  if (::poll(&p, 1, waitMs) <= 0) return false;
  char byte = 0;
  return ::recv(fd, &byte, 1, MSG_PEEK | MSG_DONTWAIT) == 0;
}

TEST(ServeIdleConnections, AParticipantIsAnsweredWhileIdleConnectionsOutnumberTheWorkersAndOneAddressIsCapped) {
  const auto dir = freshDir("ServeIdleConnections");
  constexpr int kWorkers = 8, kCap = 300, kHeld = 280, kMore = 40;
  ServedStudy server(studyData("serve_tiny.toml"), (dir / "study.db").string(), dir, 0,
                     {"--threads", std::to_string(kWorkers), "--max-connections-per-address", std::to_string(kCap)});
  std::vector<int> held;
  for (int i = 0; i < kHeld; ++i) held.push_back(connectFrom("127.0.0.1", server.port()));
  // A participant from another address: answered at once, although every worker could have been
  // held by the idle connections in a thread-per-connection server.
  const std::string page = request("127.0.0.2", server.port(), "/");
  EXPECT_EQ(page.rfind("HTTP/1.1 200", 0), 0u) << page.substr(0, 200);
  int closed = 0;
  for (const int fd : held) closed += closedByServer(fd, 0);
  EXPECT_EQ(closed, 0) << "no idle connection had to be closed for the participant's request";
  // More idle connections from 127.0.0.1 than its cap: its longest-idle ones are closed.
  for (int i = 0; i < kMore; ++i) held.push_back(connectFrom("127.0.0.1", server.port()));
  const std::string again = request("127.0.0.2", server.port(), "/");  // accepted after them: they were counted
  EXPECT_EQ(again.rfind("HTTP/1.1 200", 0), 0u) << again.substr(0, 200);
  const int evicted = kHeld + kMore - kCap;
  for (int i = 0; i < evicted; ++i) EXPECT_TRUE(closedByServer(held[std::size_t(i)], 30000)) << "held connection " << i << " (among the oldest)";
  int open = 0;
  for (std::size_t i = std::size_t(evicted); i < held.size(); ++i) open += !closedByServer(held[i], 0);
  EXPECT_EQ(open, kCap) << "the newer connections stay open";
  for (const int fd : held) ::close(fd);
  EXPECT_EQ(server.stop(SIGTERM), 0) << server.stderrText();
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tlab::testing
