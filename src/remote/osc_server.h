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
#include "remote/rate_limiter.h"
#include "remote/stats.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <span>
#include <thread>
#include <vector>

namespace vitrine::remote {

struct OscLimits {
  size_t maxDatagram = 1024;  // bytes; larger datagrams are refused whole
  RateLimit perSender{};      // messages (not datagrams) per sender IP address
};

// Who may send. UDP carries no session for a token, so beyond loopback a sender must be in an
// allowed network (--remote-allow), or first send "/vitrine/token s TOKEN": its address is then
// trusted for the run (the most recent `maxTrusted` of them). Everyone else is counted as
// unauthorised and ignored.
struct OscAccess {
  bool open = true;                   // a loopback bind: only this computer can send anyway
  std::vector<Network> allow;         // otherwise: these networks need no token
  std::string token;                  // ... and a sender that sends it is trusted
  size_t maxTrusted = 64;
};

class OscServer {
 public:
  // Binds at once (port 0: a free one); throws std::runtime_error saying why it cannot.
  OscServer(const BindAddress& bind, const Catalogue& catalogue, RemoteInbox& inbox, RemoteStats& stats,
            OscLimits limits = {}, OscAccess access = {});
  ~OscServer();  // stops and joins the thread promptly
  OscServer(const OscServer&) = delete;
  OscServer& operator=(const OscServer&) = delete;

  uint16_t port() const { return port_; }

 private:
  void run();
  void receive();
  void handleMessage(std::span<const std::byte> bytes, const std::string& sender);
  bool allowed(const std::string& sender) const;
  void trust(const std::string& sender);

  const Catalogue& catalogue_;
  RemoteInbox& inbox_;
  RemoteStats& stats_;
  OscLimits limits_;
  SenderBudgets budgets_;        // the server thread's alone
  OscAccess access_;
  std::vector<std::string> trusted_;  // senders that sent the token, oldest first (the thread's alone)
  std::vector<std::byte> buffer_;  // one datagram, one byte over the limit to see oversized ones
  int socket_ = -1;
  int wake_ = -1;  // an eventfd: written by the destructor to end the poll at once
  uint16_t port_ = 0;
  std::thread thread_;
};

}  // namespace vitrine::remote
