#pragma once
// Remote play: the one object the host owns while --remote is on. It makes the access token, listens
// for OSC (UDP) and serves the control page (HTTP + WebSocket, TCP) on the same address and port, and
// hands the main thread what clients asked for. The main thread only calls drain() and publish();
// neither blocks on the network. Destroying it stops both servers and joins their threads.
//
//   remote::RemoteControl remote({.address = "127.0.0.1", .port = 8730});
//   std::printf("Remote control: %s\n", remote.pageUrl().c_str());
//   each frame:  for (auto& command : remote.drain()) apply(command);   // then, if anything changed:
//                remote.publish({scene.name, params::snapshot(bound)});
#include "params/schema.h"
#include "remote/bind_address.h"
#include "remote/catalogue.h"
#include "remote/command.h"
#include "remote/inbox.h"
#include "remote/mdns_announcer.h"
#include "remote/osc_server.h"
#include "remote/stats.h"
#include "remote/web_server.h"

#include <memory>
#include <string>
#include <vector>

namespace vitrine::remote {

struct RemoteConfig {
  BindAddress bind;      // port 0: a free port, the same for UDP and TCP (tests)
  std::string token;     // empty: a fresh random one (tests pass their own)
  size_t inboxCapacity = 1024;
  OscLimits osc{};
  WebLimits web{};
  // --remote-allow: beyond a loopback bind, OSC from these networks needs no token (this computer's
  // own loopback addresses never do); anyone else must send the token first (OscAccess).
  std::vector<Network> oscAllow;
  // Announce OSCQuery and OSC over mDNS through Avahi (not for a loopback bind: only this computer
  // could reach it). `say` gets the announcer's console lines, on Avahi's thread.
  bool announce = false;
  MdnsAnnouncer::Say say;
};

class RemoteControl {
 public:
  // Throws std::runtime_error when it cannot listen (the port is taken, the address is not local).
  explicit RemoteControl(RemoteConfig config, Catalogue catalogue = Catalogue());
  ~RemoteControl();
  RemoteControl(const RemoteControl&) = delete;
  RemoteControl& operator=(const RemoteControl&) = delete;

  std::string pageUrl() const;  // http://127.0.0.1:8730/?token=...; IPv6 in brackets
  const std::string& token() const { return token_; }
  uint16_t port() const { return port_; }
  const BindAddress& bind() const { return bind_; }
  const Catalogue& catalogue() const { return *catalogue_; }

  std::vector<RemoteCommand> drain() { return inbox_.drain(); }
  std::vector<RemoteInbox::Refusal> drainRefusals() { return inbox_.drainRefusals(); }
  void publish(PageState state) { web_->publish(std::move(state)); }
  // Why the gallery refused a client's command, told to that client where it can be (a page; an OSC
  // controller has no reply channel: the host logs it).
  void tell(const std::string& client, std::string reason) {
    if (client.starts_with("ws ")) web_->tell(client, std::move(reason));
  }
  RemoteStatsSnapshot stats() const { return stats_.snapshot(); }
  const MdnsAnnouncer* announcer() const { return mdns_.get(); }  // null where not announced
  size_t sockets() const { return web_->sockets(); }

 private:
  BindAddress bind_;
  std::string token_;
  uint16_t port_ = 0;
  std::unique_ptr<const Catalogue> catalogue_;  // stable address for the servers' threads
  RemoteInbox inbox_;
  RemoteStats stats_;
  std::unique_ptr<OscServer> osc_;  // destroyed (threads joined) before what they point to
  std::unique_ptr<WebServer> web_;
  std::unique_ptr<MdnsAnnouncer> mdns_;  // withdrawn first, before the servers close
};

}  // namespace vitrine::remote
