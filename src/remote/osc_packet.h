#pragma once
// An OSC packet's messages: the packet itself when it is a message, or the elements of a bundle
// ("#bundle", a time tag, then size-prefixed elements, possibly bundles themselves), flattened in
// order. Time tags are ignored: everything is applied before the next update. Pure and bounded
// (nesting depth, message count); fuzzed with the other parsers.
#include "remote/messages.h"

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace vitrine::remote {

inline constexpr int kMaxBundleDepth = 4;
inline constexpr size_t kMaxMessagesPerPacket = 64;

struct OscMessage {
  std::string path;
  std::vector<OscArgument> args;
};

// The byte ranges of the packet's messages; false with *error set when the framing is broken.
bool splitOscPacket(std::span<const std::byte> packet, std::vector<std::span<const std::byte>>& messages,
                    std::string& error);

// One message's address and arguments, decoded (and validated) by liblo. False with *error set when
// the bytes are not an OSC message.
bool decodeOscMessage(std::span<const std::byte> bytes, OscMessage& message, std::string& error);

}  // namespace vitrine::remote
