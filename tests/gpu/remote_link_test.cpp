// The host's end of remote play with real OSC datagrams on loopback and real scenes: values sent for
// a scene that is not showing wait bounded (one per key, however many arrive), and when their scene
// opens they pass the same freeze guard as a live value (the bypass this guards against: set noodles.grid=64x64x64
// while kifs shows, then switch to noodles).
#include "core/assets.h"
#include "host/remote_link.h"
#include "host/gallery/remote_session.h"
#include "host/scene_renderer.h"
#include "support/gpu_test.h"

#include <arpa/inet.h>
#include <fmt/format.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <string>
#include <thread>

namespace vitrine::test {
namespace {

// An OSC string, NUL-padded to four bytes as the spec frames it.
std::string padded(std::string text) {
  text.push_back('\0');
  while (text.size() % 4) text.push_back('\0');
  return text;
}

// An OSC message with one string argument.
std::string oscString(const std::string& path, const std::string& value) { return padded(path) + padded(",s") + padded(value); }

// An OSC message with one float argument (big-endian).
std::string oscFloat(const std::string& path, float value) {
  uint32_t bits;
  std::memcpy(&bits, &value, 4);
  bits = htonl(bits);
  return padded(path) + padded(",f") + std::string(reinterpret_cast<const char*>(&bits), 4);
}

// Sends `datagram` from the loopback address `from` to 127.0.0.1:port.
void sendFrom(const char* from, uint16_t port, const std::string& datagram) {
  const int fd = ::socket(AF_INET, SOCK_DGRAM, 0);
  ASSERT_GE(fd, 0);
  sockaddr_in source{}, target{};
  source.sin_family = target.sin_family = AF_INET;
  inet_pton(AF_INET, from, &source.sin_addr);
  target.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  target.sin_port = htons(port);
  EXPECT_EQ(::bind(fd, reinterpret_cast<const sockaddr*>(&source), sizeof source), 0) << from;
  EXPECT_EQ(::sendto(fd, datagram.data(), datagram.size(), 0, reinterpret_cast<const sockaddr*>(&target), sizeof target),
            ssize_t(datagram.size()));
  ::close(fd);
}

std::string valueOf(host::SceneRenderer& renderer, const std::string& key) {
  for (const auto& [k, text] : params::snapshot(renderer.parameters()))
    if (k == key) return text;
  return {};
}

class RemoteLinkTest : public GpuTest {
 protected:
  Assets assets = Assets::locate();
  gpu::ProgramLibrary programs{device()};
  host::SceneRenderer renderer{device(), programs, assets, 1};
  host::RemoteLink link{"127.0.0.1:0"};

