#pragma once
// The control page over HTTP and its WebSocket, on one TCP port, served by Boost.Beast on one I/O
// thread. Every request and socket must carry ?token=...; the page and catalogue are read-only, and
// a socket's messages become commands in the inbox after the same checks as OSC. Boost stays inside
// the .cpp files: the host includes this header without it.
#include "params/schema.h"
#include "remote/bind_address.h"
#include "remote/catalogue.h"
#include "remote/inbox.h"
#include "remote/osc_trust.h"
#include "remote/oscquery_stream.h"
#include "remote/rate_limiter.h"
#include "remote/stats.h"

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include "rig/rig_report.h"

namespace vitrine::remote {

struct WebLimits {
  size_t maxRequestHeader = 8 * 1024;  // bytes of a request line and headers
  size_t maxRequestBody = 1024;        // GET only: anything sizeable is not for us
  size_t maxSocketMessage = 4096;      // bytes of one WebSocket message; larger closes the socket
  size_t maxSockets = 32;              // open WebSockets (phones) at once
  size_t maxConnections = 64;          // TCP connections of any kind at once
  size_t maxPerAddress = 16;           // from one IP address (a browser opens six at most)
  // Connections that have not shown the token yet, at most; the rest of maxConnections is kept for
  // those that have. A new connection beyond either limit takes the place of the oldest stranger
  // (from its own address first), which is closed: a phone's request, sent at once, always gets in.
  size_t maxStrangers = 48;
  std::chrono::milliseconds firstRequestTimeout{3'000};  // for a connection that has not shown the token
  size_t maxQueuedReplies = 8;         // per socket, for a client that reads slowly; more are dropped
  std::chrono::milliseconds requestTimeout{10'000};  // to send one whole request (slow clients)
  std::chrono::milliseconds socketIdle{30'000};      // silence before a ping, and again before closing
  RateLimit perSocket{};
  StreamLimits stream{};  // an OSCQuery socket's LISTEN set and value rate
};

// What every page is sent about the gallery ({"type":"state",...}).
struct PageState {
  std::string scene;
  params::KeyValues values;
  std::vector<std::string> mappings;     // the live mapping lines playing the scene
  std::vector<std::string> userPresets;  // the names of the user's presets of the scene
  std::vector<rig::RigLine> rig;         // the clocks followed and the outputs published
};

class WebServer {
 public:
  // Binds at once (port 0: a free one); throws std::runtime_error saying why it cannot. `trust`: who
  // may use OSCQuery without the token (OSC's own rule); null: nobody.
  WebServer(const BindAddress& bind, std::string token, const Catalogue& catalogue, RemoteInbox& inbox,
            RemoteStats& stats, WebLimits limits = {}, std::shared_ptr<const OscTrust> trust = nullptr);
  ~WebServer();  // closes every connection and joins the I/O thread
  WebServer(const WebServer&) = delete;
  WebServer& operator=(const WebServer&) = delete;

  uint16_t port() const;
  // Any thread, cheap: the state every socket is sent, now and to each new socket on connect. The JSON
  // is made on the I/O thread; an unchanged state is not resent. Its values are also what OSCQuery
  // reports, and those that changed are streamed to the OSCQuery sockets listening to them.
  void publish(PageState state);
  // Any thread: tells the page whose command it was (RemoteCommand::client) why the gallery refused it,
  // as the server's own refusals are told; nothing when that page has gone.
  void tell(std::string client, std::string reason);
  size_t sockets() const;  // open WebSockets, for tests and a status line

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace vitrine::remote
