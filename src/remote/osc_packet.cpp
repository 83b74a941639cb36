#include "remote/osc_packet.h"

#include <lo/lo.h>

#include <cstring>
#include <memory>

namespace vitrine::remote {
namespace {

constexpr char kBundleTag[8] = {'#', 'b', 'u', 'n', 'd', 'l', 'e', '\0'};

bool isBundle(std::span<const std::byte> bytes) {
  return bytes.size() >= sizeof kBundleTag && std::memcmp(bytes.data(), kBundleTag, sizeof kBundleTag) == 0;
}

uint32_t bigEndian32(const std::byte* p) {
  return (uint32_t(p[0]) << 24) | (uint32_t(p[1]) << 16) | (uint32_t(p[2]) << 8) | uint32_t(p[3]);
}

bool split(std::span<const std::byte> packet, int depth, std::vector<std::span<const std::byte>>& messages,
           std::string& error) {
  if (!isBundle(packet)) {
    if (messages.size() >= kMaxMessagesPerPacket) {
      error = "more messages in one packet than " + std::to_string(kMaxMessagesPerPacket);
      return false;
    }
    messages.push_back(packet);
    return true;
  }
  if (depth >= kMaxBundleDepth) {
    error = "bundles nested too deeply";
    return false;
  }
  constexpr size_t kHeader = 16;  // "#bundle\0" and the time tag
  if (packet.size() < kHeader) {
    error = "a bundle without its time tag";
    return false;
  }
  size_t offset = kHeader;
  while (offset < packet.size()) {
    if (packet.size() - offset < 4) {
      error = "a bundle element's size is cut off";
      return false;
    }
    const uint32_t size = bigEndian32(packet.data() + offset);
    offset += 4;
    if (size == 0 || size % 4 != 0 || size > packet.size() - offset) {
      error = "a bundle element's size does not fit the packet";
      return false;
    }
    if (!split(packet.subspan(offset, size), depth + 1, messages, error)) return false;
    offset += size;
  }
  return true;
}

struct MessageDeleter {
  void operator()(lo_message message) const { lo_message_free(message); }
};
using OwnedMessage = std::unique_ptr<std::remove_pointer_t<lo_message>, MessageDeleter>;

// A number of type T from an argument's bytes, copied out (they need not be aligned for T); 0 without bytes.
template <typename T>
T load(const char* data) {
  T value{};
  if (data) std::memcpy(&value, data, sizeof value);
  return value;
}

}  // namespace

bool splitOscPacket(std::span<const std::byte> packet, std::vector<std::span<const std::byte>>& messages,
                    std::string& error) {
  messages.clear();
  return split(packet, 0, messages, error);
}

bool decodeOscMessage(std::span<const std::byte> bytes, OscMessage& message, std::string& error) {
  // liblo byte-swaps in place while it validates: it gets its own copy.
  std::vector<std::byte> copy(bytes.begin(), bytes.end());
  int result = 0;
  OwnedMessage decoded(lo_message_deserialise(copy.data(), copy.size(), &result));
  if (!decoded) {
    error = "not an OSC message (liblo error " + std::to_string(result) + ")";
    return false;
  }
  // The address is the packet's first string, which deserialise has validated as terminated.
  message.path.assign(reinterpret_cast<const char*>(bytes.data()), strnlen(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
  message.args.clear();
  const char* types = lo_message_get_types(decoded.get());
  lo_arg** argv = lo_message_get_argv(decoded.get());
  const int argc = lo_message_get_argc(decoded.get());
  for (int i = 0; i < argc && types && types[i]; ++i) {
    OscArgument arg{.type = types[i]};
    // An argument's bytes, as liblo points at them: null for the types that carry none (T, F, N, I), and
    // only 4-byte aligned in the packet, so an 8-byte lo_arg (h, d) is never read in place (UBSan found
    // both: a reference bound to a null and to a misaligned lo_arg).
    const char* data = reinterpret_cast<const char*>(argv ? argv[i] : nullptr);
    switch (types[i]) {
      case LO_INT32: arg.number = load<int32_t>(data); break;
      case LO_INT64: arg.number = double(load<int64_t>(data)); break;
      case LO_FLOAT: arg.number = load<float>(data); break;
      case LO_DOUBLE: arg.number = load<double>(data); break;
      case LO_TRUE: arg.number = 1.0; break;
      case LO_FALSE: arg.number = 0.0; break;
      case LO_STRING:
      case LO_SYMBOL:
        if (data) arg.text = data;
        break;
      default: break;  // blobs, MIDI, time tags, nil, infinitum: kept as a type the parsers refuse
    }
    message.args.push_back(std::move(arg));
  }
  return true;
}

}  // namespace vitrine::remote
