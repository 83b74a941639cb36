#pragma once
// What a recording's frames were made with, kept beside them as FOLDER/record.json: the scene, size,
// frames a second, samples a frame, seed, start time, format, scripted input, every parameter's
// value, and the ISF filters after the scene (each file's name and fingerprint, their inputs' values
// as filter.NAME.KEY). A run into a folder that already holds a film must agree with it, or two films would be
// mixed in one numbered sequence (neon frames 0-14, then kifs frames 15-29); `record` refuses it,
// naming what differs.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "params/schema.h"

namespace vitrine::host {

struct RecordManifest {
  std::string scene;
  uint32_t width = 0, height = 0;
  double fps = 30.0;
  uint32_t spp = 1;
  uint32_t seed = 0;
  double time = 0.0;  // --time: the film's first instant
  bool reducedMotion = false;
  std::string format;        // "exr" or "png"
  std::string input;         // the --input script's fingerprint (FNV-1a of its bytes), empty without one
  params::KeyValues values;  // every parameter of the scene with its canonical text, sorted by key
  bool flashGuard = false;   // frames through the flash guard (a manifest from before it: off)
  std::vector<std::string> filters;  // each --filter in order: "NAME FINGERPRINT" of its file's bytes
  params::KeyValues filterValues;    // their inputs: filter.NAME.KEY with its exact text
  bool operator==(const RecordManifest&) const = default;
};

// FNV-1a, 64 bits, as 16 hex digits: the fingerprint of a script's text.
std::string fingerprint(std::string_view bytes);

std::string manifestText(const RecordManifest& manifest);  // JSON, one field a line
// Throws vitrine::Error naming `name` when the text is not a manifest this version wrote.
RecordManifest parseManifest(std::string_view text, std::string_view name);

// One phrase per field that differs ("scene: neon in the folder, kifs in this run"); empty when the two
// describe the same film.
std::vector<std::string> manifestDifferences(const RecordManifest& folder, const RecordManifest& run);

// The file beside the frames.
std::filesystem::path manifestPath(const std::filesystem::path& folder);
// The manifest of the sequence in `folder` (vitrine encode reads its size and rate). Throws
// vitrine::Error when the folder has none or it cannot be read.
RecordManifest readManifest(const std::filesystem::path& folder);

// Before the first frame: when `folder` holds a manifest, throws vitrine::Error unless it agrees with
// `run`, naming every difference; when it holds none, writes it (atomically) unless frames are already
// there, made by a run that kept no record of its parameters, which is refused too.
void claimFolder(const std::filesystem::path& folder, const RecordManifest& run, bool folderHasFrames);

}  // namespace vitrine::host
