// The OSC server with real UDP datagrams on loopback: good messages reach the inbox; malformed bytes,
// oversized datagrams, wrong types, unknown addresses and floods are counted and ignored, and the
// server keeps serving after all of them.
#include "remote/osc_server.h"
#include "remote_test_support.h"

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <lo/lo.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstring>
#include <vector>

namespace vitrine::remote {
namespace {

using testing::eventually;

// A UDP socket aimed at the server: sends whatever bytes a test makes.
class UdpSender {
 public:
  // `from`: the loopback address to send from (any of 127.0.0.0/8 is this computer's), else 127.0.0.1.
  explicit UdpSender(uint16_t port, const char* from = nullptr) : fd_(::socket(AF_INET, SOCK_DGRAM, 0)) {
    address_.sin_family = AF_INET;
    address_.sin_port = htons(port);
    address_.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (from) {
      sockaddr_in source{};
      source.sin_family = AF_INET;
      inet_pton(AF_INET, from, &source.sin_addr);
      EXPECT_EQ(::bind(fd_, reinterpret_cast<const sockaddr*>(&source), sizeof source), 0) << from;
    }
  }
  ~UdpSender() { ::close(fd_); }
  void send(const std::vector<std::byte>& bytes) const {
    ASSERT_EQ(::sendto(fd_, bytes.data(), bytes.size(), 0, reinterpret_cast<const sockaddr*>(&address_), sizeof address_),
              ssize_t(bytes.size()));
  }
  void send(std::string_view bytes) const { send(std::vector<std::byte>(reinterpret_cast<const std::byte*>(bytes.data()), reinterpret_cast<const std::byte*>(bytes.data() + bytes.size()))); }

 private:
  int fd_;
  sockaddr_in address_{};
};

// An OSC message serialised by liblo, built by `add` on a fresh lo_message.
template <typename Add> std::vector<std::byte> osc(const char* path, Add add) {
  lo_message message = lo_message_new();
  add(message);
  size_t size = 0;
  void* data = lo_message_serialise(message, path, nullptr, &size);
  std::vector<std::byte> bytes(static_cast<std::byte*>(data), static_cast<std::byte*>(data) + size);
  std::free(data);
  lo_message_free(message);
  return bytes;
}

std::vector<std::byte> bundle(const std::vector<std::vector<std::byte>>& elements) {
  std::vector<std::byte> bytes;
  for (const char c : std::string_view("#bundle\0\0\0\0\0\0\0\0\1", 16)) bytes.push_back(std::byte(c));
  for (const auto& element : elements) {
    const uint32_t size = htonl(uint32_t(element.size()));
    const auto* raw = reinterpret_cast<const std::byte*>(&size);
    bytes.insert(bytes.end(), raw, raw + 4);
    bytes.insert(bytes.end(), element.begin(), element.end());
  }
  return bytes;
}

class RemoteOsc : public ::testing::Test {
 protected:
  Catalogue catalogue;
  RemoteInbox inbox;
  RemoteStats stats;

