// OSC datagrams as the remote control reads them (src/remote/osc_packet.h, messages.h): a packet is
// split into messages (bundles within limits), each decoded by liblo and mapped to a command; every
// step either succeeds or says why, whatever the bytes.
#include "remote/messages.h"
#include "remote/osc_packet.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <vector>
#include "support/require.h"

using namespace vitrine::remote;

using vitrine::fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const Catalogue catalogue;
  const std::span<const std::byte> packet(reinterpret_cast<const std::byte*>(data), size);
  std::vector<std::span<const std::byte>> messages;
  std::string error;
  if (!splitOscPacket(packet, messages, error)) {
    require(!error.empty(), "a refused packet without a reason");
    return 0;
  }
  require(messages.size() <= kMaxMessagesPerPacket, "more messages than a packet may carry");
  for (const auto& bytes : messages) {
    OscMessage message;
    std::string why;
    if (!decodeOscMessage(bytes, message, why)) {
      require(!why.empty(), "a refused message without a reason");
      continue;
    }
    const ParseResult result = commandFromOsc(message.path, message.args, catalogue);
    require(result.command.has_value() == result.error.empty(), "neither a command nor a reason, or both");
  }
  return 0;
}
