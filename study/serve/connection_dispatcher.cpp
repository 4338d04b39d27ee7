#include "study/serve/connection_dispatcher.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/epoll.h>
#include <sys/eventfd.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace tlab::study {

namespace {

using Clock = std::chrono::steady_clock;

std::string lower(std::string text) {
  for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

std::string peerAddress(const sockaddr_storage& address) {
  char text[INET6_ADDRSTRLEN] = "";
  if (address.ss_family == AF_INET) ::inet_ntop(AF_INET, &reinterpret_cast<const sockaddr_in&>(address).sin_addr, text, sizeof text);
  if (address.ss_family == AF_INET6) ::inet_ntop(AF_INET6, &reinterpret_cast<const sockaddr_in6&>(address).sin6_addr, text, sizeof text);
  return text;
}

// Idle connections are file descriptors: the soft limit goes up to the hard one.
void raiseDescriptorLimit() {
  rlimit limit{};
  if (::getrlimit(RLIMIT_NOFILE, &limit) == 0 && limit.rlim_cur < limit.rlim_max) {
    limit.rlim_cur = limit.rlim_max;
    ::setrlimit(RLIMIT_NOFILE, &limit);
  }
}

constexpr char kOverloaded[] = "HTTP/1.1 503 Service Unavailable\r\nContent-Length: 0\r\nRetry-After: 1\r\nConnection: close\r\n\r\n";

}  // namespace

std::optional<RequestExtent> requestExtent(const std::string& peeked, std::size_t maxHeaderBytes, std::size_t maxBodyBytes) {
  const auto end = peeked.find("\r\n\r\n");
  if (end == std::string::npos) return peeked.size() > maxHeaderBytes ? std::nullopt : std::optional<RequestExtent>(RequestExtent{});
  const std::size_t header = end + 4;
  if (header > maxHeaderBytes) return std::nullopt;
  std::size_t length = 0;
  for (std::size_t at = peeked.find("\r\n") + 2; at < end;) {  // the header lines after the request line
    const std::size_t next = peeked.find("\r\n", at);
    const std::string line = peeked.substr(at, next - at);
    at = next + 2;
    const auto colon = line.find(':');
    if (colon == std::string::npos) continue;
    const std::string name = lower(trimmed(line.substr(0, colon)));
    if (name == "transfer-encoding") return std::nullopt;
    if (name != "content-length") continue;
    const std::string value = trimmed(line.substr(colon + 1));
    if (value.empty() || value.size() > 12 || value.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
    length = std::stoull(value);
  }
  if (length > maxBodyBytes) return RequestExtent{header, true};
  return RequestExtent{peeked.size() >= header + length ? header + length : 0, false};
}

ConnectionDispatcher::ConnectionDispatcher(DispatchLimits limits, Serve serve) : limits_(limits), serve_(std::move(serve)) {}

ConnectionDispatcher::~ConnectionDispatcher() {
  stop();
  if (listen_ >= 0) ::close(listen_);
}

int ConnectionDispatcher::bind(const std::string& host, int port) {
  raiseDescriptorLimit();
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  hints.ai_flags = AI_PASSIVE;
  addrinfo* found = nullptr;
  const std::string where = host + ":" + std::to_string(port);
  const std::string advice = " (the port is in use or the address is not this machine's); choose another with --listen HOST:PORT";
  if (::getaddrinfo(host.c_str(), std::to_string(port).c_str(), &hints, &found) != 0 || !found) throw std::runtime_error("cannot listen on " + where + advice);
  for (const addrinfo* a = found; a && listen_ < 0; a = a->ai_next) {
    const int fd = ::socket(a->ai_family, a->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, a->ai_protocol);
    if (fd < 0) continue;
    const int yes = 1;  // SO_REUSEADDR (a restarted server gets its port at once), never SO_REUSEPORT (a second server would split the participants)
    ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    if (::bind(fd, a->ai_addr, a->ai_addrlen) == 0 && ::listen(fd, SOMAXCONN) == 0) listen_ = fd;
    else ::close(fd);
  }
  ::freeaddrinfo(found);
  if (listen_ < 0) throw std::runtime_error("cannot listen on " + where + advice);
  sockaddr_storage bound{};
  socklen_t size = sizeof bound;
  ::getsockname(listen_, reinterpret_cast<sockaddr*>(&bound), &size);
  return bound.ss_family == AF_INET6 ? ntohs(reinterpret_cast<sockaddr_in6&>(bound).sin6_port) : ntohs(reinterpret_cast<sockaddr_in&>(bound).sin_port);
}

void ConnectionDispatcher::run() {
  {
    std::lock_guard lock(mutex_);
    if (stopping_ || listen_ < 0) return;
    epoll_ = ::epoll_create1(EPOLL_CLOEXEC);
    wake_ = ::eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
    if (epoll_ < 0 || wake_ < 0) throw std::runtime_error(std::string("serve: cannot watch connections: ") + std::strerror(errno));
    for (const int fd : {listen_, wake_}) {
      epoll_event e{};
      e.events = EPOLLIN;
      e.data.fd = fd;
      ::epoll_ctl(epoll_, EPOLL_CTL_ADD, fd, &e);
    }
    for (int i = 0; i < limits_.workers; ++i) workers_.emplace_back([this] { work(); });
  }
  std::vector<epoll_event> events(256);
  auto swept = Clock::now();
  for (;;) {
    const int n = ::epoll_wait(epoll_, events.data(), int(events.size()), 250);
    {
      std::lock_guard lock(mutex_);
      if (stopping_) break;
    }
    for (int i = 0; i < n; ++i) {
      const int fd = events[std::size_t(i)].data.fd;
      if (fd == listen_) accept();
      else if (fd != wake_) readable(fd);
    }
    if (Clock::now() - swept >= std::chrono::milliseconds(250)) {
      sweep();
      swept = Clock::now();
    }
  }
  queued_.notify_all();
  for (auto& w : workers_) w.join();
  std::lock_guard lock(mutex_);
  for (const auto& job : queue_) ::close(job.fd);
  queue_.clear();
  while (!connections_.empty()) closeLocked(connections_.begin()->first);
  ::close(epoll_);
  ::close(wake_);
  epoll_ = wake_ = -1;
}

void ConnectionDispatcher::stop() {
  std::lock_guard lock(mutex_);
  stopping_ = true;
  if (wake_ >= 0) {
    const std::uint64_t one = 1;
    [[maybe_unused]] const auto written = ::write(wake_, &one, sizeof one);
  }
  queued_.notify_all();
}

ConnectionDispatcher::Counts ConnectionDispatcher::counts() const {
  std::lock_guard lock(mutex_);
  Counts c = counts_;
  c.open = connections_.size();
  return c;
}

void ConnectionDispatcher::watchLocked(int fd) {
  epoll_event e{};
  e.events = EPOLLIN | EPOLLRDHUP | EPOLLET;  // edge-triggered: a partial request wakes the loop only when more arrives
  e.data.fd = fd;
  if (::epoll_ctl(epoll_, EPOLL_CTL_ADD, fd, &e) != 0) closeLocked(fd);
}

void ConnectionDispatcher::closeLocked(int fd) {
  ::epoll_ctl(epoll_, EPOLL_CTL_DEL, fd, nullptr);
  ::close(fd);
  connections_.erase(fd);
}

void ConnectionDispatcher::accept() {
  for (;;) {
    sockaddr_storage address{};
    socklen_t size = sizeof address;
    const int fd = ::accept4(listen_, reinterpret_cast<sockaddr*>(&address), &size, SOCK_NONBLOCK | SOCK_CLOEXEC);
    if (fd < 0) return;  // EAGAIN: all taken; EMFILE and the like: the next round tries again
    const int yes = 1;   // headers and body go out as separate writes: without it each reply waits for a delayed ACK
    ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &yes, sizeof yes);
    const std::string from = peerAddress(address);
    std::lock_guard lock(mutex_);
    std::size_t same = 0;
    int idlest = -1;
    for (const auto& [other, c] : connections_) {
      if (c.address != from) continue;
      ++same;
      if (!c.busy && (idlest < 0 || c.since < connections_.at(idlest).since)) idlest = other;
    }
    if (same >= limits_.perAddress) {  // the address's longest-idle connection makes room (a new one is likelier a person)
      if (idlest < 0) {
        ::close(fd);
        ++counts_.evicted;
        continue;
      }
      closeLocked(idlest);
      ++counts_.evicted;
    }
    connections_[fd] = Connection{from, Clock::now(), std::nullopt, false};
    watchLocked(fd);
  }
}

void ConnectionDispatcher::readable(int fd) {
  std::lock_guard lock(mutex_);
  const auto it = connections_.find(fd);
  if (it == connections_.end() || it->second.busy) return;
  peeked_.resize(limits_.maxHeaderBytes + limits_.maxBodyBytes);
  const ssize_t n = ::recv(fd, peeked_.data(), peeked_.size(), MSG_PEEK | MSG_DONTWAIT);
  if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return;
  if (n <= 0) return closeLocked(fd);  // closed by the client, or broken
  peeked_.resize(std::size_t(n));
  Connection& c = it->second;
  if (!c.started) c.started = Clock::now();
  const auto request = requestExtent(peeked_, limits_.maxHeaderBytes, limits_.maxBodyBytes);
  if (!request) return closeLocked(fd);
  if (request->bytes == 0) return;  // more to come, within the request time-out
  if (queue_.size() >= limits_.queueLimit) {
    [[maybe_unused]] const auto sent = ::send(fd, kOverloaded, sizeof kOverloaded - 1, MSG_NOSIGNAL | MSG_DONTWAIT);
    ++counts_.overloaded;
    return closeLocked(fd);
  }
  c.busy = true;
  ::epoll_ctl(epoll_, EPOLL_CTL_DEL, fd, nullptr);
  queue_.push_back({fd, *request});
  queued_.notify_one();
}

void ConnectionDispatcher::sweep() {
  const auto now = Clock::now();
  std::lock_guard lock(mutex_);
  std::vector<int> late, idle;
  for (const auto& [fd, c] : connections_) {
    if (c.busy) continue;
    if (c.started && now - *c.started > limits_.requestTimeout) late.push_back(fd);
    else if (!c.started && now - c.since > limits_.idleTimeout) idle.push_back(fd);
  }
  for (const int fd : late) closeLocked(fd);
  for (const int fd : idle) closeLocked(fd);
  counts_.timedOut += late.size();
}

void ConnectionDispatcher::work() {
  for (;;) {
    Job job;
    {
      std::unique_lock lock(mutex_);
      queued_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
      if (stopping_) return;
      job = queue_.front();
      queue_.pop_front();
    }
    bool keep = false;
    try {
      keep = serve_(job.fd, job.request.bytes) && !job.request.bodyLeft;
    } catch (...) {  // the routing has its own exception handler: this is the socket failing
      keep = false;
    }
    std::lock_guard lock(mutex_);
    const auto it = connections_.find(job.fd);
    if (it == connections_.end()) continue;
    if (stopping_ || !keep) {
      closeLocked(job.fd);
      continue;
    }
    it->second = Connection{it->second.address, Clock::now(), std::nullopt, false};
    watchLocked(job.fd);
  }
}

}  // namespace tlab::study
