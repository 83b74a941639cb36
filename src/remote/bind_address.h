#pragma once
// Where the remote control listens: --remote-bind ADDR:PORT. The same port serves OSC over UDP and
// the page over TCP.
#include <cstdint>
#include <string>
#include <string_view>

namespace vitrine::remote {

struct BindAddress {
  std::string address = "127.0.0.1";  // loopback unless the user says otherwise
  uint16_t port = 8730;               // 0: any free port (tests)
};

// "127.0.0.1:8730", "0.0.0.0:9000", "[::1]:8730", "[::]:0". Numeric addresses only (a host name would
// need a resolver at start-up and may name several addresses). Throws std::invalid_argument with a
// sentence saying what is wrong.
BindAddress parseBind(std::string_view text);
// "127.0.0.1:8730", "[::1]:8730": the form parseBind reads and a URL uses.
std::string formatBind(const BindAddress& bind);

}  // namespace vitrine::remote
