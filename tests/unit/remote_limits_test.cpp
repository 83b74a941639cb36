// What remote clients can make the gallery hold and who may send OSC: the values waiting for a scene
// that is not showing are bounded per key, per client and in all; --remote-allow networks match as
// CIDR says. Pure: no sockets.
#include "remote/network.h"
#include "remote/waiting_values.h"

#include <gtest/gtest.h>
#include <fmt/format.h>

#include <stdexcept>

namespace vitrine::remote {
namespace {

TEST(RemoteWaitingValues, KeepsTheLastValuePerKeyInFirstArrivalOrder) {
  WaitingValues waiting;
  for (int i = 0; i < 10'000; ++i) ASSERT_TRUE(waiting.put("osc 127.0.0.1", "noodles", "grid", fmt::format("{}x4x4", i % 9 + 1)));
  ASSERT_TRUE(waiting.put("ws 127.0.0.1:5000", "noodles", "segments", "12"));
  ASSERT_TRUE(waiting.put("osc 127.0.0.1", "noodles", "grid", "2x2x2"));
  EXPECT_EQ(waiting.size(), 2u);
  EXPECT_EQ(waiting.take("noodles"), (params::KeyValues{{"grid", "2x2x2"}, {"segments", "12"}}));
  EXPECT_EQ(waiting.size(), 0u);
  EXPECT_TRUE(waiting.take("noodles").empty()) << "taken once";
}

TEST(RemoteWaitingValues, OneClientCanHoldOnlyItsShare) {
  WaitingValues waiting({.perClient = 4, .total = 100});
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(waiting.put("a", "kifs", fmt::format("k{}", i), "1"));
  EXPECT_FALSE(waiting.put("a", "kifs", "k4", "1")) << "a fifth key from the same client";
  EXPECT_TRUE(waiting.put("a", "kifs", "k0", "2")) << "replacing its own value is no new one";
  EXPECT_TRUE(waiting.put("b", "kifs", "k4", "1"));
  EXPECT_EQ(waiting.fromClient("a"), 4u);
  // Taking over a value another client sent moves it to the newcomer's share.
  EXPECT_TRUE(waiting.put("b", "kifs", "k0", "3"));
  EXPECT_EQ(waiting.fromClient("a"), 3u);
  EXPECT_EQ(waiting.fromClient("b"), 2u);
  waiting.take("kifs");
  EXPECT_EQ(waiting.fromClient("a"), 0u);
  EXPECT_TRUE(waiting.put("a", "kifs", "k9", "1")) << "taken values free the share";
}

// A flood: 480,000 datagrams from rotating loopback addresses, each a new "client".
TEST(RemoteWaitingValues, AFloodFromRotatingSendersStaysWithinTheTotal) {
  WaitingValues waiting({.perClient = 64, .total = 256});
  size_t refused = 0;
  for (int i = 0; i < 480'000; ++i) {
    const std::string client = fmt::format("osc 127.{}.{}.{}", (i >> 16) & 255, (i >> 8) & 255, i & 255);
    refused += !waiting.put(client, i % 2 ? "noodles" : "bloom", fmt::format("key{}", i % 5000), std::to_string(i));
  }
  EXPECT_EQ(waiting.size(), 256u);
  // The first 256 keys are kept; each comes back 96 times in all, replacing itself; the rest is refused.
  EXPECT_EQ(refused, 480'000u - 256u * 96u);
}

TEST(RemoteNetwork, ParsesNetworksAndSaysWhatIsWrong) {
  EXPECT_EQ(formatNetwork(parseNetwork("192.168.1.0/24")), "192.168.1.0/24");
  EXPECT_EQ(formatNetwork(parseNetwork("10.0.0.7")), "10.0.0.7/32");
  EXPECT_EQ(formatNetwork(parseNetwork("fd00::/8")), "fd00::/8");
  EXPECT_EQ(formatNetwork(parseNetwork("0.0.0.0/0")), "0.0.0.0/0");
  EXPECT_EQ(formatNetwork(parseNetwork("::ffff:10.1.2.0/24")), "10.1.2.0/24");  // mapped: the IPv4 network
  for (const char* bad : {"", "/24", "192.168.1.0/", "192.168.1.0/33", "192.168.1.0/-1", "192.168.1.0/2x",
                          "fd00::/129", "lan", "192.168.1", "1.2.3.4.5/8", "192.168.1.0/24/8"})
    EXPECT_THROW(parseNetwork(bad), std::invalid_argument) << bad;
  try {
    parseNetwork("192.168.1.7/24");
    ADD_FAILURE() << "host bits past the prefix";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("192.168.1.0/24"), std::string::npos) << e.what();
  }
}

TEST(RemoteNetwork, MatchesAddressesByPrefix) {
  const Network lan = parseNetwork("192.168.1.0/24");
  EXPECT_TRUE(contains(lan, "192.168.1.0"));
  EXPECT_TRUE(contains(lan, "192.168.1.255"));
  EXPECT_TRUE(contains(lan, "::ffff:192.168.1.20")) << "an IPv4-mapped sender on a dual-stack socket";
  EXPECT_FALSE(contains(lan, "192.168.2.1"));
  EXPECT_FALSE(contains(lan, "192.168.0.255"));
  EXPECT_FALSE(contains(lan, "::1"));
  EXPECT_FALSE(contains(lan, "nonsense"));
  EXPECT_FALSE(contains(lan, ""));
  const Network odd = parseNetwork("10.0.0.0/13");  // a prefix that is no whole byte
  EXPECT_TRUE(contains(odd, "10.7.255.255"));
  EXPECT_FALSE(contains(odd, "10.8.0.0"));
  const Network host = parseNetwork("127.0.0.2");
  EXPECT_TRUE(contains(host, "127.0.0.2"));
  EXPECT_FALSE(contains(host, "127.0.0.3"));
  EXPECT_TRUE(contains(parseNetwork("0.0.0.0/0"), "203.0.113.9"));
  const Network ula = parseNetwork("fd00::/8");
  EXPECT_TRUE(contains(ula, "fd12:3456::1"));
  EXPECT_FALSE(contains(ula, "fe80::1"));
  EXPECT_FALSE(contains(ula, "253.0.0.1")) << "families do not mix";
  EXPECT_TRUE(isLoopbackAddress("127.0.0.1"));
  EXPECT_TRUE(isLoopbackAddress("127.255.0.9"));
  EXPECT_TRUE(isLoopbackAddress("::1"));
  EXPECT_FALSE(isLoopbackAddress("0.0.0.0"));
  EXPECT_FALSE(isLoopbackAddress("::"));
  EXPECT_FALSE(isLoopbackAddress("192.168.1.20"));
}

}  // namespace
}  // namespace vitrine::remote
