#include "study/serve/routing_server.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <string>

namespace tlab::study {

namespace {

void addressOf(const sockaddr_storage& a, std::string& ip, int& port) {
  char text[INET6_ADDRSTRLEN] = "";
  if (a.ss_family == AF_INET) {
    const auto& v4 = reinterpret_cast<const sockaddr_in&>(a);
    ::inet_ntop(AF_INET, &v4.sin_addr, text, sizeof text);
    port = ntohs(v4.sin_port);
  } else if (a.ss_family == AF_INET6) {
    const auto& v6 = reinterpret_cast<const sockaddr_in6&>(a);
    ::inet_ntop(AF_INET6, &v6.sin6_addr, text, sizeof text);
    port = ntohs(v6.sin6_port);
  }
  ip = text;
}

// One request already in memory; the reply goes to the socket.
class RequestStream : public httplib::Stream {
 public:
  RequestStream(int fd, std::string request, int writeTimeoutSeconds) : fd_(fd), request_(std::move(request)), writeTimeoutMs_(writeTimeoutSeconds * 1000) {}

  bool is_readable() const override { return at_ < request_.size(); }
  bool is_writable() const override {
    pollfd p{fd_, POLLOUT, 0};
    return ::poll(&p, 1, writeTimeoutMs_) > 0 && (p.revents & POLLOUT);
  }
  ssize_t read(char* ptr, size_t size) override {
    const std::size_t n = std::min(size, request_.size() - at_);
    std::memcpy(ptr, request_.data() + at_, n);
    at_ += n;
    return ssize_t(n);
  }
  ssize_t write(const char* ptr, size_t size) override {
    std::size_t sent = 0;
    while (sent < size) {
      if (!is_writable()) return -1;
      const ssize_t n = ::send(fd_, ptr + sent, size - sent, MSG_NOSIGNAL | MSG_DONTWAIT);
      if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)) continue;
      if (n <= 0) return -1;
      sent += std::size_t(n);
    }
    return ssize_t(size);
  }
  void get_remote_ip_and_port(std::string& ip, int& port) const override {
    sockaddr_storage a{};
    socklen_t size = sizeof a;
    if (::getpeername(fd_, reinterpret_cast<sockaddr*>(&a), &size) == 0) addressOf(a, ip, port);
  }
  void get_local_ip_and_port(std::string& ip, int& port) const override {
    sockaddr_storage a{};
    socklen_t size = sizeof a;
    if (::getsockname(fd_, reinterpret_cast<sockaddr*>(&a), &size) == 0) addressOf(a, ip, port);
  }
  socket_t socket() const override { return fd_; }  // cpp-httplib declares socket_t at global scope

 private:
  int fd_;
  std::string request_;
  std::size_t at_ = 0;
  int writeTimeoutMs_;
};

}  // namespace

bool RoutingServer::answer(int fd, std::size_t bytes, int writeTimeoutSeconds) {
  std::string request(bytes, '\0');
  std::size_t got = 0;
  while (got < bytes) {  // all there already (the dispatcher peeked it): no waiting on the client
    const ssize_t n = ::recv(fd, request.data() + got, bytes - got, MSG_DONTWAIT);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    got += std::size_t(n);
  }
  RequestStream stream(fd, std::move(request), writeTimeoutSeconds);
  bool closed = false;
  const bool answered = process_request(stream, false, closed, nullptr);
  return answered && !closed;
}

}  // namespace tlab::study