  // Applies what arrives (to the scene showing, or into the waiting values) until `done`, for `limit` at most.
  template <typename Done> bool applyUntil(Done done, std::chrono::milliseconds limit = std::chrono::seconds(3)) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < deadline) {
      link.apply(renderer, nullptr, 0.0, 16.0);
      if (done()) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return false;
  }
};

TEST_F(RemoteLinkTest, AFloodForAHiddenSceneWaitsAsOneValuePerKey) {
  renderer.setScene(*findScene("kifs"));
  // 600 values from 30 rotating loopback addresses (each within its rate budget), all for noodles.
  for (int i = 0; i < 600; ++i)
    sendFrom(fmt::format("127.0.3.{}", i % 30 + 1).c_str(), link.port(),
             oscString("/vitrine/noodles/grid", fmt::format("{}x4x4", i % 8 + 1)));
  // Whatever arrived is drained, not left queued (600 here; a flood can send 480,000).
  applyUntil([&] { return false; }, std::chrono::milliseconds(500));
  EXPECT_EQ(link.waiting(), 1u);
}

TEST_F(RemoteLinkTest, AWaitingValueThatWouldFreezeTheWindowIsRefusedWhenItsSceneOpens) {
  renderer.setScene(*findScene("kifs"));
  sendFrom("127.0.0.1", link.port(), oscString("/vitrine/noodles/grid", "64x64x64"));
  sendFrom("127.0.0.1", link.port(), oscString("/vitrine/noodles/msaa", "off"));
  ASSERT_TRUE(applyUntil([&] { return link.waiting() == 2; }));
  renderer.setScene(*findScene("noodles"));
  const std::string before = valueOf(renderer, "grid");
  // 200 ms frames here: 64x64x64 is 32 times the default's strands, about 6 s a frame.
  const params::KeyValues applied = link.applyWaiting(renderer, 200.0);
  EXPECT_EQ(applied, (params::KeyValues{{"msaa", "off"}})) << "the harmless value still applies";
  EXPECT_EQ(valueOf(renderer, "grid"), before);
  EXPECT_EQ(valueOf(renderer, "msaa"), "off");
  EXPECT_EQ(link.waiting(), 0u);
}

// The kiosk holds a scene while a person plays it, not while a lighting desk streams modulation
// values, a client sets values for a hidden scene or saves presets.
TEST_F(RemoteLinkTest, OnlyPlayingTheSceneShowingCountsAsATouch) {
  renderer.setScene(*findScene("kifs"));
  const auto drain = [&] {  // whether what arrived within 300 ms touched the scene
    bool touched = false;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(300);
    while (std::chrono::steady_clock::now() < deadline) {
      touched = link.apply(renderer, nullptr, 0.0, 16.0).touched || touched;
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return touched;
  };
  sendFrom("127.0.0.1", link.port(), oscFloat("/vitrine/mod/fader", 0.5f));
  EXPECT_FALSE(drain()) << "a modulation source";
  sendFrom("127.0.0.1", link.port(), oscString("/vitrine/noodles/msaa", "off"));
  EXPECT_FALSE(drain()) << "a value for a hidden scene";
  sendFrom("127.0.0.1", link.port(), oscString("/vitrine/kifs/step", "4"));
  EXPECT_TRUE(drain()) << "a value for the scene showing";
}

// A kiosk starting a fresh gallery in the process (after a lost device) opens the remote again: the
// page's address stays, token and the port the system chose, so a phone reconnects by itself.
TEST_F(RemoteLinkTest, ARemoteOpenedAgainKeepsItsTokenAndPort) {
  std::string first;
  uint16_t port = 0;
  {
    host::RemoteLink a("127.0.0.1:0");
    port = a.port();
    first = a.pageUrl();
  }
  host::RemoteLink b("127.0.0.1:0");
  EXPECT_EQ(b.port(), port);
  EXPECT_EQ(b.pageUrl(), first);
  host::RemoteLink c("127.0.0.1:0");  // while b holds the port: another one, the same token
  EXPECT_NE(c.port(), port);
  EXPECT_EQ(c.pageUrl().substr(c.pageUrl().find("token=")), first.substr(first.find("token=")));
}

// The gallery's session over the link: a live value and a waiting one, once its scene's frames are timed,
// become clients' keys of their scenes (kept out of the settings file), until the user sets them.
TEST_F(RemoteLinkTest, TheSessionKnowsWhichValuesAClientSet) {
  host::RemoteSession session;
  session.listen("127.0.0.1:0", {}, nullptr);
  renderer.setScene(*findScene("kifs"));
  sendFrom("127.0.0.1", session.port(), oscString("/vitrine/noodles/msaa", "off"));  // first: waiting once step is in
  sendFrom("127.0.0.1", session.port(), oscString("/vitrine/kifs/step", "3"));
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(3);
  while (valueOf(renderer, "step") != "3" && std::chrono::steady_clock::now() < deadline) {
    session.apply(renderer, 0.0, 16.0, std::nullopt);
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  EXPECT_EQ(valueOf(renderer, "step"), "3");
  EXPECT_EQ(session.notTheUsers("kifs"), std::set<std::string>{"step"});
  renderer.setScene(*findScene("noodles"));
  EXPECT_TRUE(session.apply(renderer, 0.0, 16.0, std::nullopt).values.empty()) << "its frames are not timed yet";
  EXPECT_EQ(session.apply(renderer, 0.0, 16.0, 16.0).values, (params::KeyValues{{"msaa", "off"}}));
  EXPECT_EQ(session.notTheUsers("noodles"), std::set<std::string>{"msaa"});
  session.userSet("kifs", host::PanelEdit{host::PanelEdit::What::Values, {{"step", "5"}}, {}, {}});
  EXPECT_EQ(session.notTheUsers("kifs"), std::set<std::string>{});
}

}  // namespace
}  // namespace vitrine::test
