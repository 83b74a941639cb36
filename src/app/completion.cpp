// The bash completion script, from the flag table. The flags, the modes they belong to and what their
// values are, are written into the script, as the binary that printed it declares them. Scene names,
// parameter keys and preset names are asked of vitrine as one types (--list-scenes, --list-keys,
// --list-presets), not written in: the presets include the user's own, saved since, and the answers are
// the binary's being typed (build/vitrine or the one on the PATH).
#include "app/flags.h"
#include "app/help.h"

#include <fmt/format.h>

#include <string_view>
#include <vector>

namespace vitrine::help {
namespace {

// The names of the flags whose values are `value`, as a case pattern: "--scene|--list-params".
std::string casePattern(flags::Value value) {
  std::string out;
  for (const flags::Flag& flag : flags::table())
    if (flag.value == value) out += (out.empty() ? "" : "|") + std::string(flag.name);
  return out.empty() ? "--no-such-flag" : out;
}

// The shell's name for a mode's list of flags: "gallery", "headless", "export".
std::string modeVariable(const flags::ModeInfo& mode) {
  if (mode.bit == flags::kHeadless) return "headless";
  if (mode.bit == flags::kExport) return "export";
  if (mode.bit == flags::kListing) return "listing";
  return mode.word.empty() ? "gallery" : std::string(mode.word);
}

constexpr std::string_view kBody = R"SH(
# The binary being completed: the one typed (build/vitrine), else the one on the PATH.
_vitrine_bin() {
  local bin=${COMP_WORDS[0]}
  bin=${bin/#\~/$HOME}
  [[ $bin == */* && -x $bin ]] || bin=vitrine
  printf '%s' "$bin"
}

# Adds the words of `$1` (one a line) that begin with `$2` to COMPREPLY, quoted for the shell.
_vitrine_add() {
  local word
  while IFS= read -r word; do
    [[ -n $word && $word == "$2"* ]] && COMPREPLY+=("$(printf '%q' "$word")")
  done <<< "$1"
}

# The scene named by --scene on the line, if any.
_vitrine_scene() {
  local i
  for ((i = 1; i < COMP_CWORD; i++)); do
    [[ ${COMP_WORDS[i]} == --scene ]] && { printf '%s' "${COMP_WORDS[i + 1]}"; return; }
  done
}

# [SCENE.]NAME values: `$1` lists SCENE.NAME lines (--list-keys, --list-presets), `$2` follows each
# (= after a key). Before a '.', the scenes ("bloom.") and the names of --scene's scene.
_vitrine_qualified() {
  local bin cur=${3//\\/} scene
  bin=$(_vitrine_bin)
  if [[ $cur == *.* ]]; then
    scene=${cur%%.*}
    _vitrine_add "$("$bin" "$1" "$scene" 2>/dev/null | sed "s/\$/$2/")" "$cur"
  else
    _vitrine_add "$("$bin" --list-scenes 2>/dev/null | awk '{print $2 "."}')" "$cur"
    scene=$(_vitrine_scene)
    [[ -n $scene ]] && _vitrine_add "$("$bin" "$1" "$scene" 2>/dev/null | sed "s/^[^.]*\.//; s/\$/$2/")" "$cur"
  fi
  compopt -o nospace 2>/dev/null
}

_vitrine() {
  local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD - 1]} mode=gallery word
  COMPREPLY=()
  case ${COMP_WORDS[1]} in
    @COMMAND_PATTERN@) mode=${COMP_WORDS[1]} ;;
  esac
  for word in "${COMP_WORDS[@]:1:COMP_CWORD-1}"; do
    case $word in
@MODE_FLAGS@    esac
  done
  case $prev in
    @OPTIONAL_SCENE@) [[ $cur == -* ]] || _vitrine_add "$("$(_vitrine_bin)" --list-scenes 2>/dev/null | awk '{print $2}')" "$cur" ;;
    @SCENE@)
      _vitrine_add "$("$(_vitrine_bin)" --list-scenes 2>/dev/null | awk '{print $2}')" "$cur"
      [[ $mode == bench ]] && _vitrine_add all "$cur"
      return ;;
    @SETTING@) _vitrine_qualified --list-keys = "$cur"; return ;;
    @PRESET@) _vitrine_qualified --list-presets '' "$cur"; return ;;
    @FILE@) compopt -o filenames 2>/dev/null; COMPREPLY=($(compgen -f -- "$cur")); return ;;
@CHOICES@    @TEXT@) return ;;  # a value with nothing to offer: a number, a size, a name
  esac
  if ((${#COMPREPLY[@]})); then
    return
  elif [[ $cur == -* ]]; then
    local flags=_vitrine_$mode
    COMPREPLY=($(compgen -W "${!flags} $_vitrine_listing" -- "$cur"))
  elif ((COMP_CWORD == 1)); then
    COMPREPLY=($(compgen -W "@COMMANDS@" -- "$cur"))
  elif [[ $mode == encode || $mode == compare ]]; then
    compopt -o filenames 2>/dev/null
    COMPREPLY=($(compgen -f -- "$cur"))
  fi
}
complete -F _vitrine vitrine
)SH";

void replaceMark(std::string& text, std::string_view what, std::string_view with) {
  text.replace(text.find(what), what.size(), with);
}

}  // namespace

std::string bashCompletion() {
  std::string out = "# bash completion for vitrine: written by `vitrine --help-completion` from its flag table.\n";
  out += "# Each mode's flags:\n";
  for (const flags::ModeInfo& mode : flags::modes()) {
    std::string names;
    for (const flags::Flag& flag : flags::table())
      if (flag.modes & mode.bit) names += (names.empty() ? "" : " ") + std::string(flag.name);
    out += fmt::format("_vitrine_{}='{}'\n", modeVariable(mode), names);
  }
  std::string body(kBody);
  replaceMark(body, "@SCENE@", casePattern(flags::Value::Scene));
  replaceMark(body, "@OPTIONAL_SCENE@", casePattern(flags::Value::OptionalScene));
  replaceMark(body, "@SETTING@", casePattern(flags::Value::Setting));
  replaceMark(body, "@PRESET@", casePattern(flags::Value::Preset));
  replaceMark(body, "@FILE@", casePattern(flags::Value::File));
  replaceMark(body, "@TEXT@", casePattern(flags::Value::Text));
  std::string choices;
  for (const flags::Flag& flag : flags::table()) {
    if (flag.value != flags::Value::Choice) continue;
    std::string words(flag.metavar);
    for (char& c : words) c = c == '|' ? ' ' : c;
    choices += fmt::format("    {}) COMPREPLY=($(compgen -W '{}' -- \"$cur\")); return ;;\n", flag.name, words);
  }
  replaceMark(body, "@CHOICES@", choices);
  // The modes: those a first word starts (bench), and those a flag picks (--headless).
  std::string commands, modeFlags;
  for (const flags::ModeInfo& mode : flags::modes()) {
    if (mode.word.starts_with("--")) modeFlags += fmt::format("      {}) mode={} ;;\n", mode.word, modeVariable(mode));
    else if (!mode.word.empty()) commands += (commands.empty() ? "" : " ") + std::string(mode.word);
  }
  std::string commandPattern = commands;
  for (char& c : commandPattern) c = c == ' ' ? '|' : c;
  replaceMark(body, "@COMMAND_PATTERN@", commandPattern);
  replaceMark(body, "@MODE_FLAGS@", modeFlags);
  replaceMark(body, "@COMMANDS@", commands);
  return out + body;
}

}  // namespace vitrine::help
