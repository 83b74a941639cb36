#include "remote/network.h"

#include <arpa/inet.h>
#include <fmt/format.h>

#include <charconv>
#include <cstring>
#include <optional>
#include <stdexcept>

namespace vitrine::remote {
namespace {

// The address as a network of one host; an IPv4-mapped IPv6 address becomes IPv4.
std::optional<Network> host(std::string_view text) {
  if (text.size() >= INET6_ADDRSTRLEN) return std::nullopt;
  const std::string address(text);
  Network network;
  in_addr v4{};
  in6_addr v6{};
  if (inet_pton(AF_INET, address.c_str(), &v4) == 1) {
    std::memcpy(network.address.data(), &v4, 4);
    return network;
  }
  if (inet_pton(AF_INET6, address.c_str(), &v6) != 1) return std::nullopt;
  static constexpr uint8_t kMapped[12] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0xff, 0xff};
  if (std::memcmp(v6.s6_addr, kMapped, 12) == 0) {
    std::memcpy(network.address.data(), v6.s6_addr + 12, 4);
    return network;
  }
  network.v6 = true;
  network.prefix = 128;
  std::memcpy(network.address.data(), v6.s6_addr, 16);
  return network;
}

bool prefixMatches(const std::array<uint8_t, 16>& a, const std::array<uint8_t, 16>& b, int bits) {
  const int whole = bits / 8;
  if (std::memcmp(a.data(), b.data(), size_t(whole)) != 0) return false;
  if (bits % 8 == 0) return true;
  const uint8_t mask = uint8_t(0xff << (8 - bits % 8));
  return (a[size_t(whole)] & mask) == (b[size_t(whole)] & mask);
}

}  // namespace

Network parseNetwork(std::string_view text) {
  const auto fail = [&](std::string_view why) {
    return std::invalid_argument(
        fmt::format("expected a network as ADDR/BITS (192.168.1.0/24, fd00::/8) or one address, not '{}': {}",
                    text.substr(0, 64), why));
  };
  const size_t slash = text.find('/');
  const std::optional<Network> parsed = host(text.substr(0, slash));
  if (!parsed) throw fail("not a numeric IP address");
  Network network = *parsed;
  const int most = network.v6 ? 128 : 32;
  if (slash != std::string_view::npos) {
    const std::string_view bits = text.substr(slash + 1);
    int prefix = -1;
    const auto [end, ec] = std::from_chars(bits.data(), bits.data() + bits.size(), prefix);
    if (bits.empty() || ec != std::errc() || end != bits.data() + bits.size() || prefix < 0 || prefix > most)
      throw fail(fmt::format("the prefix is a whole number from 0 to {}", most));
    network.prefix = prefix;
  }
  std::array<uint8_t, 16> masked = network.address;
  for (int bit = network.prefix; bit < most; ++bit) masked[size_t(bit / 8)] &= uint8_t(~(0x80 >> (bit % 8)));
  if (masked != network.address)
    throw fail(fmt::format("bits are set past the prefix; the network is {}",
                           formatNetwork(Network{network.v6, masked, network.prefix})));
  return network;
}

std::string formatNetwork(const Network& network) {
  char text[INET6_ADDRSTRLEN] = {};
  inet_ntop(network.v6 ? AF_INET6 : AF_INET, network.address.data(), text, sizeof text);
  return fmt::format("{}/{}", text, network.prefix);
}

bool contains(const Network& network, std::string_view address) {
  const std::optional<Network> parsed = host(address);
  return parsed && parsed->v6 == network.v6 && prefixMatches(parsed->address, network.address, network.prefix);
}

bool isLoopbackAddress(std::string_view address) {
  static const Network v4 = parseNetwork("127.0.0.0/8"), v6 = parseNetwork("::1");
  return contains(v4, address) || contains(v6, address);
}

}  // namespace vitrine::remote
