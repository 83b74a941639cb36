#pragma once
// Networks for --remote-allow ("192.168.1.0/24", "10.0.0.7", "fd00::/8"): who may send OSC without
// the token when the remote control listens beyond loopback. Pure: numeric addresses only, no resolver.
#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace vitrine::remote {

struct Network {
  bool v6 = false;
  std::array<uint8_t, 16> address{};  // IPv4 in the first 4 bytes; bits past the prefix are zero
  int prefix = 32;                    // leading bits that must match: 0..32 (IPv4), 0..128 (IPv6)
};

// "ADDR/BITS" or a bare address (one host). Throws std::invalid_argument with a sentence: not an
// address, a prefix out of range, host bits set ("192.168.1.7/24" is meant as 192.168.1.0/24, but
// saying so is kinder than guessing).
Network parseNetwork(std::string_view text);
std::string formatNetwork(const Network& network);  // "192.168.1.0/24"
// Whether the numeric `address` ("192.168.1.20", "::1", "::ffff:192.168.1.20", as peerHost gives
// it) lies in `network`. An IPv4-mapped IPv6 address is its IPv4 address. False for anything else.
bool contains(const Network& network, std::string_view address);
// 127.0.0.0/8 or ::1: only this computer can reach such a bind, so it needs no allow-list.
bool isLoopbackAddress(std::string_view address);

}  // namespace vitrine::remote
