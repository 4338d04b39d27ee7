#pragma once
// Host loops over a frame's pixels on several threads (issue #29: the passes that run as host code
// where the GL runs on the CPU). [0, n) is cut into `shares` contiguous shares, share s being
// [n·s/shares, n·(s+1)/shares); each runs on a thread of its own (the caller's runs the first), and
// all are joined before the call returns. A share's results go to its own places (or its own
// share-indexed slot), so they never depend on how many shares there are.
#include <algorithm>
#include <cstddef>
#include <thread>
#include <vector>

namespace tlab::core {

// Shares for n items on up to `threads` threads, each of at least `leastPerShare` items (fewer
// items than that cost more to start a thread for than they save): at least 1.
inline std::size_t sharesFor(std::size_t n, std::size_t leastPerShare, unsigned threads) {
  return std::clamp<std::size_t>(n / std::max<std::size_t>(leastPerShare, 1), 1, std::max(threads, 1u));
}

// Calls body(from, to, share) for each share of [0, n).
template <class Body>
void forEachShare(std::size_t n, std::size_t shares, const Body& body) {
  shares = std::max<std::size_t>(shares, 1);
  std::vector<std::jthread> workers;  // joined as they go out of scope
  for (std::size_t s = 1; s < shares; ++s) workers.emplace_back([&body, n, s, shares] { body(n * s / shares, n * (s + 1) / shares, s); });
  body(0, n / shares, 0);
}

}  // namespace tlab::core
