#pragma once
// The two wire formats, turned into RemoteCommands. Pure functions: no I/O, no state, no exceptions
// escape, any input is safe (they are fuzzed). They judge form only (types, shapes, sizes); whether a
// scene, parameter or value exists is the catalogue's check.
//
// WebSocket, one JSON object per text message:
//   {"type":"scene","name":"neon"}
//   {"type":"set","scene":"kifs","key":"step","value":"3"}        (value: a string, number or boolean)
//   {"type":"action","scene":"neon","name":"release","args":[0,1,2]}
//   {"type":"pointer","x":0.4,"y":0.6,"down":true}
//   {"type":"preset","op":"save","scene":"kifs","name":"evening"}   (op: save, apply or delete)
// OSC (UDP):
//   /vitrine/scene s                       switch scene
//   /vitrine/<scene>/<param> f|i|h|d|s|T|F   set a parameter
//   /vitrine/<scene>/<action> f|i...        run an action with numeric arguments
//   /vitrine/pointer x y [down]            the cursor, 0..1 from the top left; down: T/F or a number
//   /vitrine/mod/<name> f|i|h|d|T|F        live input's source osc.<name>, 0..1 (docs/LIVE.md)
//   /vitrine/preset/<op> s s               save, apply or delete the user's preset: SCENE NAME
#include "remote/catalogue.h"
#include "remote/command.h"

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace vitrine::remote {

inline constexpr size_t kMaxSocketMessage = 4096;  // bytes of one WebSocket message
inline constexpr int kMaxJsonDepth = 4;            // {"args":[...]} needs two

struct ParseResult {
  std::optional<RemoteCommand> command;  // set on success
  std::string error;                     // set on failure: what was wrong, for the log and the client
};

ParseResult parseSocketMessage(std::string_view text);

// One OSC argument as decoded from a packet: its type tag and its value. Numbers (i h f d, and T F as
// 1/0) in `number`; strings (s S) in `text`; other tags (blobs, MIDI, nil, ...) carry nothing and are
// refused as wrong types.
struct OscArgument {
  char type = 0;
  double number = 0.0;
  std::string text;
};

// `catalogue` tells a parameter from an action at /vitrine/<scene>/<name>: a name the scene declares
// as an action is one; anything else is taken as a parameter (and the check judges whether it exists).
ParseResult commandFromOsc(std::string_view path, std::span<const OscArgument> args, const Catalogue& catalogue);

// A number as a parameter's value text: integers without a decimal point ("3"), others as the
// shortest float text ("0.05"); nullopt when not finite or beyond float range.
std::optional<std::string> numberText(double value);

}  // namespace vitrine::remote
