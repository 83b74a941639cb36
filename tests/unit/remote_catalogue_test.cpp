// The catalogue the page is generated from and the check every command passes, plus the small parts
// around it: the access token, --remote-bind, the rate limiter and the inbox.
#include "remote/access_token.h"
#include "remote/bind_address.h"
#include "remote/catalogue.h"
#include "remote/inbox.h"
#include "remote/rate_limiter.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>

namespace vitrine::remote {
namespace {

using Kind = RemoteCommand::Kind;

RemoteCommand set(std::string scene, std::string key, std::string value) {
  return {.kind = Kind::Set, .scene = std::move(scene), .key = std::move(key), .value = std::move(value)};
}

TEST(RemoteCatalogue, JsonDescribesEveryScene) {
  const Catalogue catalogue;
  const auto json = nlohmann::json::parse(catalogue.json());
  ASSERT_EQ(json["scenes"].size(), catalogue.scenes().size());
  const auto& kifs = *std::find_if(json["scenes"].begin(), json["scenes"].end(),
                                   [](const auto& scene) { return scene["name"] == "kifs"; });
  EXPECT_EQ(kifs["title"], "Volumetric KIFS");
  const auto& step = kifs["params"][0];
  EXPECT_EQ(step["key"], "step");
  EXPECT_EQ(step["kind"], "int");
  EXPECT_EQ(step["min"], 1);
  EXPECT_EQ(step["max"], 9);
  EXPECT_EQ(step["default"], "9");
  const auto& tier = kifs["params"][1];
  EXPECT_EQ(tier["kind"], "choice");
  EXPECT_EQ(tier["choices"], (std::vector<std::string>{"auto", "high", "medium", "low"}));
  EXPECT_TRUE(kifs["params"][2]["logarithmic"]);
  EXPECT_EQ(kifs["params"][3]["key"], "fold");  // played by the bass, and saved
  EXPECT_FALSE(kifs["params"][3]["transient"]);
  EXPECT_TRUE(kifs["params"][4]["transient"]);
  for (const auto& scene : json["scenes"])
    for (const auto& param : scene["params"])
      EXPECT_TRUE(param["kind"] == "float" || param["kind"] == "int" || param["kind"] == "bool" ||
                  param["kind"] == "choice" || param["kind"] == "colour" || param["kind"] == "text");
}

TEST(RemoteCatalogue, JsonListsActions) {
  const auto json = nlohmann::json::parse(Catalogue().json());
  std::map<std::string, nlohmann::json> actions;
  for (const auto& scene : json["scenes"]) actions[scene["name"]] = scene["actions"];
  ASSERT_EQ(actions["neon"].size(), 2u);
  EXPECT_EQ(actions["neon"][0]["name"], "release");
  EXPECT_EQ(actions["neon"][0]["args"], (std::vector<std::string>{"x", "y", "z"}));
  EXPECT_EQ(actions["neon"][1]["name"], "burst");  // the beat's, with live audio
  EXPECT_TRUE(actions["neon"][1]["args"].empty());
  ASSERT_GE(actions["glass"].size(), 1u);
  EXPECT_EQ(actions["glass"][0]["name"], "shuffle");
  EXPECT_TRUE(actions["glass"][0]["args"].empty());
}

TEST(RemoteCatalogue, AcceptsWhatTheSchemaAccepts) {
  const Catalogue catalogue;
  EXPECT_EQ(catalogue.check(set("kifs", "step", "3")), "");
  EXPECT_EQ(catalogue.check(set("kifs", "tier", "low")), "");
  EXPECT_EQ(catalogue.check(set("bloom", "mute", "on")), "");
  EXPECT_EQ(catalogue.check(set("noodles", "grid", "16x16x4")), "");
  EXPECT_EQ(catalogue.check({.kind = Kind::Scene, .scene = "glass"}), "");
  EXPECT_EQ(catalogue.check({.kind = Kind::Action, .scene = "neon", .key = "release", .args = {0, 1, 2}}), "");
  EXPECT_EQ(catalogue.check({.kind = Kind::Action, .scene = "glass", .key = "shuffle"}), "");
  EXPECT_EQ(catalogue.check({.kind = Kind::Pointer, .position = {0.0f, 1.0f}}), "");
}

TEST(RemoteCatalogue, RefusesUnknownNames) {
  const Catalogue catalogue;
  EXPECT_NE(catalogue.check({.kind = Kind::Scene, .scene = "nope"}).find("unknown scene 'nope'"), std::string::npos);
  EXPECT_NE(catalogue.check(set("nope", "step", "3")).find("unknown scene"), std::string::npos);
  EXPECT_NE(catalogue.check(set("kifs", "stepp", "3")).find("unknown parameter 'stepp'"), std::string::npos);
  EXPECT_NE(catalogue.check({.kind = Kind::Action, .scene = "kifs", .key = "release", .args = {0, 1, 2}})
                .find("has no action 'release'"),
            std::string::npos);
}

TEST(RemoteCatalogue, RefusesValuesTheSchemaRefuses) {
  const Catalogue catalogue;
  EXPECT_NE(catalogue.check(set("kifs", "step", "12")).find("kifs.step=12: expected a whole number from 1 to 9"),
            std::string::npos);
  EXPECT_NE(catalogue.check(set("kifs", "step", "3.5")), "");
  EXPECT_NE(catalogue.check(set("kifs", "step", "")), "");
  EXPECT_NE(catalogue.check(set("kifs", "target_ms", "1e+30")), "");
  EXPECT_NE(catalogue.check(set("kifs", "target_ms", "nan")), "");
  EXPECT_NE(catalogue.check(set("kifs", "tier", "ultra")), "");
  EXPECT_NE(catalogue.check(set("bloom", "mute", "maybe")), "");
  EXPECT_NE(catalogue.check(set("noodles", "grid", "0x0x0")), "");
  EXPECT_NE(catalogue.check(set("kifs", "step", std::string(kMaxValueLength + 1, '1'))), "");
}

// A value that names a file (glass' background image, its panorama) is the person at the gallery's to
// choose: a client may pick only the built-in names, and every path gets the same refusal, so nothing
// tells a file that exists from one that does not, a folder from a file, or a picture from a secret.
TEST(RemoteCatalogue, FilesAreNotARemoteClientsToName) {
  const Catalogue catalogue;
  EXPECT_EQ(catalogue.check(set("glass", "background", "checker")), "");
  EXPECT_EQ(catalogue.check(set("glass", "background", "page")), "");
  EXPECT_EQ(catalogue.check(set("glass", "panorama", "photo_studio")), "");
  EXPECT_EQ(catalogue.check(set("glass", "panorama", "city")), "");
  const auto photo = std::filesystem::temp_directory_path() / "vitrine_remote_photo.png";
  std::ofstream(photo) << "not really a picture";
  for (const std::string key : {"background", "panorama"}) {
    std::set<std::string> refusals;
    for (const std::string& path : {photo.string(), std::string("/etc/passwd"), std::string("/no/such/file.png"),
                                   std::string("/tmp"), std::string("~/.bashrc"), std::string("/dev/zero"),
                                   std::string("studio.exr"), std::string("")}) {
      const std::string why = catalogue.check(set("glass", key, path));
      EXPECT_NE(why, "") << key << "=" << path;
      if (!path.empty()) {
        EXPECT_EQ(why.find(path), std::string::npos) << why;
      }
      refusals.insert(why);
    }
    EXPECT_EQ(refusals.size(), 1u) << "the refusals tell paths apart: " << *refusals.begin();
  }
  std::filesystem::remove(photo);
  // The page offers the built-in names as a list, never a text field for a path.
  const auto json = nlohmann::json::parse(catalogue.json());
  for (const auto& scene : json["scenes"])
    for (const auto& param : scene["params"])
      if (scene["name"] == "glass" && param["key"] == "background") {
        EXPECT_EQ(param["kind"], "choice");
        EXPECT_EQ(param["choices"], (std::vector<std::string>{"page", "photo", "gradient", "checker"}));
      }
}

TEST(RemoteCatalogue, RefusesWrongArityAndBadPointers) {
  const Catalogue catalogue;
  EXPECT_NE(catalogue.check({.kind = Kind::Action, .scene = "neon", .key = "release", .args = {0, 1}})
                .find("takes 3 numbers (x y z), not 2"),
            std::string::npos);
  EXPECT_NE(catalogue.check({.kind = Kind::Action, .scene = "neon", .key = "release", .args = {0, 1, 2, 3}}), "");
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_NE(catalogue.check({.kind = Kind::Action, .scene = "neon", .key = "release", .args = {0, nan, 2}}), "");
  EXPECT_NE(catalogue.check({.kind = Kind::Pointer, .position = {1.5f, 0.5f}}), "");
  EXPECT_NE(catalogue.check({.kind = Kind::Pointer, .position = {0.5f, -0.01f}}), "");
  EXPECT_NE(catalogue.check({.kind = Kind::Pointer, .position = {nan, 0.5f}}), "");
}

TEST(RemoteAccess, TokensAreRandomHexAndComparedWhole) {
  std::set<std::string> seen;
  for (int i = 0; i < 8; ++i) {
    const std::string token = makeAccessToken();
    EXPECT_EQ(token.size(), 32u);
    EXPECT_EQ(token.find_first_not_of("0123456789abcdef"), std::string::npos);
    seen.insert(token);
  }
  EXPECT_EQ(seen.size(), 8u);
  EXPECT_TRUE(tokensEqual("abc123", "abc123"));
  EXPECT_FALSE(tokensEqual("abc124", "abc123"));
  EXPECT_FALSE(tokensEqual("abc12", "abc123"));
  EXPECT_FALSE(tokensEqual("", ""));  // no token configured never matches
}

TEST(RemoteAccess, QueryValues) {
  EXPECT_EQ(queryValue("/?token=ab12", "token"), "ab12");
  EXPECT_EQ(queryValue("/socket?x=1&token=ab12&y", "token"), "ab12");
  EXPECT_EQ(queryValue("/socket?xtoken=ab12", "token"), "");
  EXPECT_EQ(queryValue("/socket", "token"), "");
  EXPECT_EQ(queryValue("/socket?token", "token"), "");
  EXPECT_EQ(targetPath("/socket?token=1"), "/socket");
  EXPECT_EQ(targetPath("/"), "/");
}

TEST(RemoteBind, ParsesAddressesAndPorts) {
  const auto v4 = parseBind("0.0.0.0:9000");
  EXPECT_EQ(v4.address, "0.0.0.0");
  EXPECT_EQ(v4.port, 9000);
  const auto v6 = parseBind("[::1]:0");
  EXPECT_EQ(v6.address, "::1");
  EXPECT_EQ(v6.port, 0);
  EXPECT_EQ(formatBind(v6), "[::1]:0");
  EXPECT_EQ(formatBind(parseBind("127.0.0.1:8730")), "127.0.0.1:8730");
}

TEST(RemoteBind, RefusesWithReasons) {
  const auto why = [](std::string_view text) {
    try {
      parseBind(text);
    } catch (const std::invalid_argument& error) {
      return std::string(error.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(why("127.0.0.1").find("no ':PORT'"), std::string::npos);
  EXPECT_NE(why("127.0.0.1:65536").find("0 to 65535"), std::string::npos);
  EXPECT_NE(why("127.0.0.1:-1").find("0 to 65535"), std::string::npos);
  EXPECT_NE(why("127.0.0.1:80x").find("0 to 65535"), std::string::npos);
  EXPECT_NE(why(":8730").find("no address"), std::string::npos);
  EXPECT_NE(why("localhost:8730").find("not a numeric IPv4 address"), std::string::npos);
  EXPECT_NE(why("::1:8730").find("in brackets"), std::string::npos);
  EXPECT_NE(why("[127.0.0.1]:8730").find("IPv6"), std::string::npos);
}

TEST(RemoteRateLimit, BucketRefillsAtItsRate) {
  const auto start = SteadyClock::now();
  TokenBucket bucket({.rate = 10, .burst = 5}, start);
  for (int i = 0; i < 5; ++i) EXPECT_TRUE(bucket.take(start));
  EXPECT_FALSE(bucket.take(start));
  EXPECT_TRUE(bucket.take(start + std::chrono::milliseconds(100)));  // one token per 100 ms
  EXPECT_FALSE(bucket.take(start + std::chrono::milliseconds(100)));
  int later = 0;
  for (int i = 0; i < 20; ++i) later += bucket.take(start + std::chrono::seconds(60));
  EXPECT_EQ(later, 5);  // never more than the burst
}

TEST(RemoteRateLimit, SenderTableIsBounded) {
  SenderBudgets budgets({.rate = 1, .burst = 1}, 4);
  const auto now = SteadyClock::now();
  for (int i = 0; i < 100; ++i) EXPECT_TRUE(budgets.take("10.0.0." + std::to_string(i), now));
  EXPECT_EQ(budgets.size(), 4u);
  EXPECT_FALSE(budgets.take("10.0.0.99", now));  // still remembered: over budget
}

TEST(RemoteInbox, DrainsInOrderAndDropsWhenFull) {
  RemoteInbox inbox(3);
  for (int i = 0; i < 5; ++i)
    EXPECT_EQ(inbox.push({.kind = Kind::Scene, .scene = std::to_string(i)}), i < 3);
  const auto drained = inbox.drain();
  ASSERT_EQ(drained.size(), 3u);
  EXPECT_EQ(drained[0].scene, "0");
  EXPECT_EQ(drained[2].scene, "2");
  EXPECT_TRUE(inbox.drain().empty());
  EXPECT_TRUE(inbox.push({.kind = Kind::Scene}));
}

}  // namespace
}  // namespace vitrine::remote
