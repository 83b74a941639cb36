// The man page: the synopsis and every flag from the flag table, in man(7) roff, which man-db and
// groff render and lintian checks. Written by `vitrine --help-man` (app/help.h says why the binary).
#include "app/flags.h"
#include "app/help.h"

#include <fmt/format.h>

#include <string_view>

namespace vitrine::help {
namespace {

// Text as roff reads it: a backslash doubled, every '-' a minus sign (so flags can be searched and
// copied), and a line that would start with '.' or '\'' kept from being read as a request.
std::string roff(std::string_view text) {
  std::string out;
  for (const char c : text) {
    if (c == '\\') out += "\\e";
    else if (c == '-') out += "\\-";
    else out += c;
  }
  if (!out.empty() && (out.front() == '.' || out.front() == '\'')) out.insert(0, "\\&");
  return out;
}

// "\fB\-\-scene\fR\ \fINAME\fR": the flag bold, its value italic, the two never apart at a line's end.
std::string flagWithValue(const flags::Flag& flag) {
  std::string text = fmt::format("\\fB{}\\fR", roff(flag.name));
  if (!flag.metavar.empty()) text += fmt::format("\\ \\fI{}\\fR", roff(flag.metavar));
  return text;
}

}  // namespace

std::string manPage() {
  // No hyphenation (HY: the man macros turn it on again at each paragraph) and a ragged right edge:
  // flags and file names stay whole and searchable.
  std::string out = ".TH VITRINE 1 \"\" \"Vitrine\" \"User Commands\"\n.nr HY 0\n.nh\n.ad l\n"
                    ".SH NAME\nvitrine \\- a gallery of real\\-time GPU pieces\n.SH SYNOPSIS\n";
  for (const flags::ModeInfo& mode : flags::modes()) {
    out += ".SY vitrine\n";
    if (const flags::Flag* word = flags::find(mode.word)) out += flagWithValue(*word) + "\n";
    else if (!mode.word.empty()) out += fmt::format("\\fB{}\\fR\n", roff(mode.word));
    if (!mode.operands.empty()) out += fmt::format("\\fI{}\\fR\n", roff(mode.operands));
    bool first = true;
    for (const flags::SynopsisItem& item : flags::synopsis(mode)) {
      const bool listing = mode.bit == flags::kListing;
      if (listing && !first) out += "|\n";
      if (item.required || listing) out += flagWithValue(*item.flag) + "\n";
      else out += fmt::format("[{}]{}\n", flagWithValue(*item.flag), item.flag->repeatable ? "...\\&" : "");
      first = false;
    }
    out += ".YS\n";
  }
  out += ".SH DESCRIPTION\n";
  for (const flags::ModeInfo& mode : flags::modes()) {
    if (mode.bit == flags::kListing) continue;
    out += fmt::format(".TP\n.B {}\n{}\n", roff(flags::modeHeading(mode)), roff(mode.about));
  }
  out += ".SH OPTIONS\n";
  for (const flags::FlagGroup& group : flags::groups()) {
    out += fmt::format(".SS \"{}\"\n", roff(group.title));
    for (const flags::Flag* flag : group.flags) {
      const std::string alias = flag->alias.empty() ? "" : fmt::format("\\fB{}\\fR, ", roff(flag->alias));
      out += fmt::format(".TP\n{}{}\n{}{}\n", alias, flagWithValue(*flag), roff(flag->help),
                         flag->repeatable ? " May be given more than once." : "");
    }
  }
  out += ".PP\n" + roff(fmt::format("A flag outside its modes is refused, naming the mode, as is one given twice, "
                                    "except {}, which repeat.",
                                    flags::repeatableList())) +
         "\n";
  out += ".SH ENVIRONMENT\n.TP\n.B VITRINE_VALIDATION\n1 turns on the validation layer, as \\fB\\-\\-validate\\fR does.\n"
         ".SH FILES\n.TP\n.I $XDG_CONFIG_HOME/vitrine/settings.json\n"
         "The gallery's settings (else \\fI~/.config/vitrine\\fR); your presets in \\fIpresets/\\fR beside it.\n";
  return out;
}

}  // namespace vitrine::help
