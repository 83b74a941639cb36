// OSCQuery over the web server's real HTTP and WebSocket (Boost.Beast clients on loopback): the
// namespace beside the page, the rule for clients without the token (OSC's network rule, and never a
// browser's request), LISTEN and IGNORE with values streamed as binary OSC, and OSC sent over the socket.
#include "remote/web_server.h"
#include "remote_http_client.h"

#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <gtest/gtest.h>
#include <lo/lo.h>
#include <nlohmann/json.hpp>
#include <sys/socket.h>

#include <cstdlib>
#include <memory>
#include <optional>
#include <vector>

namespace vitrine::remote {
namespace {

namespace net = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = net::ip::tcp;
using testing::eventually;
using testing::limitReads;

const std::string kQueryToken = "fedcba9876543210fedcba9876543210";


http::response<http::string_body> queryGet(uint16_t port, const std::string& target, const testing::Headers& headers = {}) {
  return testing::request(port, target, http::verb::get, headers);
}

// An OSCQuery client's socket: JSON commands out, binary OSC values in.
class OscQueryClient {
 public:
  OscQueryClient(uint16_t port, const std::string& target) : socket_(io_) {
    socket_.next_layer().connect({net::ip::make_address("127.0.0.1"), port});
    limitReads(socket_.next_layer());
    socket_.handshake("127.0.0.1:" + std::to_string(port), target);
  }
  void command(const std::string& name, const std::string& path) {
    socket_.text(true);
    socket_.write(net::buffer(nlohmann::json{{"COMMAND", name}, {"DATA", path}}.dump()));
  }
  void osc(lo_message message, const char* path) {
    size_t size = 0;
    void* bytes = lo_message_serialise(message, path, nullptr, &size);
    socket_.binary(true);
    socket_.write(net::buffer(bytes, size));
    std::free(bytes);
  }
  // The next value: its path and its one argument as text; nullopt when nothing came in time.
  std::optional<std::pair<std::string, std::string>> value() {
    beast::flat_buffer buffer;
    beast::error_code error;
    socket_.read(buffer, error);
    if (error || socket_.got_text()) return std::nullopt;
    std::string bytes = beast::buffers_to_string(buffer.data());
    int result = 0;
    lo_message message = lo_message_deserialise(bytes.data(), bytes.size(), &result);
    if (!message) return std::nullopt;
    const char type = lo_message_get_types(message)[0];
    lo_arg* arg = lo_message_get_argv(message)[0];
    std::string text = type == 'i' ? std::to_string(arg->i) : type == 's' ? std::string(&arg->s) : std::string(1, type);
    lo_message_free(message);
    return std::pair{std::string(bytes.c_str()), text};
  }

