#pragma once
// OSC over UDP: a socket bound to the remote control's address and port, read on its own thread.
// Each datagram is size-checked, rate-limited per sender IP, split into messages, decoded by liblo,
// turned into commands, checked against the catalogue and queued in the inbox; everything else is
// counted and dropped. The socket is read with recvfrom rather than through lo_server so that the
// bind address, truncated datagrams and malformed packets are ours to see and count.
#include "remote/bind_address.h"
#include "remote/catalogue.h"
#include "remote/inbox.h"
#include "remote/network.h"
#include "remote/osc_trust.h"
#include "remote/rate_limiter.h"
#include "remote/stats.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <span>
#include <thread>
#include <vector>

namespace vitrine::remote {

struct OscLimits {
  size_t maxDatagram = 1024;  // bytes; larger datagrams are refused whole
  RateLimit perSender{};      // messages (not datagrams) per sender IP address
};

class OscServer {
 public:
  // Binds at once (port 0: a free one); throws std::runtime_error saying why it cannot.
  OscServer(const BindAddress& bind, const Catalogue& catalogue, RemoteInbox& inbox, RemoteStats& stats,
            OscLimits limits = {}, OscAccess access = {});
  // The same, with who may send shared with the OSCQuery responder (RemoteControl).
  OscServer(const BindAddress& bind, const Catalogue& catalogue, RemoteInbox& inbox, RemoteStats& stats,
            OscLimits limits, std::shared_ptr<OscTrust> trust);
  ~OscServer();  // stops and joins the thread promptly
  OscServer(const OscServer&) = delete;
  OscServer& operator=(const OscServer&) = delete;

  uint16_t port() const { return port_; }

 private:
  void run();
  void receive();
  void handleMessage(std::span<const std::byte> bytes, const std::string& sender);

  const Catalogue& catalogue_;
  RemoteInbox& inbox_;
  RemoteStats& stats_;
  OscLimits limits_;
  SenderBudgets budgets_;        // the server thread's alone
  // Who may send (UDP carries no session for a token): beyond loopback, an allowed network or an
  // address that sent "/vitrine/token s TOKEN" once; everyone else is counted as unauthorised.
  std::shared_ptr<OscTrust> trust_;
  std::vector<std::byte> buffer_;  // one datagram, one byte over the limit to see oversized ones
  int socket_ = -1;
  int wake_ = -1;  // an eventfd: written by the destructor to end the poll at once
  uint16_t port_ = 0;
  std::thread thread_;
};

}  // namespace vitrine::remote
