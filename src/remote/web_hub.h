#pragma once
// What the web server's sessions share: the configuration, the catalogue and the page, where
// commands go, and the open sockets. Lives as long as the server; touched only on the I/O thread,
// except the atomic socket count.
#include "remote/catalogue.h"
#include "remote/inbox.h"
#include "remote/stats.h"
#include "remote/web_server.h"

#include <atomic>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_set>

namespace vitrine::remote {

class SocketSession;

struct WebHub {
  std::string token;
  const Catalogue& catalogue;
  RemoteInbox& inbox;
  RemoteStats& stats;
  WebLimits limits;
  std::string_view page;

  std::unordered_set<SocketSession*> openSockets;  // handshake done: these get state pushes
  std::shared_ptr<const std::string> lastState;    // sent to each socket when it opens
  std::atomic<size_t> sockets{0};                  // sessions alive, handshaking or open
  size_t connections = 0;                          // TCP connections alive, HTTP or WebSocket
};

// Counts a TCP connection for as long as it lives (moved from the HTTP session to its socket).
class ConnectionSlot {
 public:
  explicit ConnectionSlot(WebHub& hub) : hub_(&hub) { ++hub_->connections; }
  ~ConnectionSlot() {
    if (hub_) --hub_->connections;
  }
  ConnectionSlot(ConnectionSlot&& other) noexcept : hub_(other.hub_) { other.hub_ = nullptr; }
  ConnectionSlot(const ConnectionSlot&) = delete;
  ConnectionSlot& operator=(const ConnectionSlot&) = delete;
  ConnectionSlot& operator=(ConnectionSlot&&) = delete;

 private:
  WebHub* hub_;
};

}  // namespace vitrine::remote
