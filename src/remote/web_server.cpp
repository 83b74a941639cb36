#include "remote/web_server.h"

#include "remote/http_session.h"
#include "remote/page.h"
#include "remote/socket_session.h"
#include "remote/web_hub.h"

#include <boost/asio.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <climits>
#include <thread>

namespace vitrine::remote {

namespace net = boost::asio;
using tcp = net::ip::tcp;

struct WebServer::Impl {
  // Declared before the I/O context, so sessions (destroyed with the context's pending handlers)
  // can still unregister from it.
  WebHub hub;
  net::io_context io{1};
  tcp::acceptor acceptor{io};
  net::steady_timer retry{io};  // after a failed accept (out of descriptors): pause, do not spin
  std::thread thread;
  uint16_t port = 0;

  Impl(const BindAddress& bind, std::string token, const Catalogue& catalogue, RemoteInbox& inbox,
       RemoteStats& stats, WebLimits limits, std::shared_ptr<const OscTrust> trust)
      : hub{std::move(token), catalogue, inbox, stats, limits, pageHtml(), std::move(trust), machineName()} {
    boost::system::error_code error;
    const auto address = net::ip::make_address(bind.address, error);
    const auto failed = [&](std::string_view what) {
      return std::runtime_error(
          fmt::format("Cannot {} the remote page on TCP {}: {}", what, formatBind(bind), error.message()));
    };
    if (error) throw failed("parse the address of");
    const tcp::endpoint endpoint(address, bind.port);
    if (acceptor.open(endpoint.protocol(), error)) throw failed("open a socket for");
    if (acceptor.set_option(net::socket_base::reuse_address(true), error)) throw failed("configure");
    if (acceptor.bind(endpoint, error)) throw failed("listen for");
    if (acceptor.listen(net::socket_base::max_listen_connections, error)) throw failed("listen for");
    port = acceptor.local_endpoint().port();
    hub.host.oscPort = port;  // OSC listens on the same port, over UDP
    if (bind.address != "0.0.0.0" && bind.address != "::") hub.host.oscAddress = bind.address;
    accept();
    thread = std::thread([this] { io.run(); });
  }

  ~Impl() {
    io.stop();
    thread.join();
  }

  static std::string machineName() {
    char name[HOST_NAME_MAX + 1] = {};
    return ::gethostname(name, sizeof name - 1) == 0 ? std::string(name) : std::string();
  }

  void accept() {
    acceptor.async_accept([this](boost::system::error_code error, tcp::socket socket) {
      if (error) {
        if (error == net::error::operation_aborted) return;
        retry.expires_after(std::chrono::milliseconds(100));
        retry.async_wait([this](boost::system::error_code waited) {
          if (!waited) accept();
        });
        return;
      }
      boost::system::error_code ignored;
      const std::string address = socket.remote_endpoint(ignored).address().to_string();
      if (makeRoom(address)) {
        std::make_shared<HttpSession>(std::move(socket), hub, address)->start();
      } else {
        count(hub.stats.connectionsRefused);
        socket.close(ignored);
      }
      accept();
    });
  }

  // Whether a new connection from `address` fits, once the oldest strangers in its way are closed:
  // its address's own first when that address is at its limit, else anyone's. Holders of the token
  // are never closed for a newcomer; when they alone fill a limit, the newcomer is refused.
  bool makeRoom(const std::string& address) {
    const auto fromAddress = [&] {
      const auto it = hub.perAddress.find(address);
      return it == hub.perAddress.end() ? size_t(0) : it->second;
    };
    const auto evictOldest = [&](bool sameAddress) {
      for (HttpSession* stranger : hub.strangers)
        if (!sameAddress || stranger->address() == address) {
          stranger->evict();  // leaves the list and gives its slot back at once
          return true;
        }
      return false;
    };
    while (fromAddress() >= hub.limits.maxPerAddress)
      if (!evictOldest(true)) return false;
    while (hub.connections >= hub.limits.maxConnections || hub.strangers.size() >= hub.limits.maxStrangers)
      if (!evictOldest(false)) return false;
    return true;
  }

  // The values OSCQuery reports: those that changed are streamed to the sockets listening to them.
  void updateValues(const PageState& page) {
    std::vector<std::string> changed;
    if (page.scene != hub.values.scene) {
      hub.values.scene = page.scene;
      changed.emplace_back("/vitrine/scene");
    }
    auto& stored = hub.values.values[page.scene];
    for (const auto& [key, text] : page.values) {
      const auto it = stored.find(key);
      if (it != stored.end() && it->second == text) continue;
      stored.insert_or_assign(key, text);
      changed.push_back(fmt::format("/vitrine/{}/{}", page.scene, key));
    }
    if (!changed.empty())
      for (SocketSession* socket : hub.querySockets) socket->valuesChanged(changed);
  }

  // On the I/O thread: the state as JSON, sent to every open socket unless unchanged.
  void broadcast(const PageState& page) {
    updateValues(page);
    nlohmann::json object = nlohmann::json::object();
    for (const auto& [key, text] : page.values) object[key] = text;
    nlohmann::json rig = nlohmann::json::array();
    for (const rig::RigLine& line : page.rig) rig.push_back({{"name", line.name}, {"ok", line.ok}, {"text", line.text}});
    auto state = std::make_shared<const std::string>(
        nlohmann::json{{"type", "state"}, {"scene", page.scene}, {"values", std::move(object)},
                       {"mappings", page.mappings}, {"user_presets", page.userPresets},
                       {"rig", std::move(rig)}}
            .dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
    if (hub.lastState && *hub.lastState == *state) return;
    hub.lastState = state;
    for (SocketSession* socket : hub.openSockets) socket->sendState(state);
  }
};

WebServer::WebServer(const BindAddress& bind, std::string token, const Catalogue& catalogue, RemoteInbox& inbox,
                     RemoteStats& stats, WebLimits limits, std::shared_ptr<const OscTrust> trust)
    : impl_(std::make_unique<Impl>(bind, std::move(token), catalogue, inbox, stats, limits, std::move(trust))) {}

WebServer::~WebServer() = default;

uint16_t WebServer::port() const { return impl_->port; }

void WebServer::publish(PageState state) {
  net::post(impl_->io, [impl = impl_.get(), state = std::move(state)] { impl->broadcast(state); });
}

void WebServer::tell(std::string client, std::string reason) {
  net::post(impl_->io, [impl = impl_.get(), client = std::move(client), reason = std::move(reason)] {
    for (SocketSession* socket : impl->hub.openSockets)
      if (socket->client() == client) socket->refuse(reason);
  });
}

size_t WebServer::sockets() const { return impl_->hub.sockets.load(); }

}  // namespace vitrine::remote
