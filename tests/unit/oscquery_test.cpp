// OSCQuery's pure parts: the namespace made from the scene registry (every parameter with its type,
// range, value, description and access; every action), attribute queries and their refusals,
// HOST_INFO, the binary OSC values LISTEN streams (read back by liblo), the stream's rate and bounds,
// and the rule for clients without the token.
#include "remote/osc_trust.h"
#include "remote/oscquery.h"
#include "remote/oscquery_stream.h"
#include "scenes/catalogue.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <lo/lo.h>
#include <nlohmann/json.hpp>

#include <memory>
#include <vector>

namespace vitrine::remote {
namespace {

using Json = nlohmann::json;

std::vector<const SceneInfo*> everyScene() {
  std::vector<const SceneInfo*> scenes;
  for (const SceneInfo& info : sceneRegistry()) scenes.push_back(&info);
  return scenes;
}

class OscQuery : public ::testing::Test {
 protected:
  std::vector<const SceneInfo*> scenes = everyScene();
  OscQueryValues values;
  OscQueryHost host{.name = "Vitrine", .oscAddress = "", .oscPort = 8730};

  OscQueryReply ask(std::string_view target) const { return answerOscQuery(scenes, values, host, target); }
  Json node(std::string_view target) const {
    const OscQueryReply reply = ask(target);
    EXPECT_EQ(reply.status, 200) << target << ": " << reply.body;
    return Json::parse(reply.body);
  }
  // The first parameter of any scene that `match` accepts, with its scene.
  template <typename Match> std::pair<const SceneInfo*, const params::Param*> find(Match match) const {
    for (const SceneInfo* scene : scenes)
      for (const params::Param& param : scene->schema().params())
        if (match(param)) return {scene, &param};
    return {nullptr, nullptr};
  }
};

TEST_F(OscQuery, EveryParameterOfEverySceneIsDescribedAtItsOscPath) {
  const Json root = node("/");
  EXPECT_EQ(root["FULL_PATH"], "/");
  const Json& vitrine = root["CONTENTS"]["vitrine"];
  size_t described = 0;
  for (const SceneInfo* scene : scenes) {
    const std::string name(scene->name);
    ASSERT_TRUE(vitrine["CONTENTS"].contains(name)) << name;
    const Json& contents = vitrine["CONTENTS"][name]["CONTENTS"];
    for (const params::Param& param : scene->schema().params()) {
      ASSERT_TRUE(contents.contains(param.key)) << name << "." << param.key;
      const Json& p = contents[param.key];
      EXPECT_EQ(p["FULL_PATH"], "/vitrine/" + name + "/" + param.key);
      EXPECT_EQ(p["ACCESS"], 3);
      EXPECT_EQ(p["TYPE"], std::string(1, oscType(param)));
      ASSERT_EQ(p["VALUE"].size(), 1u);
      EXPECT_FALSE(p["DESCRIPTION"].get<std::string>().empty()) << param.key;
      const bool files = param.has(params::kNamesFile);
      if (!files && (param.kind == params::Kind::Float || param.kind == params::Kind::Int)) {
        EXPECT_EQ(p["RANGE"][0]["MIN"].get<double>(), param.min) << param.key;
        EXPECT_EQ(p["RANGE"][0]["MAX"].get<double>(), param.max) << param.key;
        EXPECT_TRUE(p["VALUE"][0].is_number());
      }
      if (param.kind == params::Kind::Choice) {
        EXPECT_EQ(p["RANGE"][0]["VALS"], Json(param.choices)) << param.key;
      }
      if (files) {
        EXPECT_EQ(p["RANGE"][0]["VALS"], Json(param.builtIns)) << param.key;
      }
      if (param.kind == params::Kind::Bool) {
        EXPECT_TRUE(p["VALUE"][0].is_boolean());
      }
      ++described;
    }
    for (const SceneAction& action : scene->actions) {
      const Json& a = contents[std::string(action.name)];
      EXPECT_EQ(a["ACCESS"], 2);
      EXPECT_EQ(a["TYPE"], action.args.empty() ? std::string("N") : std::string(action.args.size(), 'f'));
      EXPECT_FALSE(a.contains("VALUE"));
    }
  }
  EXPECT_GT(described, 20u);
  EXPECT_EQ(vitrine["CONTENTS"]["scene"]["RANGE"][0]["VALS"].size(), scenes.size());
}

TEST_F(OscQuery, TypesFollowEachKind) {
  const auto typeOf = [&](params::Kind kind) {
    const auto [scene, param] = find([&](const params::Param& p) { return p.kind == kind && !p.has(params::kNamesFile); });
    return param ? oscType(*param) : '?';
  };
  EXPECT_EQ(typeOf(params::Kind::Float), 'f');
  EXPECT_EQ(typeOf(params::Kind::Int), 'i');
  EXPECT_EQ(typeOf(params::Kind::Bool), 'T');
  EXPECT_EQ(typeOf(params::Kind::Choice), 's');
}

TEST_F(OscQuery, ValuesAreThosePublishedElseDefaults) {
  EXPECT_EQ(node("/vitrine/kifs/step?VALUE"), Json::parse(R"({"VALUE":[9]})"));
  values.scene = "kifs";
  values.values["kifs"]["step"] = "4";
  EXPECT_EQ(node("/vitrine/kifs/step?VALUE"), Json::parse(R"({"VALUE":[4]})"));
  EXPECT_EQ(node("/vitrine/scene?VALUE"), Json::parse(R"({"VALUE":["kifs"]})"));
  const auto [scene, flag] = find([](const params::Param& p) { return p.kind == params::Kind::Bool; });
  ASSERT_TRUE(flag);
  values.values[std::string(scene->name)][flag->key] = "on";
  EXPECT_EQ(node(fmt::format("/vitrine/{}/{}?VALUE", scene->name, flag->key))["VALUE"][0], true);
}

TEST_F(OscQuery, AttributesOneAtATime) {
  EXPECT_EQ(node("/vitrine/kifs/step?TYPE"), Json::parse(R"({"TYPE":"i"})"));
  EXPECT_EQ(node("/vitrine/kifs/step?ACCESS"), Json::parse(R"({"ACCESS":3})"));
  EXPECT_EQ(node("/vitrine/kifs/step?RANGE"), Json::parse(R"({"RANGE":[{"MIN":1,"MAX":9}]})"));
  EXPECT_EQ(node("/vitrine/kifs/step?token=abc&TYPE"), Json::parse(R"({"TYPE":"i"})"));  // the token is the server's
  EXPECT_EQ(node("/vitrine/kifs/?FULL_PATH"), Json::parse(R"({"FULL_PATH":"/vitrine/kifs"})"));
  EXPECT_TRUE(node("/vitrine?CONTENTS")["CONTENTS"].contains("kifs"));
  EXPECT_EQ(ask("/vitrine/kifs?VALUE").status, 204);  // a container has no value
  EXPECT_EQ(ask("/vitrine/kifs/step?CONTENTS").status, 204);
}

TEST_F(OscQuery, MalformedAndUnknownQueriesAreRefused) {
  EXPECT_EQ(ask("/vitrine/kifs/nope").status, 404);
  EXPECT_EQ(ask("/nothing").status, 404);
  EXPECT_EQ(ask("/vitrine/kifs/step?BOGUS").status, 400);
  EXPECT_EQ(ask("/vitrine/kifs/step?UNIT").status, 400);  // defined by OSCQuery, not given here
  EXPECT_EQ(ask("/vitrine/kifs/step?VALUE&TYPE").status, 400);
  EXPECT_EQ(ask("/vitrine/kifs/step?VALUE=3").status, 400);
  EXPECT_EQ(ask("/vitrine//kifs").status, 400);
  EXPECT_EQ(ask("/vitrine/k%69fs").status, 400);
  EXPECT_EQ(ask("vitrine").status, 400);
  EXPECT_EQ(ask("").status, 400);
  EXPECT_EQ(ask("/vitrine/kifs/step?" + std::string(600, 'A')).status, 400);
  EXPECT_EQ(ask("/" + std::string(600, 'a')).status, 400);
  EXPECT_EQ(ask(std::string("/vitrine/\x01\xff", 11)).status, 400);
}

TEST_F(OscQuery, HostInfoNamesTheOscPortAndExtensions) {
  const Json info = node("/?HOST_INFO");
  EXPECT_EQ(info["NAME"], "Vitrine");
  EXPECT_EQ(info["OSC_PORT"], 8730);
  EXPECT_EQ(info["OSC_TRANSPORT"], "UDP");
  EXPECT_FALSE(info.contains("OSC_IP"));  // a wildcard bind: the address the client reached
  EXPECT_EQ(info["EXTENSIONS"]["LISTEN"], true);
  EXPECT_EQ(info["EXTENSIONS"]["VALUE"], true);
  EXPECT_EQ(info["EXTENSIONS"]["PATH_CHANGED"], false);
  host.oscAddress = "192.168.1.20";
  EXPECT_EQ(node("/?HOST_INFO")["OSC_IP"], "192.168.1.20");
}

// liblo reads the streamed message back: its address, type and value.
struct DecodedValue {
  std::string path, types;
  lo_message message = nullptr;
  ~DecodedValue() {
    if (message) lo_message_free(message);
  }
};
std::unique_ptr<DecodedValue> decodeValue(const std::string& bytes) {
  auto decoded = std::make_unique<DecodedValue>();
  std::vector<char> copy(bytes.begin(), bytes.end());
  int result = 0;
  decoded->message = lo_message_deserialise(copy.data(), copy.size(), &result);
  if (!decoded->message) return nullptr;
  decoded->path = lo_get_path(copy.data(), ssize_t(copy.size()));
  decoded->types = lo_message_get_types(decoded->message);
  return decoded;
}

TEST_F(OscQuery, StreamedValuesAreOscMessagesOfTheAdvertisedType) {
  values.scene = "kifs";
  values.values["kifs"]["step"] = "4";
  auto step = decodeValue(*oscValueMessage(scenes, values, "/vitrine/kifs/step"));
  ASSERT_TRUE(step);
  EXPECT_EQ(step->path, "/vitrine/kifs/step");
  EXPECT_EQ(step->types, "i");
  EXPECT_EQ(lo_message_get_argv(step->message)[0]->i, 4);

  const auto [scene, real] = find([](const params::Param& p) { return p.kind == params::Kind::Float; });
  values.values[std::string(scene->name)][real->key] = "0.25";
  auto number = decodeValue(*oscValueMessage(scenes, values, fmt::format("/vitrine/{}/{}", scene->name, real->key)));
  ASSERT_TRUE(number);
  EXPECT_EQ(number->types, "f");
  EXPECT_FLOAT_EQ(lo_message_get_argv(number->message)[0]->f, 0.25f);

  auto showing = decodeValue(*oscValueMessage(scenes, values, "/vitrine/scene"));
  ASSERT_TRUE(showing);
  EXPECT_EQ(showing->types, "s");
  EXPECT_STREQ(&lo_message_get_argv(showing->message)[0]->s, "kifs");

  EXPECT_FALSE(oscValueMessage(scenes, values, "/vitrine/kifs"));
  EXPECT_FALSE(oscValueMessage(scenes, values, "/vitrine/kifs/nope"));
  EXPECT_TRUE(listenable(scenes, "/vitrine/kifs/step"));
  EXPECT_TRUE(listenable(scenes, "/vitrine/scene"));
  EXPECT_FALSE(listenable(scenes, "/vitrine/pointer"));
  EXPECT_FALSE(listenable(scenes, "/vitrine/kifs"));
}

TEST(OscQueryStream, CommandsAreListenAndIgnoreOnly) {
  const auto listen = parseStreamCommand(R"({"COMMAND":"LISTEN","DATA":"/vitrine/kifs/step"})");
  ASSERT_TRUE(listen);
  EXPECT_TRUE(listen->listen);
  EXPECT_EQ(listen->path, "/vitrine/kifs/step");
  EXPECT_FALSE(parseStreamCommand(R"({"COMMAND":"IGNORE","DATA":"/x"})")->listen);
  for (const char* bad : {"", "[]", "not Json", R"({"COMMAND":"LISTEN"})", R"({"COMMAND":"LISTEN","DATA":3})",
                          R"({"COMMAND":"PATH_CHANGED","DATA":"/x"})", R"({"COMMAND":"LISTEN","DATA":""})",
                          R"({"COMMAND":["LISTEN"],"DATA":"/x"})"})
    EXPECT_FALSE(parseStreamCommand(bad)) << bad;
  EXPECT_FALSE(parseStreamCommand(R"({"COMMAND":"LISTEN","DATA":")" + std::string(600, 'a') + "\"}"));
}

TEST(OscQueryStream, FastValuesAreCoalescedToTheRate) {
  using namespace std::chrono_literals;
  ValueStream stream({.maxPaths = 2, .interval = 33ms});
  const auto t0 = ValueStream::Clock::now();
  EXPECT_TRUE(stream.listen("/a"));
  EXPECT_TRUE(stream.listen("/a"));
  EXPECT_TRUE(stream.listen("/b"));
  EXPECT_FALSE(stream.listen("/c"));  // bounded
  EXPECT_EQ(stream.size(), 2u);
  stream.changed("/c");  // not listened to: nothing waits
  EXPECT_TRUE(stream.due(t0).empty());
  stream.changed("/a");
  EXPECT_EQ(stream.due(t0), std::vector<std::string>{"/a"});
  // Ten changes within the interval: one send at its end, with the latest value (read at send time).
  for (int i = 0; i < 10; ++i) stream.changed("/a");
  stream.changed("/b");
  EXPECT_TRUE(stream.due(t0 + 10ms).empty());
  ASSERT_TRUE(stream.next());
  EXPECT_EQ(*stream.next(), t0 + 33ms);
  EXPECT_EQ(stream.due(t0 + 33ms), (std::vector<std::string>{"/a", "/b"}));
  EXPECT_FALSE(stream.next());
  stream.changed("/a");
  stream.ignore("/a");  // drops what waited for it
  EXPECT_TRUE(stream.due(t0 + 100ms).empty());
  EXPECT_FALSE(stream.listening("/a"));
}

TEST(OscQueryAccess, TokenlessClientsFollowOscsRule) {
  OscTrust closed({.open = false, .allow = {parseNetwork("192.168.1.0/24")}, .token = "secret"});
  EXPECT_TRUE(closed.allowed("192.168.1.40"));
  EXPECT_FALSE(closed.allowed("10.0.0.5"));
  EXPECT_FALSE(closed.offer("10.0.0.5", "wrong"));
  EXPECT_FALSE(closed.allowed("10.0.0.5"));
  EXPECT_TRUE(closed.offer("10.0.0.5", "secret"));
  EXPECT_TRUE(closed.allowed("10.0.0.5"));
  EXPECT_TRUE(OscTrust({.open = true}).allowed("203.0.113.9"));
}

TEST(OscQueryAccess, OnlyNativeClientsGoWithoutTheToken) {
  EXPECT_TRUE(nativeClientRequest(false, "192.168.1.20:8730", "studio"));
  EXPECT_TRUE(nativeClientRequest(false, "127.0.0.1", "studio"));
  EXPECT_TRUE(nativeClientRequest(false, "[::1]:8730", "studio"));
  EXPECT_TRUE(nativeClientRequest(false, "localhost:8730", "studio"));
  EXPECT_TRUE(nativeClientRequest(false, "Studio.local:8730", "studio"));
  EXPECT_TRUE(nativeClientRequest(false, "studio", "studio"));
  EXPECT_FALSE(nativeClientRequest(true, "127.0.0.1:8730", "studio"));  // a browser's page sent it
  EXPECT_FALSE(nativeClientRequest(false, "attacker.example:8730", "studio"));  // DNS rebinding
  EXPECT_FALSE(nativeClientRequest(false, "studio.attacker.example", "studio"));
  EXPECT_FALSE(nativeClientRequest(false, "", "studio"));
  EXPECT_FALSE(nativeClientRequest(false, "127.0.0.1:80x", "studio"));
  EXPECT_FALSE(nativeClientRequest(false, "[::1", "studio"));
}

}  // namespace
}  // namespace vitrine::remote
