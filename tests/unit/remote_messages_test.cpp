// The remote control's wire formats: JSON from the page's socket and OSC addresses, parsed into
// commands, with everything malformed refused by reason rather than by crash.
#include "remote/messages.h"

#include <gtest/gtest.h>

#include <string>

namespace vitrine::remote {
namespace {

using Kind = RemoteCommand::Kind;

RemoteCommand parsed(std::string_view text) {
  const ParseResult result = parseSocketMessage(text);
  EXPECT_TRUE(result.command) << text << ": " << result.error;
  return result.command.value_or(RemoteCommand{});
}

std::string refusal(std::string_view text) {
  const ParseResult result = parseSocketMessage(text);
  EXPECT_FALSE(result.command) << text << " was accepted";
  EXPECT_FALSE(result.error.empty()) << text;
  return result.error;
}

TEST(RemoteMessages, SocketCommandsOfEveryKind) {
  const auto scene = parsed(R"({"type":"scene","name":"neon"})");
  EXPECT_EQ(scene.kind, Kind::Scene);
  EXPECT_EQ(scene.scene, "neon");

  const auto set = parsed(R"({"type":"set","scene":"kifs","key":"step","value":"3"})");
  EXPECT_EQ(set.kind, Kind::Set);
  EXPECT_EQ(set.scene, "kifs");
  EXPECT_EQ(set.key, "step");
  EXPECT_EQ(set.value, "3");

  const auto action = parsed(R"({"type":"action","scene":"neon","name":"release","args":[0,1.5,-2]})");
  EXPECT_EQ(action.kind, Kind::Action);
  EXPECT_EQ(action.key, "release");
  EXPECT_EQ(action.args, (std::vector<float>{0.0f, 1.5f, -2.0f}));

  const auto pointer = parsed(R"({"type":"pointer","x":0.25,"y":0.75,"down":true})");
  EXPECT_EQ(pointer.kind, Kind::Pointer);
  EXPECT_FLOAT_EQ(pointer.position.x, 0.25f);
  EXPECT_FLOAT_EQ(pointer.position.y, 0.75f);
  EXPECT_TRUE(pointer.down);
  EXPECT_FALSE(parsed(R"({"type":"pointer","x":0,"y":0})").down);
}

TEST(RemoteMessages, NumbersAndBooleansBecomeCanonicalText) {
  EXPECT_EQ(parsed(R"({"type":"set","scene":"kifs","key":"step","value":3})").value, "3");
  EXPECT_EQ(parsed(R"({"type":"set","scene":"kifs","key":"step","value":3.0})").value, "3");
  EXPECT_EQ(parsed(R"({"type":"set","scene":"k","key":"x","value":0.05})").value, "0.05");
  EXPECT_EQ(parsed(R"({"type":"set","scene":"k","key":"x","value":-2.5})").value, "-2.5");
  EXPECT_EQ(parsed(R"({"type":"set","scene":"k","key":"x","value":true})").value, "on");
  EXPECT_EQ(parsed(R"({"type":"set","scene":"k","key":"x","value":false})").value, "off");
}

TEST(RemoteMessages, MalformedJsonIsRefused) {
  refusal("");
  refusal("{");
  refusal("not json");
  refusal(R"({"type":"set","scene":"kifs",)");
  refusal("[1,2,3]");
  refusal("42");
  refusal("\"scene\"");
  refusal(std::string("{\"type\":\"scene\",\"name\":\"\xff\xfe\"}"));  // not UTF-8
}

TEST(RemoteMessages, WrongTypesAreRefused) {
  refusal(R"({"type":7})");
  refusal(R"({"name":"neon"})");
  refusal(R"({"type":"scene","name":5})");
  refusal(R"({"type":"scene","name":["neon"]})");
  refusal(R"({"type":"set","scene":"kifs","key":"step"})");
  refusal(R"({"type":"set","scene":"kifs","key":"step","value":null})");
  refusal(R"({"type":"set","scene":"kifs","key":"step","value":[3]})");
  refusal(R"({"type":"set","scene":"kifs","key":"step","value":{"v":3}})");
  refusal(R"({"type":"set","scene":"kifs","key":5,"value":"3"})");
  refusal(R"({"type":"action","scene":"neon","name":"release","args":"0 1 2"})");
  refusal(R"({"type":"action","scene":"neon","name":"release","args":[0,"1",2]})");
  refusal(R"({"type":"pointer","x":"0.5","y":0.5})");
  refusal(R"({"type":"pointer","x":0.5})");
  refusal(R"({"type":"pointer","x":0.5,"y":0.5,"down":1})");
}

TEST(RemoteMessages, UnknownTypeIsNamed) {
  EXPECT_NE(refusal(R"({"type":"reboot"})").find("unknown type 'reboot'"), std::string::npos);
}

TEST(RemoteMessages, NonFiniteAndHugeNumbersAreRefused) {
  // JSON has no NaN; these are what a client may try instead.
  refusal(R"({"type":"pointer","x":NaN,"y":0.5})");
  refusal(R"({"type":"pointer","x":1e999,"y":0.5})");
  refusal(R"({"type":"pointer","x":1e300,"y":0.5})");  // beyond float
  refusal(R"({"type":"set","scene":"k","key":"x","value":1e300})");
  refusal(R"({"type":"action","scene":"neon","name":"release","args":[1e39,0,0]})");
  // Huge but within float: parsed here, judged out of range by the catalogue.
  EXPECT_EQ(parsed(R"({"type":"set","scene":"k","key":"x","value":1e30})").value, "1e+30");
}

TEST(RemoteMessages, SizesAndNamesAreBounded) {
  refusal(std::string(kMaxSocketMessage + 1, ' '));
  refusal(std::string(200, '[') + std::string(200, ']'));  // deep nesting, refused before parsing
  refusal(R"({"type":"scene","name":"../../etc/passwd"})");
  refusal(R"({"type":"scene","name":""})");
  refusal("{\"type\":\"scene\",\"name\":\"" + std::string(kMaxNameLength + 1, 'a') + "\"}");
  refusal("{\"type\":\"set\",\"scene\":\"k\",\"key\":\"x\",\"value\":\"" + std::string(kMaxValueLength + 1, '1') + "\"}");
  refusal(R"({"type":"action","scene":"neon","name":"release","args":[1,2,3,4,5,6,7,8,9]})");
  // Brackets inside strings do not count as nesting.
  EXPECT_EQ(parsed(R"({"type":"set","scene":"k","key":"x","value":"[[[[[[[["})").value, "[[[[[[[[");
}

OscArgument number(char type, double value) { return {.type = type, .number = value}; }
OscArgument text(std::string value) { return {.type = 's', .text = std::move(value)}; }

TEST(RemoteMessages, OscAddressesBecomeCommands) {
  const Catalogue catalogue;
  const std::vector<OscArgument> neon{text("neon")};
  auto result = commandFromOsc("/vitrine/scene", neon, catalogue);
  ASSERT_TRUE(result.command) << result.error;
  EXPECT_EQ(result.command->kind, Kind::Scene);
  EXPECT_EQ(result.command->scene, "neon");

  const std::vector<OscArgument> three{number('i', 3)};
  result = commandFromOsc("/vitrine/kifs/step", three, catalogue);
  ASSERT_TRUE(result.command) << result.error;
  EXPECT_EQ(result.command->kind, Kind::Set);
  EXPECT_EQ(result.command->value, "3");

  const std::vector<OscArgument> xyz{number('f', 0.5), number('i', 1), number('d', -2)};
  result = commandFromOsc("/vitrine/neon/release", xyz, catalogue);
  ASSERT_TRUE(result.command) << result.error;
  EXPECT_EQ(result.command->kind, Kind::Action);
  EXPECT_EQ(result.command->args, (std::vector<float>{0.5f, 1.0f, -2.0f}));

  result = commandFromOsc("/vitrine/glass/shuffle", {}, catalogue);
  ASSERT_TRUE(result.command) << result.error;
  EXPECT_EQ(result.command->kind, Kind::Action);
  EXPECT_TRUE(result.command->args.empty());

  // Live input's OSC sources: /vitrine/mod/NAME with one number, checked and carried as osc.NAME.
  const std::vector<OscArgument> level{number('f', 0.25)};
  result = commandFromOsc("/vitrine/mod/fader_1", level, catalogue);
  ASSERT_TRUE(result.command) << result.error;
  EXPECT_EQ(result.command->kind, Kind::Modulation);
  EXPECT_EQ(result.command->key, "fader_1");
  EXPECT_EQ(result.command->args, (std::vector<float>{0.25f}));
  EXPECT_EQ(catalogue.check(*result.command), "");
  EXPECT_FALSE(commandFromOsc("/vitrine/mod/fader", {}, catalogue).command);
  EXPECT_FALSE(commandFromOsc("/vitrine/mod/fader", neon, catalogue).command);  // a string

  const std::vector<OscArgument> touch{number('f', 0.1), number('f', 0.9), {.type = 'T', .number = 1}};
  result = commandFromOsc("/vitrine/pointer", touch, catalogue);
  ASSERT_TRUE(result.command) << result.error;
  EXPECT_EQ(result.command->kind, Kind::Pointer);
  EXPECT_TRUE(result.command->down);
}

TEST(RemoteMessages, OscBooleansFromTagsNumbersAndWords) {
  const Catalogue catalogue;
  const auto value = [&](OscArgument arg) {
    const std::vector<OscArgument> args{std::move(arg)};
    const auto result = commandFromOsc("/vitrine/bloom/mute", args, catalogue);
    return result.command ? result.command->value : "refused: " + result.error;
  };
  EXPECT_EQ(value({.type = 'T', .number = 1}), "on");
  EXPECT_EQ(value({.type = 'F'}), "off");
  EXPECT_EQ(value(number('i', 1)), "1");
  EXPECT_EQ(value(text("on")), "on");
  EXPECT_EQ(value(number('f', 0)), "0");
}

TEST(RemoteMessages, OscWrongTypesAndAddressesAreRefused) {
  const Catalogue catalogue;
  const auto refused = [&](std::string_view path, std::vector<OscArgument> args) {
    const auto result = commandFromOsc(path, args, catalogue);
    EXPECT_FALSE(result.command) << path << " was accepted";
    EXPECT_FALSE(result.error.empty());
  };
  refused("/vitrine/scene", {number('i', 3)});
  refused("/vitrine/scene", {});
  refused("/vitrine/scene", {text("neon"), text("kifs")});
  refused("/vitrine/kifs/step", {});
  refused("/vitrine/kifs/step", {{.type = 'b'}});  // a blob
  refused("/vitrine/kifs/step", {number('f', std::numeric_limits<double>::quiet_NaN())});
  refused("/vitrine/kifs/step", {number('d', 1e300)});
  refused("/vitrine/neon/release", {number('f', 0), text("1"), number('f', 2)});
  refused("/vitrine/neon/release", {number('f', 0), number('f', std::numeric_limits<double>::infinity()), number('f', 2)});
  refused("/vitrine/pointer", {number('f', 0.5)});
  refused("/vitrine/pointer", {text("0.5"), number('f', 0.5)});
  refused("/vitrine/pointer", {number('f', 0.5), number('f', 0.5), text("down")});
  refused("/other/scene", {text("neon")});
  refused("/vitrine", {text("neon")});
  refused("", {});
  refused("vitrine/scene", {text("neon")});
  refused("/vitrine/kifs/step/extra", {number('i', 3)});
  refused("/vitrine//step", {number('i', 3)});
  refused("/vitrine/ki fs/step", {number('i', 3)});
}

// The user's presets: /vitrine/preset/<op> SCENE NAME and {"type":"preset",...}, a new name judged by
// the catalogue exactly as the panel judges it.
TEST(RemoteMessages, PresetCommandsOverOscAndTheSocket) {
  const Catalogue catalogue;
  const std::vector<OscArgument> evening{text("kifs"), text("evening look")};
  for (const std::string op : {"save", "apply", "delete"}) {
    const ParseResult result = commandFromOsc("/vitrine/preset/" + op, evening, catalogue);
    ASSERT_TRUE(result.command) << op << ": " << result.error;
    EXPECT_EQ(result.command->kind, Kind::Preset);
    EXPECT_EQ(result.command->scene, "kifs");
    EXPECT_EQ(result.command->key, op);
    EXPECT_EQ(result.command->value, "evening look");
    EXPECT_EQ(catalogue.check(*result.command), "");
  }
  EXPECT_FALSE(commandFromOsc("/vitrine/preset/rename", evening, catalogue).command);
  for (const std::vector<OscArgument>& wrong : {std::vector<OscArgument>{text("kifs")},
                                                 std::vector<OscArgument>{text("kifs"), number('i', 3)},
                                                 std::vector<OscArgument>{text("kifs"), text("")}})
    EXPECT_FALSE(commandFromOsc("/vitrine/preset/save", wrong, catalogue).command);

  const auto socket = parsed(R"({"type":"preset","op":"apply","scene":"kifs","name":"sphere"})");
  EXPECT_EQ(socket.kind, Kind::Preset);
  EXPECT_EQ(socket.key, "apply");
  EXPECT_EQ(socket.value, "sphere");
  EXPECT_EQ(catalogue.check(socket), "") << "a built-in preset may be applied";
  EXPECT_NE(refusal(R"({"type":"preset","op":"drop","scene":"kifs","name":"x"})").find("save, apply or delete"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"type":"preset","op":"save","scene":"kifs"})").find("\"name\""), std::string::npos);

  // Saving under a built-in name, or a name no --preset could spell, is refused before the host sees it.
  const auto clash = parsed(R"({"type":"preset","op":"save","scene":"kifs","name":"sphere"})");
  EXPECT_NE(catalogue.check(clash).find("one of the scene's own presets"), std::string::npos);
  const auto dotted = parsed(R"({"type":"preset","op":"save","scene":"kifs","name":"a.b"})");
  EXPECT_NE(catalogue.check(dotted).find("'.'"), std::string::npos);
  const auto nowhere = parsed(R"({"type":"preset","op":"save","scene":"nowhere","name":"x"})");
  EXPECT_NE(catalogue.check(nowhere).find("unknown scene"), std::string::npos);
}

}  // namespace
}  // namespace vitrine::remote
