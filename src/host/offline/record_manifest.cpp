#include "host/offline/record_manifest.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <iterator>
#include <limits>

#include "core/atomic_file.h"
#include "app/options.h"
#include "core/bounded_file.h"
#include "core/error.h"
#include "core/printable.h"

namespace vitrine::host {
namespace {

using nlohmann::json;

constexpr int kManifestVersion = 1;
constexpr std::uintmax_t kMaxManifestBytes = 1 << 20;
constexpr uint32_t kMaxSide = 65536;  // past every device's largest image

std::string readText(const std::filesystem::path& path) {
  try {
    return readBoundedFile(path, kMaxManifestBytes);
  } catch (const FileRefused& refused) {
    throw Error(fmt::format("Cannot read {}: {}.", path.string(), refused.why));
  }
}

}  // namespace

std::string fingerprint(std::string_view bytes) {
  uint64_t hash = 0xcbf29ce484222325ull;
  for (const char c : bytes) hash = (hash ^ static_cast<unsigned char>(c)) * 0x100000001b3ull;
  return fmt::format("{:016x}", hash);
}

std::string manifestText(const RecordManifest& manifest) {
  json values = json::object();
  for (const auto& [key, value] : manifest.values) values[key] = value;
  json filterValues = json::object();
  for (const auto& [key, value] : manifest.filterValues) filterValues[key] = value;
  const json document = {
      {"vitrine_record", kManifestVersion},
      {"scene", manifest.scene},
      {"width", manifest.width},
      {"height", manifest.height},
      {"fps", manifest.fps},
      {"spp", manifest.spp},
      {"seed", manifest.seed},
      {"time", manifest.time},
      {"reduced_motion", manifest.reducedMotion},
      {"flash_guard", manifest.flashGuard},
      {"format", manifest.format},
      {"input", manifest.input},
      {"values", values},
      {"filters", manifest.filters},
      {"filter_values", filterValues},
  };
  return document.dump(2) + "\n";
}

RecordManifest parseManifest(std::string_view text, std::string_view name) {
  const json document = json::parse(text, nullptr, /*allow_exceptions=*/false);
  auto refuse = [&](std::string_view why) -> RecordManifest {
    throw Error(fmt::format("{} is not a recording's manifest that this vitrine can read ({}); move it away "
                            "with the frames, or record into another folder.",
                            printable(name), why));
  };
  if (document.is_discarded() || !document.is_object()) return refuse("not a JSON object");
  try {
    if (!document.contains("vitrine_record") || document.at("vitrine_record") != kManifestVersion)
      return refuse("no \"vitrine_record\": 1");
    // Numbers as record's own options bound them: a hand-edited -54 or 0 must not become a height of
    // 4294967242 or "inf s of sound" downstream.
    const auto whole = [&](const char* key, uint64_t min, uint64_t max) -> uint32_t {
      const json& value = document.at(key);
      // The parser keeps every whole number from 0 up as unsigned; a negative or fractional one is not.
      if (!value.is_number_unsigned() || value.get<uint64_t>() < min || value.get<uint64_t>() > max) refuse(fmt::format("{} {}: a whole number from {} to {}", key, value.dump(), min, max));
      return value.get<uint32_t>();
    };
    RecordManifest manifest;
    manifest.scene = document.at("scene").get<std::string>();
    manifest.width = whole("width", 1, kMaxSide);
    manifest.height = whole("height", 1, kMaxSide);
    manifest.fps = document.at("fps").get<double>();
    if (!(manifest.fps > 0.0 && manifest.fps <= kMaxRecordFps))
      refuse(fmt::format("fps {}: frames a second are above 0 and at most {}", document.at("fps").dump(), kMaxRecordFps));
    manifest.spp = whole("spp", 1, kMaxRecordSpp);
    manifest.seed = whole("seed", 0, std::numeric_limits<uint32_t>::max());
    manifest.time = document.at("time").get<double>();
    manifest.reducedMotion = document.at("reduced_motion").get<bool>();
    manifest.flashGuard = document.value("flash_guard", false);
    manifest.format = document.at("format").get<std::string>();
    manifest.input = document.at("input").get<std::string>();
    if (document.contains("filters")) manifest.filters = document.at("filters").get<std::vector<std::string>>();
    if (document.contains("filter_values"))
      for (const auto& [key, value] : document.at("filter_values").items())
        manifest.filterValues.emplace_back(key, value.get<std::string>());
    for (const auto& [key, value] : document.at("values").items())
      manifest.values.emplace_back(key, value.get<std::string>());
    std::sort(manifest.values.begin(), manifest.values.end());
    return manifest;
  } catch (const json::exception& e) {
    return refuse(e.what());
  }
}

std::vector<std::string> manifestDifferences(const RecordManifest& folder, const RecordManifest& run) {
  std::vector<std::string> out;
  auto differ = [&](std::string_view field, const std::string& was, const std::string& now) {
    if (was != now) out.push_back(fmt::format("{}: {} in the folder, {} in this run", field, printable(was), printable(now)));
  };
  differ("scene", folder.scene, run.scene);
  differ("size", fmt::format("{}x{}", folder.width, folder.height), fmt::format("{}x{}", run.width, run.height));
  differ("fps", fmt::format("{}", folder.fps), fmt::format("{}", run.fps));
  differ("spp", fmt::format("{}", folder.spp), fmt::format("{}", run.spp));
  differ("seed", fmt::format("{}", folder.seed), fmt::format("{}", run.seed));
  differ("time", fmt::format("{}", folder.time), fmt::format("{}", run.time));
  differ("reduced motion", folder.reducedMotion ? "on" : "off", run.reducedMotion ? "on" : "off");
  differ("flash guard", folder.flashGuard ? "on" : "off", run.flashGuard ? "on" : "off");
  differ("format", folder.format, run.format);
  differ("input script", folder.input.empty() ? "none" : folder.input, run.input.empty() ? "none" : run.input);
  const auto chain = [](const std::vector<std::string>& filters) {
    std::string text;
    for (const std::string& filter : filters) text += (text.empty() ? "" : ", ") + filter;
    return text.empty() ? std::string("none") : text;
  };
  differ("filters", chain(folder.filters), chain(run.filters));
  if (folder.scene != run.scene) return out;  // other parameters altogether: the scene says it
  auto valueOf = [](const params::KeyValues& values, const std::string& key) -> std::string {
    for (const auto& [k, v] : values)
      if (k == key) return v;
    return "(none)";
  };
  std::vector<std::string> keys;
  for (const auto& [key, value] : folder.values) keys.push_back(key);
  for (const auto& [key, value] : run.values) keys.push_back(key);
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  for (const std::string& key : keys) differ(key, valueOf(folder.values, key), valueOf(run.values, key));
  if (folder.filters != run.filters) return out;  // other filters: the chain says it
  keys.clear();
  for (const auto& [key, value] : folder.filterValues) keys.push_back(key);
  for (const auto& [key, value] : run.filterValues) keys.push_back(key);
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  for (const std::string& key : keys) differ(key, valueOf(folder.filterValues, key), valueOf(run.filterValues, key));
  return out;
}

std::filesystem::path manifestPath(const std::filesystem::path& folder) { return folder / "record.json"; }

RecordManifest readManifest(const std::filesystem::path& folder) {
  const std::filesystem::path path = manifestPath(folder);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw Error(fmt::format("{} holds no record.json, so its frames' size and rate are unknown; encode a folder that "
                            "vitrine record wrote.", folder.string()));
  return parseManifest(readText(path), path.string());
}

void claimFolder(const std::filesystem::path& folder, const RecordManifest& run, bool folderHasFrames) {
  const std::filesystem::path path = manifestPath(folder);
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    if (folderHasFrames)
      throw Error(fmt::format("{} holds frames but no record.json, so what made them is unknown; resuming could "
                              "mix two films. Move the frames away or record into another folder.",
                              folder.string()));
    const std::string text = manifestText(run);
    writeFileAtomically(path, std::span(reinterpret_cast<const unsigned char*>(text.data()), text.size()));
  }
  // Read back even after writing it: a run started at the same moment into the same folder may have
  // written its own.
  const RecordManifest existing = parseManifest(readText(path), path.string());
  const std::vector<std::string> differences = manifestDifferences(existing, run);
  if (differences.empty()) return;
  std::string list;
  for (const std::string& difference : differences) list += fmt::format("\n  {}", difference);
  throw Error(fmt::format("{} holds another film: its record.json differs from this run in{}\nRecord into another "
                          "folder, or run with the folder's values.",
                          folder.string(), list));
}

}  // namespace vitrine::host