 private:
  net::io_context io_;
  websocket::stream<tcp::socket> socket_;
};

unsigned queryUpgradeStatus(uint16_t port, const std::string& target, bool withOrigin = false) {
  return testing::upgradeStatus(port, target,
                                withOrigin ? testing::Headers{{"Origin", "http://attacker.example"}} : testing::Headers{});
}

class OscQueryWeb : public ::testing::Test {
 protected:
  Catalogue catalogue;
  RemoteInbox inbox;
  RemoteStats stats;
  std::shared_ptr<const OscTrust> open = std::make_shared<OscTrust>(OscAccess{.open = true});
  std::shared_ptr<const OscTrust> closed = std::make_shared<OscTrust>(OscAccess{.open = false, .token = kQueryToken});
};

TEST_F(OscQueryWeb, TheNamespaceBesideThePage) {
  WebServer server({"127.0.0.1", 0}, kQueryToken, catalogue, inbox, stats, {}, open);
  const auto tokenless = queryGet(server.port(), "/");
  ASSERT_EQ(tokenless.result(), http::status::ok);
  EXPECT_EQ(tokenless[http::field::content_type], "application/json");
  EXPECT_TRUE(nlohmann::json::parse(tokenless.body())["CONTENTS"]["vitrine"]["CONTENTS"].contains("kifs"));
  // The URL the gallery prints stays the page; JSON where a holder of the token asks for it.
  EXPECT_EQ(queryGet(server.port(), "/?token=" + kQueryToken)[http::field::content_type], "text/html; charset=utf-8");
  EXPECT_EQ(queryGet(server.port(), "/?token=" + kQueryToken, {{"Accept", "application/json"}})[http::field::content_type],
            "application/json");
  const auto info = queryGet(server.port(), "/?HOST_INFO");
  EXPECT_EQ(nlohmann::json::parse(info.body())["OSC_PORT"], server.port());
  EXPECT_EQ(queryGet(server.port(), "/vitrine/kifs/step?VALUE").body(), R"({"VALUE":[9]})");
  EXPECT_EQ(queryGet(server.port(), "/vitrine/kifs/step?NOPE").result(), http::status::bad_request);
  EXPECT_EQ(queryGet(server.port(), "/vitrine/kifs/nope").result(), http::status::not_found);
  EXPECT_EQ(queryGet(server.port(), "/vitrine/kifs?VALUE").result(), http::status::no_content);
  EXPECT_EQ(queryGet(server.port(), "/vitrine/kifs/step?" + std::string(9000, 'A')).result(),
            http::status::payload_too_large);
  // What the gallery publishes is what VALUE reports.
  server.publish({.scene = "kifs", .values = {{"step", "4"}}});
  EXPECT_TRUE(eventually([&] { return queryGet(server.port(), "/vitrine/kifs/step?VALUE").body() == R"({"VALUE":[4]})"; }));
}

TEST_F(OscQueryWeb, WithoutTheTokenOnlyWhoMaySendOscAndNeverABrowser) {
  WebServer shut({"127.0.0.1", 0}, kQueryToken, catalogue, inbox, stats, {}, closed);
  EXPECT_EQ(queryGet(shut.port(), "/").result(), http::status::forbidden);
  EXPECT_EQ(queryGet(shut.port(), "/vitrine/kifs/step?VALUE").result(), http::status::forbidden);
  EXPECT_EQ(queryUpgradeStatus(shut.port(), "/"), 403u);
  EXPECT_EQ(queryGet(shut.port(), "/vitrine/kifs/step?VALUE&token=" + kQueryToken).result(), http::status::ok);
  EXPECT_EQ(queryUpgradeStatus(shut.port(), "/?token=" + kQueryToken), 101u);

  WebServer noTrust({"127.0.0.1", 0}, kQueryToken, catalogue, inbox, stats);  // no OSC rule given: the token only
  EXPECT_EQ(queryGet(noTrust.port(), "/").result(), http::status::forbidden);

  WebServer server({"127.0.0.1", 0}, kQueryToken, catalogue, inbox, stats, {}, open);
  EXPECT_EQ(queryGet(server.port(), "/", {{"Origin", "http://attacker.example"}}).result(),
            http::status::forbidden);
  EXPECT_EQ(queryGet(server.port(), "/", {{"Host", "attacker.example"}}).result(), http::status::forbidden);
  EXPECT_EQ(queryUpgradeStatus(server.port(), "/", true), 403u);
  EXPECT_EQ(queryUpgradeStatus(server.port(), "/"), 101u);
  // The page, its catalogue and its socket need the token whoever asks.
  EXPECT_EQ(queryGet(server.port(), "/catalogue.json").result(), http::status::forbidden);
  EXPECT_EQ(queryGet(server.port(), "/index.html").result(), http::status::forbidden);
  EXPECT_EQ(queryUpgradeStatus(server.port(), "/socket"), 403u);
}

TEST_F(OscQueryWeb, ListenStreamsChangesAndIgnoreStopsThem) {
  WebServer server({"127.0.0.1", 0}, kQueryToken, catalogue, inbox, stats, {}, open);
  OscQueryClient client(server.port(), "/");
  client.command("LISTEN", "/vitrine/kifs/step");
  client.command("LISTEN", "/vitrine/scene");
  client.command("LISTEN", "/vitrine/kifs/nope");  // refused: no such value
  ASSERT_TRUE(eventually([&] { return stats.snapshot().accepted == 2 && stats.snapshot().refused == 1; }));
  server.publish({.scene = "kifs", .values = {{"step", "4"}}});
  std::map<std::string, std::string> got;
  for (int i = 0; i < 2; ++i)
    if (auto value = client.value()) got.insert(*value);
  EXPECT_EQ(got["/vitrine/kifs/step"], "4");
  EXPECT_EQ(got["/vitrine/scene"], "kifs");

  // A value moving at every publish reaches the client at most at the stream's rate, latest last.
  for (int step = 1; step <= 9; ++step) server.publish({.scene = "kifs", .values = {{"step", std::to_string(step)}}});
  std::vector<std::string> seen;
  while (seen.empty() || seen.back() != "9") {
    auto value = client.value();
    ASSERT_TRUE(value);
    seen.push_back(value->second);
  }
  EXPECT_LT(seen.size(), 9u);

  client.command("IGNORE", "/vitrine/kifs/step");
  ASSERT_TRUE(eventually([&] { return stats.snapshot().accepted == 3; }));
  server.publish({.scene = "kifs", .values = {{"step", "2"}}});
  server.publish({.scene = "noodles", .values = {}});  // still listened to: it comes, and nothing before it
  const auto next = client.value();
  ASSERT_TRUE(next);
  EXPECT_EQ(*next, (std::pair<std::string, std::string>{"/vitrine/scene", "noodles"}));
}

TEST_F(OscQueryWeb, OscOverTheSocketIsCheckedAndQueuedAsUdpIs) {
  WebServer server({"127.0.0.1", 0}, kQueryToken, catalogue, inbox, stats, {}, open);
  OscQueryClient client(server.port(), "/");
  lo_message set = lo_message_new();
  lo_message_add_int32(set, 3);
  client.osc(set, "/vitrine/kifs/step");
  lo_message_add_int32(set, 99);  // two arguments: malformed for a value
  client.osc(set, "/vitrine/kifs/step");
  lo_message_free(set);
  lo_message tooBig = lo_message_new();
  lo_message_add_int32(tooBig, 12);
  client.osc(tooBig, "/vitrine/kifs/step");  // out of range: refused by the check
  lo_message_free(tooBig);
  ASSERT_TRUE(eventually([&] { return stats.snapshot().refused == 1 && stats.snapshot().malformed == 1; }));
  const auto commands = inbox.drain();
  ASSERT_EQ(commands.size(), 1u);
  EXPECT_EQ(commands[0].kind, RemoteCommand::Kind::Set);
  EXPECT_EQ(commands[0].value, "3");
  EXPECT_TRUE(commands[0].client.starts_with("oscquery 127.0.0.1:"));
}

}  // namespace
}  // namespace vitrine::remote