  uint64_t total(const RemoteStatsSnapshot& s) const {
    return s.accepted + s.malformed + s.refused + s.rateLimited + s.oversized + s.dropped;
  }
};

TEST_F(RemoteOsc, GoodMessagesReachTheInbox) {
  OscServer server({"127.0.0.1", 0}, catalogue, inbox, stats);
  ASSERT_NE(server.port(), 0);
  UdpSender sender(server.port());
  sender.send(osc("/vitrine/scene", [](lo_message m) { lo_message_add_string(m, "neon"); }));
  sender.send(osc("/vitrine/kifs/step", [](lo_message m) { lo_message_add_int32(m, 3); }));
  sender.send(osc("/vitrine/kifs/target_ms", [](lo_message m) { lo_message_add_float(m, 12.5f); }));
  sender.send(osc("/vitrine/bloom/mute", [](lo_message m) { lo_message_add_true(m); }));
  sender.send(osc("/vitrine/neon/release", [](lo_message m) {
    lo_message_add_float(m, 0.5f);
    lo_message_add_float(m, 1.0f);
    lo_message_add_float(m, -2.0f);
  }));
  sender.send(osc("/vitrine/pointer", [](lo_message m) {
    lo_message_add_float(m, 0.25f);
    lo_message_add_float(m, 0.75f);
    lo_message_add_int32(m, 1);
  }));
  ASSERT_TRUE(eventually([&] { return stats.snapshot().accepted == 6; })) << stats.snapshot().malformed;
  const auto commands = inbox.drain();
  ASSERT_EQ(commands.size(), 6u);
  EXPECT_EQ(commands[0].scene, "neon");
  EXPECT_EQ(commands[1].value, "3");
  EXPECT_EQ(commands[2].value, "12.5");
  EXPECT_EQ(commands[3].value, "on");
  EXPECT_EQ(commands[4].args, (std::vector<float>{0.5f, 1.0f, -2.0f}));
  EXPECT_TRUE(commands[5].down);
  EXPECT_EQ(commands[5].client, "osc 127.0.0.1");
}

TEST_F(RemoteOsc, BundlesAreUnpacked) {
  OscServer server({"127.0.0.1", 0}, catalogue, inbox, stats);
  UdpSender sender(server.port());
  sender.send(bundle({osc("/vitrine/kifs/step", [](lo_message m) { lo_message_add_int32(m, 2); }),
                      bundle({osc("/vitrine/scene", [](lo_message m) { lo_message_add_string(m, "kifs"); })})}));
  ASSERT_TRUE(eventually([&] { return stats.snapshot().accepted == 2; }));
  const auto commands = inbox.drain();
  EXPECT_EQ(commands[0].value, "2");
  EXPECT_EQ(commands[1].scene, "kifs");
}

TEST_F(RemoteOsc, BadDatagramsAreCountedAndIgnored) {
  OscServer server({"127.0.0.1", 0}, catalogue, inbox, stats);
  UdpSender sender(server.port());
  // Malformed bytes: not OSC at all, a path without its terminator, a type tag promising a missing
  // argument, a broken bundle, an empty datagram.
  sender.send("hello, gallery");
  sender.send(std::string_view("/vitrine/scene", 14));
  sender.send(std::string_view("/vitrine/kifs/step\0\0,i\0\0", 24));
  sender.send(std::string_view("#bundle\0\0\0\0\0\0\0\0\0\0\0\0\x40", 20));
  sender.send(std::string_view("", 0));
  // Wrong types and unknown addresses.
  sender.send(osc("/vitrine/scene", [](lo_message m) { lo_message_add_int32(m, 3); }));
  sender.send(osc("/vitrine/neon/release", [](lo_message m) { lo_message_add_string(m, "x"); }));
  sender.send(osc("/vitrine/pointer", [](lo_message m) { lo_message_add_float(m, 0.5f); }));
  sender.send(osc("/somewhere/else", [](lo_message m) { lo_message_add_int32(m, 1); }));
  // Well-formed but naming what does not exist, or out of range.
  sender.send(osc("/vitrine/nope/step", [](lo_message m) { lo_message_add_int32(m, 3); }));
  sender.send(osc("/vitrine/kifs/nope", [](lo_message m) { lo_message_add_int32(m, 3); }));
  sender.send(osc("/vitrine/kifs/step", [](lo_message m) { lo_message_add_int32(m, 12); }));
  sender.send(osc("/vitrine/kifs/step", [](lo_message m) { lo_message_add_string(m, "three"); }));
  sender.send(osc("/vitrine/pointer", [](lo_message m) {
    lo_message_add_float(m, 2.0f);
    lo_message_add_float(m, 0.5f);
  }));
  // Oversized: a datagram over the limit, whatever it holds.
  sender.send(osc("/vitrine/kifs/step", [](lo_message m) { lo_message_add_string(m, std::string(3000, '9').c_str()); }));

  ASSERT_TRUE(eventually([&] { return total(stats.snapshot()) == 15; })) << total(stats.snapshot());
  const auto counted = stats.snapshot();
  EXPECT_EQ(counted.accepted, 0u);
  EXPECT_EQ(counted.oversized, 1u);
  EXPECT_EQ(counted.malformed, 9u);
  EXPECT_EQ(counted.refused, 5u);
  EXPECT_TRUE(inbox.drain().empty());

  // Still serving.
  sender.send(osc("/vitrine/kifs/step", [](lo_message m) { lo_message_add_int32(m, 4); }));
  ASSERT_TRUE(eventually([&] { return stats.snapshot().accepted == 1; }));
  EXPECT_EQ(inbox.drain().at(0).value, "4");
}

// OSC has no reply channel: a refused value is kept (a few at a time) for the gallery's console to say why.
TEST_F(RemoteOsc, RefusalsAreKeptForTheConsole) {
  OscServer server({"127.0.0.1", 0}, catalogue, inbox, stats);
  UdpSender sender(server.port());
  for (int i = 0; i < 40; ++i) sender.send(osc("/vitrine/kifs/step", [](lo_message m) { lo_message_add_int32(m, 12); }));
  ASSERT_TRUE(eventually([&] { return stats.snapshot().refused == 40; }));
  const auto refusals = inbox.drainRefusals();
  ASSERT_EQ(refusals.size(), RemoteInbox::kRefusalNotes);
  EXPECT_EQ(refusals[0].client, "osc 127.0.0.1");
  EXPECT_NE(refusals[0].reason.find("kifs.step=12: expected a whole number from 1 to 9"), std::string::npos);
  EXPECT_TRUE(inbox.drainRefusals().empty());
}

TEST_F(RemoteOsc, FloodsAreRateLimited) {
  OscServer server({"127.0.0.1", 0}, catalogue, inbox, stats, {.perSender = {.rate = 1, .burst = 5}});
  UdpSender sender(server.port());
  const auto message = osc("/vitrine/kifs/step", [](lo_message m) { lo_message_add_int32(m, 5); });
  for (int i = 0; i < 40; ++i) sender.send(message);
  ASSERT_TRUE(eventually([&] { return total(stats.snapshot()) == 40; }));
  EXPECT_EQ(stats.snapshot().accepted, 5u);
  EXPECT_EQ(stats.snapshot().rateLimited, 35u);
  EXPECT_EQ(inbox.drain().size(), 5u);
}

TEST_F(RemoteOsc, FullInboxDropsAndCounts) {
  RemoteInbox small(2);
  OscServer server({"127.0.0.1", 0}, catalogue, small, stats);
  UdpSender sender(server.port());
  const auto message = osc("/vitrine/kifs/step", [](lo_message m) { lo_message_add_int32(m, 5); });
  for (int i = 0; i < 5; ++i) sender.send(message);
  ASSERT_TRUE(eventually([&] { return total(stats.snapshot()) == 5; }));
  EXPECT_EQ(stats.snapshot().accepted, 2u);
  EXPECT_EQ(stats.snapshot().dropped, 3u);
}

// Beyond loopback (here: a server told it is not open, on loopback addresses only), OSC comes only
// from allowed networks or senders that sent the token; the rest is counted as unauthorised.
TEST_F(RemoteOsc, BeyondLoopbackOnlyAllowedNetworksAndTokenHoldersAreHeard) {
  const OscAccess access{.open = false, .allow = {parseNetwork("127.0.0.2/32")}, .token = "secret-token"};
  OscServer server({"127.0.0.1", 0}, catalogue, inbox, stats, {}, access);
  const auto step = osc("/vitrine/kifs/step", [](lo_message m) { lo_message_add_int32(m, 3); });
  const auto token = [](const char* text) {
    return osc("/vitrine/token", [text](lo_message m) { lo_message_add_string(m, text); });
  };
  UdpSender allowed(server.port(), "127.0.0.2"), stranger(server.port(), "127.0.0.3"),
      holder(server.port(), "127.0.0.4");
  stranger.send(step);
  stranger.send(token("wrong-token"));
  ASSERT_TRUE(eventually([&] { return stats.snapshot().unauthorised == 2; }));
  allowed.send(step);
  ASSERT_TRUE(eventually([&] { return stats.snapshot().accepted == 1; }));
  holder.send(token("secret-token"));
  holder.send(step);
  ASSERT_TRUE(eventually([&] { return stats.snapshot().accepted == 3; }));
  stranger.send(step);  // still unknown
  ASSERT_TRUE(eventually([&] { return stats.snapshot().unauthorised == 3; }));
  const auto commands = inbox.drain();
  ASSERT_EQ(commands.size(), 2u);
  EXPECT_EQ(commands[0].client, "osc 127.0.0.2");
  EXPECT_EQ(commands[1].client, "osc 127.0.0.4");
}

TEST_F(RemoteOsc, RefusesAnAddressInUse) {
  OscServer first({"127.0.0.1", 0}, catalogue, inbox, stats);
  try {
    OscServer second({"127.0.0.1", first.port()}, catalogue, inbox, stats);
    FAIL() << "bound twice";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("Address already in use"), std::string::npos) << error.what();
  }
}

TEST_F(RemoteOsc, StopsPromptly) {
  const auto start = std::chrono::steady_clock::now();
  { OscServer server({"127.0.0.1", 0}, catalogue, inbox, stats); }
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::milliseconds(200));
}

}  // namespace
}  // namespace vitrine::remote
