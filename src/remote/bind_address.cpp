#include "remote/bind_address.h"

#include <arpa/inet.h>
#include <fmt/format.h>

#include <charconv>
#include <stdexcept>

namespace vitrine::remote {
namespace {

bool isIpv4(const std::string& text) {
  in_addr parsed{};
  return inet_pton(AF_INET, text.c_str(), &parsed) == 1;
}

bool isIpv6(const std::string& text) {
  in6_addr parsed{};
  return inet_pton(AF_INET6, text.c_str(), &parsed) == 1;
}

}  // namespace

BindAddress parseBind(std::string_view text) {
  const auto fail = [&](std::string_view why) {
    return std::invalid_argument(fmt::format("--remote-bind expects ADDR:PORT (127.0.0.1:8730, 0.0.0.0:8730, "
                                             "[::1]:8730), not '{}': {}", text, why));
  };
  const size_t colon = text.rfind(':');
  if (colon == std::string_view::npos) throw fail("no ':PORT'");
  std::string_view host = text.substr(0, colon);
  const std::string_view portText = text.substr(colon + 1);

  BindAddress bind;
  const bool bracketed = host.size() >= 2 && host.front() == '[' && host.back() == ']';
  if (bracketed) host = host.substr(1, host.size() - 2);
  bind.address = std::string(host);
  if (bind.address.empty()) throw fail("no address");
  if (bracketed ? !isIpv6(bind.address) : !isIpv4(bind.address)) {
    if (!bracketed && isIpv6(bind.address)) throw fail("write an IPv6 address in brackets, [::1]:8730");
    throw fail(fmt::format("'{}' is not a numeric IP{} address", bind.address, bracketed ? "v6" : "v4"));
  }

  unsigned port = 0;
  const auto [end, ec] = std::from_chars(portText.data(), portText.data() + portText.size(), port);
  if (portText.empty() || ec != std::errc() || end != portText.data() + portText.size() || port > 65535)
    throw fail("the port is a whole number from 0 to 65535");
  bind.port = uint16_t(port);
  return bind;
}

std::string formatBind(const BindAddress& bind) {
  if (bind.address.find(':') != std::string::npos) return fmt::format("[{}]:{}", bind.address, bind.port);
  return fmt::format("{}:{}", bind.address, bind.port);
}

}  // namespace vitrine::remote
