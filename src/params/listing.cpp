#include "params/listing.h"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

namespace vitrine::params {
namespace {

// Only what changes how a user sets the value: the panel-only flags (logarithmic, apply on release)
// say nothing on the command line.
std::string flagsText(const Param& param) {
  std::vector<std::string> words;
  if (param.has(kRebuilds)) words.emplace_back("rebuilds");
  if (param.has(kTransient)) words.emplace_back("not saved");
  return fmt::format("{}", fmt::join(words, ", "));
}

// Cells wider than these wrap onto the lines below (a list of 18 glass names, a long sentence), so a
// row stays readable on a terminal and one long cell does not widen every other row.
constexpr size_t kTypeWidth = 30, kHelpWidth = 72, kPresetWidth = 100;

// `text` in pieces of at most `width` characters, broken after `separator` (a piece longer than
// `width` with no separator in it stays whole).
std::vector<std::string> wrapped(const std::string& text, size_t width, char separator) {
  std::vector<std::string> lines;
  std::string line;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find(separator, start);
    end = end == std::string::npos ? text.size() : end + 1;
    const std::string word = text.substr(start, end - start);
    if (!line.empty() && line.size() + word.size() > width + (separator == ' ' ? 1 : 0)) {
      lines.push_back(line);
      line.clear();
    }
    line += word;
    start = end;
  }
  if (!line.empty() || lines.empty()) lines.push_back(line);
  for (std::string& piece : lines) piece.erase(piece.find_last_not_of(' ') + 1);
  return lines;
}

struct Row {
  std::vector<std::string> cells[5];  // key, type, default, flags, help: each one line or more
};

}  // namespace

std::string describeSchema(std::string_view sceneName, const Schema& schema) {
  std::string out = fmt::format("{}: {} parameters (--set KEY=VALUE)\n", sceneName, schema.params().size());
  if (schema.params().empty()) out += "  (none)\n";

  // Groups in order of first appearance; the unnamed group is the scene's first section, so it leads.
  std::vector<std::string> groups;
  for (const Param& param : schema.params())
    if (std::find(groups.begin(), groups.end(), param.group) == groups.end()) groups.push_back(param.group);
  std::stable_partition(groups.begin(), groups.end(), [](const std::string& group) { return group.empty(); });

  // Column widths over the whole table, so the groups line up with each other.
  std::vector<Row> rows;
  size_t widths[4] = {};
  for (const Param& param : schema.params()) {
    Row row{{{param.key},
             wrapped(param.typeName(), kTypeWidth, '|'),
             {"default " + param.defaultText},
             {flagsText(param)},
             wrapped(param.help, kHelpWidth, ' ')}};
    for (size_t c = 0; c < 4; ++c)
      for (const std::string& line : row.cells[c]) widths[c] = std::max(widths[c], line.size());
    rows.push_back(std::move(row));
  }

  for (const std::string& group : groups) {
    if (!group.empty()) out += fmt::format("\n  [{}]\n", group);
    for (size_t i = 0; i < rows.size(); ++i) {
      if (schema.params()[i].group != group) continue;
      const Row& row = rows[i];
      size_t height = 0;
      for (const auto& cell : row.cells) height = std::max(height, cell.size());
      for (size_t at = 0; at < height; ++at) {
        std::string line = "  ";
        for (size_t c = 0; c < 4; ++c)  // a column no one uses takes no room
          if (widths[c] > 0) line += fmt::format("{:<{}}  ", at < row.cells[c].size() ? row.cells[c][at] : "", widths[c]);
        if (at < row.cells[4].size()) line += row.cells[4][at];
        line.erase(line.find_last_not_of(' ') + 1);
        out += line + '\n';
      }
    }
  }

  if (!schema.presets().empty()) {
    out += "\npresets (--preset NAME):\n";
    size_t nameWidth = 0;
    for (const Preset& preset : schema.presets()) nameWidth = std::max(nameWidth, preset.name.size());
    for (const Preset& preset : schema.presets()) {
      std::vector<std::string> pairs;
      for (const auto& [key, value] : preset.values) pairs.push_back(key + "=" + value);
      out += fmt::format("  {:<{}}  {}\n", preset.name, nameWidth, preset.help);
      for (const std::string& line : wrapped(fmt::format("{}", fmt::join(pairs, " ")), kPresetWidth, ' '))
        out += fmt::format("  {:<{}}  {}\n", "", nameWidth, line);
    }
  }
  return out;
}

}  // namespace vitrine::params
