#pragma once
// record's checkpoints: a film's simulation at the start of a frame, kept beside its frames as
// checkpoint_NNNNNN.state, so a later run (a --range on another machine, a resumed run) starts there
// instead of simulating every frame before it.
//
// A file is one line of text, "vitrine checkpoint VERSION BYTES FNV1A64\n", then BYTES bytes whose FNV-1a
// is FNV1A64: the film's fingerprint (of its record.json), the scene, the device that wrote it, the
// frame, the film's sound commands so far, and the run's simulation (Offscreen::saveSimulation). The
// bytes are native: a checkpoint is for the build and kind of machine that wrote it, and a run only
// trusts one that names its own film and version; see docs/RECORDING.md.
#include "audio/engine.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vitrine::host {

inline constexpr uint32_t kCheckpointVersion = 1;

struct Checkpoint {
  std::string film;    // the fingerprint of the film's record.json
  std::string scene;
  std::string device;  // the device that simulated it: a resume on another says so
  uint32_t frame = 0;  // the first frame not yet simulated
  std::vector<audio::Command> sound;  // the scene's sound up to there
  std::vector<std::byte> simulation;
};

std::filesystem::path checkpointPath(const std::filesystem::path& folder, uint32_t frame);
// Writes it atomically (a reader sees a whole checkpoint or none). Throws vitrine::Error.
void writeCheckpoint(const std::filesystem::path& path, Checkpoint checkpoint);
// The file's checkpoint. Throws vitrine::Error naming the file when it is cut short, fails its checksum,
// was written by another version or belongs to another film than `film`.
Checkpoint readCheckpoint(const std::filesystem::path& path, std::string_view film);
// The frame of the latest checkpoint in `folder` at or before `frame`, if any (by its file name).
std::optional<uint32_t> latestCheckpointFrame(const std::filesystem::path& folder, uint32_t frame);

}  // namespace vitrine::host
