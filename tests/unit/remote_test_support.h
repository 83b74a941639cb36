#pragma once
// Shared by the remote control's tests: polling with a deadline instead of sleeping, and reads that
// give up instead of hanging a test that fails.
#include <sys/socket.h>
#include <sys/time.h>

#include <chrono>
#include <functional>
#include <thread>

namespace vitrine::remote::testing {

// True as soon as `done` is; false after `limit`. Polls every millisecond.
inline bool eventually(const std::function<bool()>& done,
                       std::chrono::milliseconds limit = std::chrono::milliseconds(2000)) {
  const auto deadline = std::chrono::steady_clock::now() + limit;
  while (!done()) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return true;
}

// Reads on a test's socket (anything with native_handle()) give up after two seconds.
template <typename Socket> void limitReads(Socket& socket) {
  timeval limit{2, 0};
  ::setsockopt(socket.native_handle(), SOL_SOCKET, SO_RCVTIMEO, &limit, sizeof limit);
}

}  // namespace vitrine::remote::testing
