#include "remote/remote_control.h"

#include "remote/access_token.h"
#include "remote/socket_address.h"

#include <fmt/format.h>
#include <ifaddrs.h>
#include <net/if.h>
#include <netinet/in.h>
#include <unistd.h>

#include <climits>
#include <cstring>
#include <stdexcept>

namespace vitrine::remote {
namespace {

// The interface that holds `address` (a bind to one address is announced there alone); -1 for a
// wildcard bind or an address no interface holds (then every interface: the announcement says less
// than it could, never something wrong).
int interfaceOf(const std::string& address) {
  if (address == "0.0.0.0" || address == "::") return -1;
  ifaddrs* list = nullptr;
  if (::getifaddrs(&list) != 0) return -1;
  int index = -1;
  for (const ifaddrs* entry = list; entry && index < 0; entry = entry->ifa_next)
    if (entry->ifa_addr && (entry->ifa_addr->sa_family == AF_INET || entry->ifa_addr->sa_family == AF_INET6)) {
      sockaddr_storage storage{};
      std::memcpy(&storage, entry->ifa_addr,
                  entry->ifa_addr->sa_family == AF_INET ? sizeof(sockaddr_in) : sizeof(sockaddr_in6));
      if (peerHost(storage) == address) index = int(::if_nametoindex(entry->ifa_name));
    }
  ::freeifaddrs(list);
  return index == 0 ? -1 : index;
}

std::string serviceName() {
  char host[HOST_NAME_MAX + 1] = {};
  if (::gethostname(host, sizeof host - 1) != 0 || !host[0]) return "Vitrine";
  return fmt::format("Vitrine on {}", std::string(host).substr(0, 40));  // DNS-SD names: 63 bytes at most
}

}  // namespace

RemoteControl::RemoteControl(RemoteConfig config, Catalogue catalogue)
    : bind_(config.bind),
      token_(config.token.empty() ? makeAccessToken() : config.token),
      catalogue_(std::make_unique<const Catalogue>(std::move(catalogue))),
      inbox_(config.inboxCapacity) {
  // UDP first: with port 0 the kernel picks one, and TCP then asks for the same number, which is
  // almost always free too; if not, both try again with a new pick.
  constexpr int kAttempts = 16;
  OscAccess access{.open = isLoopbackAddress(bind_.address), .allow = config.oscAllow, .token = token_};
  access.allow.push_back(parseNetwork("127.0.0.0/8"));  // a wildcard bind hears this computer too
  access.allow.push_back(parseNetwork("::1"));
  // One rule for OSC and OSCQuery: whoever may send OSC may read what it can do, and no one else.
  const auto trust = std::make_shared<OscTrust>(std::move(access));
  for (int attempt = 0;; ++attempt) {
    osc_ = std::make_unique<OscServer>(bind_, *catalogue_, inbox_, stats_, config.osc, trust);
    try {
      web_ = std::make_unique<WebServer>(BindAddress{bind_.address, osc_->port()}, token_, *catalogue_, inbox_,
                                         stats_, config.web, trust);
      break;
    } catch (const std::runtime_error&) {
      osc_.reset();
      if (bind_.port != 0 || attempt + 1 == kAttempts) throw;
    }
  }
  port_ = osc_->port();
  bind_.port = port_;
  if (config.announce && !isLoopbackAddress(bind_.address))
    mdns_ = std::make_unique<MdnsAnnouncer>(serviceName(), port_, interfaceOf(bind_.address), std::move(config.say));
}

RemoteControl::~RemoteControl() {
  mdns_.reset();
  web_.reset();
  osc_.reset();
}

std::string RemoteControl::pageUrl() const {
  // A wildcard bind is no address a phone can open: name one of this machine's network addresses.
  BindAddress shown = bind_;
  if (bind_.address == "0.0.0.0" || bind_.address == "::") shown.address = networkAddress();
  return fmt::format("http://{}/?token={}", formatBind(shown), token_);
}

}  // namespace vitrine::remote
