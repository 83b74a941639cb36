#include "remote/remote_control.h"

#include "remote/access_token.h"
#include "remote/socket_address.h"

#include <fmt/format.h>

#include <stdexcept>

namespace vitrine::remote {

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
  for (int attempt = 0;; ++attempt) {
    osc_ = std::make_unique<OscServer>(bind_, *catalogue_, inbox_, stats_, config.osc, access);
    try {
      web_ = std::make_unique<WebServer>(BindAddress{bind_.address, osc_->port()}, token_, *catalogue_, inbox_,
                                         stats_, config.web);
      break;
    } catch (const std::runtime_error&) {
      osc_.reset();
      if (bind_.port != 0 || attempt + 1 == kAttempts) throw;
    }
  }
  port_ = osc_->port();
  bind_.port = port_;
}

RemoteControl::~RemoteControl() {
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
