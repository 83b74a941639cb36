#pragma once
// What the web server's sessions share: the configuration, the catalogue and the page, where
// commands go, and the open sockets. Lives as long as the server; touched only on the I/O thread,
// except the atomic socket count.
#include "remote/catalogue.h"
#include "remote/inbox.h"
#include "remote/osc_trust.h"
#include "remote/oscquery.h"
#include "remote/stats.h"
#include "remote/web_server.h"

#include <atomic>
#include <list>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_set>

namespace vitrine::remote {

class SocketSession;
class HttpSession;

struct WebHub {
  std::string token;
  const Catalogue& catalogue;
  RemoteInbox& inbox;
  RemoteStats& stats;
  WebLimits limits;
  std::string_view page;
  // Who may read the OSCQuery namespace and use its socket without the token: those who may send OSC
  // (null: nobody; the token is needed).
  std::shared_ptr<const OscTrust> trust;
  std::string machineName;  // this computer's host name, which a client's Host header may name

  OscQueryHost host;                                  // HOST_INFO: the OSC port and address
  OscQueryValues values;                              // what the gallery last published, per scene
  std::unordered_set<SocketSession*> querySockets;    // OSCQuery sockets: value streams

  std::unordered_set<SocketSession*> openSockets;  // handshake done: these get state pushes
  std::shared_ptr<const std::string> lastState;    // sent to each socket when it opens
  std::atomic<size_t> sockets{0};                  // sessions alive, handshaking or open
  size_t connections = 0;                          // TCP connections alive, HTTP or WebSocket
  std::map<std::string, size_t, std::less<>> perAddress;  // connections alive per client IP address
  // Connections that have not yet sent a request with the token, oldest first: the ones given up
  // when a new connection needs room, so idle strangers can never lock out a phone with the token.
  std::list<HttpSession*> strangers;
};

// Counts a TCP connection, in all and for its address, for as long as it lives (moved from the HTTP
// session to its socket).
class ConnectionSlot {
 public:
  ConnectionSlot(WebHub& hub, std::string address) : hub_(&hub), address_(std::move(address)) {
    ++hub_->connections;
    ++hub_->perAddress[address_];
  }
  ~ConnectionSlot() {
    if (!hub_) return;
    --hub_->connections;
    if (const auto it = hub_->perAddress.find(address_); it != hub_->perAddress.end() && --it->second == 0)
      hub_->perAddress.erase(it);
  }
  ConnectionSlot(ConnectionSlot&& other) noexcept : hub_(other.hub_), address_(std::move(other.address_)) {
    other.hub_ = nullptr;
  }
  ConnectionSlot(const ConnectionSlot&) = delete;
  ConnectionSlot& operator=(const ConnectionSlot&) = delete;
  ConnectionSlot& operator=(ConnectionSlot&&) = delete;
  const std::string& address() const { return address_; }

 private:
  WebHub* hub_;
  std::string address_;
};

}  // namespace vitrine::remote
