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

struct Row {
  std::string key, type, defaultText, flags, help;
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
    Row row{param.key, param.typeName(), "default " + param.defaultText, flagsText(param), param.help};
    widths[0] = std::max(widths[0], row.key.size());
    widths[1] = std::max(widths[1], row.type.size());
    widths[2] = std::max(widths[2], row.defaultText.size());
    widths[3] = std::max(widths[3], row.flags.size());
    rows.push_back(std::move(row));
  }

  for (const std::string& group : groups) {
    if (!group.empty()) out += fmt::format("\n  [{}]\n", group);
    for (size_t i = 0; i < rows.size(); ++i) {
      if (schema.params()[i].group != group) continue;
      const Row& row = rows[i];
      const std::string* cells[] = {&row.key, &row.type, &row.defaultText, &row.flags};
      std::string line = "  ";
      for (size_t c = 0; c < 4; ++c)
        if (widths[c] > 0) line += fmt::format("{:<{}}  ", *cells[c], widths[c]);  // a column no one uses: none
      line += row.help;
      line.erase(line.find_last_not_of(' ') + 1);
      out += line + '\n';
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
      out += fmt::format("  {:<{}}  {}\n", "", nameWidth, fmt::join(pairs, " "));
    }
  }
  return out;
}

}  // namespace vitrine::params
