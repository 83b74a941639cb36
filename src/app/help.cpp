// --help: every mode's synopsis and every flag's help, from the flag table, wrapped at 100 columns.
#include "app/help.h"

#include "app/flags.h"

#include <fmt/format.h>

#include <algorithm>
#include <string_view>
#include <vector>

namespace vitrine::help {
namespace {

constexpr size_t kHelpWidth = 100;
constexpr size_t kHelpColumn = 28;  // where a flag's help starts; a longer flag puts it on the next line

// Appends `words` to `out` as lines no longer than kHelpWidth, the first starting at `first` columns (already
// written), the others indented by `indent`. A word longer than a line has one of its own.
void wrapWords(std::string& out, const std::vector<std::string>& words, size_t first, size_t indent) {
  size_t column = first;
  bool lineEmpty = true;
  for (const std::string& word : words) {
    if (!lineEmpty && column + 1 + word.size() > kHelpWidth) {
      out += "\n" + std::string(indent, ' ');
      column = indent;
      lineEmpty = true;
    }
    if (!lineEmpty) out += ' ', ++column;
    out += word;
    column += word.size();
    lineEmpty = false;
  }
  out += "\n";
}

std::vector<std::string> splitWords(std::string_view text) {
  std::vector<std::string> list;
  size_t start = 0;
  while (start < text.size()) {
    const size_t end = std::min(text.find(' ', start), text.size());
    if (end > start) list.emplace_back(text.substr(start, end - start));
    start = end + 1;
  }
  return list;
}

std::string withValue(const flags::Flag& flag) {
  return flag.metavar.empty() ? std::string(flag.name) : fmt::format("{} {}", flag.name, flag.metavar);
}

// "[--size WxH]", "[--set [SCENE.]KEY=VALUE]...", "--out FILE", "--list-params [SCENE]".
std::string synopsisWord(const flags::SynopsisItem& item) {
  const flags::Flag& flag = *item.flag;
  if (item.required) return withValue(flag);
  return fmt::format("[{}]{}", withValue(flag), flag.repeatable ? "..." : "");
}

}  // namespace

std::string usage() {
  std::string out = "Vitrine: a gallery of real-time GPU pieces.\n\n";
  for (const flags::ModeInfo& mode : flags::modes()) {
    std::vector<std::string> line{"vitrine"};
    if (const flags::Flag* word = flags::find(mode.word)) line.push_back(withValue(*word));
    else if (!mode.word.empty()) line.emplace_back(mode.word);
    if (!mode.operands.empty()) line.emplace_back(mode.operands);
    bool first = true;
    for (const flags::SynopsisItem& item : flags::synopsis(mode)) {
      const bool listing = mode.bit == flags::kListing;  // each a mode of its own: "A | B"
      if (listing && !first) line.emplace_back("|");
      line.push_back(synopsisWord({item.flag, item.required || listing}));
      first = false;
    }
    out += "  ";
    wrapWords(out, line, 2, 10);
  }
  for (const flags::ModeInfo& mode : flags::modes()) {
    if (mode.bit == flags::kListing) continue;
    out += "\n";
    wrapWords(out, splitWords(fmt::format("{}: {}", flags::modeHeading(mode), mode.about)), 0, 0);
  }
  for (const flags::FlagGroup& group : flags::groups()) {
    out += fmt::format("\n{}:\n", group.title);
    for (const flags::Flag* flag : group.flags) {
      std::string name = "  " + withValue(*flag);
      if (!flag->alias.empty()) name = fmt::format("  {}, {}", flag->alias, withValue(*flag));
      out += name;
      if (name.size() + 2 > kHelpColumn) {
        out += "\n" + std::string(kHelpColumn, ' ');
      } else {
        out += std::string(kHelpColumn - name.size(), ' ');
      }
      wrapWords(out, splitWords(flag->help), kHelpColumn, kHelpColumn);
    }
  }
  out += "\n";
  wrapWords(out,
       splitWords(fmt::format("A flag outside its modes is refused, naming the mode, as is one given twice, except {}, "
                         "which repeat.",
                         flags::repeatableList())),
       0, 0);
  return out;
}

}  // namespace vitrine::help
