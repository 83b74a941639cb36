#pragma once
// Who may use the OSC interface without the page's token: everyone on a loopback bind (only this
// computer can reach it), else the --remote-allow networks and this computer's loopback addresses,
// and any address that sent the token once as /vitrine/token. Shared by the OSC server (which
// trusts senders) and the OSCQuery responder (which describes the same interface to the same
// clients), so the two can never disagree. Thread-safe: each server's thread asks it.
#include "remote/network.h"

#include <cstddef>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

namespace vitrine::remote {

struct OscAccess {
  bool open = true;                   // a loopback bind: only this computer can send anyway
  std::vector<Network> allow;         // otherwise: these networks need no token
  std::string token;                  // ... and a sender that sends it is trusted
  size_t maxTrusted = 64;
};

class OscTrust {
 public:
  explicit OscTrust(OscAccess access = {}) : access_(std::move(access)) {}

  // Whether `address` (numeric, as peerHost gives it) may send OSC and read the OSCQuery namespace.
  bool allowed(std::string_view address) const;
  // Checks `token` (constant time); on a match trusts `address` for the rest of the run (the most
  // recent maxTrusted of them) and returns true.
  bool offer(std::string_view address, std::string_view token);
  const std::string& token() const { return access_.token; }

 private:
  const OscAccess access_;
  mutable std::mutex mutex_;
  std::vector<std::string> trusted_;  // senders that sent the token, oldest first
};

// Whether a request without the token may be a native OSCQuery client's (ossia, VDMX, TouchDesigner)
// rather than something a web page made a browser send: browsers add Origin to every WebSocket upgrade
// and cross-origin request, and a page that rebinds its own domain to this computer's address names
// that domain in Host. So: no Origin header, and a Host that is an address literal ("192.168.1.20:8730",
// "[::1]:8730"), "localhost", or this computer's name (`machineName`, or it with ".local", as mDNS
// resolves it), with an optional port.
bool nativeClientRequest(bool hasOrigin, std::string_view host, std::string_view machineName);

}  // namespace vitrine::remote
