#pragma once
// One declaration per command-line flag: its name, the modes it belongs to, its value, whether it
// repeats, one help text, and how it stores into Options. The parse, the mode checks, the "given
// twice" rule, --help, the man page and the bash completion all read this table (app/flags.cpp);
// none of them names a flag of its own. Adding a flag is one entry.
//
//   {.name = "--seed", .modes = kRuns, .value = "S", .help = "...",
//    .store = [](Options& o, std::string_view flag, const std::string& v) { o.seed = parseWhole(flag, v, 0); }},
#include "app/options.h"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vitrine::flags {

// The modes a flag belongs to. The run modes refuse a flag outside them, naming the mode; the
// listings (--list-*, --help, --version) take what they need and ignore the rest.
enum ModeBit : unsigned {
  kGallery = 1u << 0,
  kHeadless = 1u << 1,
  kBench = 1u << 2,
  kRecord = 1u << 3,
  kEncode = 1u << 4,
  kCompare = 1u << 5,
  kExport = 1u << 6,   // --export-preset
  kListing = 1u << 7,  // the --list-* modes, --help, --version and the generated documents
  kRuns = kGallery | kHeadless | kBench | kRecord,  // the modes that run a scene
};

// What a flag's value is, for the bash completion (app/completion.cpp) and the parse.
enum class Value {
  None,         // a switch
  Text,         // anything: no completion
  File,         // a file (or folder) name
  Scene,        // a scene's name
  OptionalScene,  // an optional scene's name: taken only when the next word is not an option
  Setting,      // [SCENE.]KEY=VALUE
  Preset,       // [SCENE.]NAME
  Choice,       // one of the words of `metavar`, split at '|'
};

using Store = void (*)(Options& options, std::string_view flag, const std::string& value);

struct Flag {
  std::string_view name;      // "--scene"
  unsigned modes = 0;         // ModeBit: where it is accepted
  std::string_view metavar;   // "NAME", "on|off", "[SCENE]" (optional); empty for a switch
  Value value = Value::None;
  bool repeatable = false;    // may be given more than once (each adds); else the second is refused
  unsigned requiredIn = 0;    // ModeBit: the modes whose synopsis shows it outside brackets
  std::string_view help;      // sentences, wrapped by whoever shows them
  Store store = nullptr;      // parses the value (empty for a switch) into Options; throws vitrine::Error
  std::string_view alias = {};  // "-h"
};

// A mode as the synopsis shows it: how it is started, its operands, and what it does.
struct ModeInfo {
  ModeBit bit;
  std::string_view word;      // the first argument ("bench"), or the flag that picks it ("--headless")
  std::string_view operands;  // "FOLDER", "REFERENCE.exr CANDIDATE.exr"; after the flags
  std::string_view title;     // "the gallery": headings, and "only for ..." refusals
  std::string_view about;     // sentences: what the mode does
  Mode mode = Mode::Gallery;  // the Mode a subcommand word sets (bench, record, encode, compare)
};

std::span<const Flag> table();
std::span<const ModeInfo> modes();

const Flag* find(std::string_view arg);  // by name or alias; null when none
const ModeInfo* subcommand(std::string_view word);  // "bench", "record", "encode", "compare"; null else

// The modes `mode` checks its flags against: its bit, or 0 for the listings (which check nothing).
unsigned checkedBit(Mode mode);
// "the gallery", "--headless and record runs", "the gallery, --headless and bench runs": the run modes
// of `modes` (ModeBit), as the refusals and --help name them.
std::string modeList(unsigned modes);
// "--set, --preset and --map": the repeatable flags' names, in the table's order.
std::string repeatableList();
std::string_view modeTitle(unsigned bit);  // "the gallery", "--headless", "bench"
std::string modeHeading(const ModeInfo& mode);  // "The gallery", "--headless", "record": as typed
std::string joinAnd(const std::vector<std::string_view>& names);  // "a, b and c"

// The views the documents share (app/help.cpp, man_page.cpp, completion.cpp).
// A mode's synopsis: the flags it takes, those it needs first, each once; the word that picks the
// mode (--headless) is not among them. For the listings, each listing flag.
struct SynopsisItem {
  const Flag* flag;
  bool required;
};
std::vector<SynopsisItem> synopsis(const ModeInfo& mode);
// The flags grouped by the modes they belong to, in the order each group's first flag has in the table.
struct FlagGroup {
  unsigned modes;
  std::string title;  // "For the gallery, --headless and record runs", "The listings"
  std::vector<const Flag*> flags;
};
std::vector<FlagGroup> groups();

}  // namespace vitrine::flags
