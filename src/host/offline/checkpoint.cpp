#include "host/offline/checkpoint.h"

#include "core/atomic_file.h"
#include "core/bounded_file.h"
#include "core/error.h"
#include "core/printable.h"
#include "frame/state_archive.h"
#include "host/offline/record_manifest.h"

#include <fmt/format.h>

#include <charconv>
#include <cinttypes>
#include <cstdio>
#include <regex>

namespace vitrine::host {
namespace {

// Far above any scene's simulation (a few MB); what a link to a device or a huge file is refused at.
constexpr uintmax_t kMaxCheckpointBytes = uintmax_t(1) << 30;

// Every field in order, saved or restored: one list for both.
void walk(StateArchive& state, Checkpoint& checkpoint) {
  state(checkpoint.film, checkpoint.scene, checkpoint.device, checkpoint.frame, checkpoint.sound,
        checkpoint.simulation);
}

std::string_view textOf(std::span<const std::byte> bytes) {
  return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
}

}  // namespace

std::filesystem::path checkpointPath(const std::filesystem::path& folder, uint32_t frame) {
  return folder / fmt::format("checkpoint_{:06d}.state", frame);
}

void writeCheckpoint(const std::filesystem::path& path, Checkpoint checkpoint) {
  StateArchive state = StateArchive::saving();
  walk(state, checkpoint);
  const std::string header = fmt::format("vitrine checkpoint {} {} {}\n", kCheckpointVersion, state.bytes().size(),
                                         fingerprint(textOf(state.bytes())));
  std::vector<unsigned char> file(header.begin(), header.end());
  const auto* payload = reinterpret_cast<const unsigned char*>(state.bytes().data());
  file.insert(file.end(), payload, payload + state.bytes().size());
  writeFileAtomically(path, file);
}

Checkpoint readCheckpoint(const std::filesystem::path& path, std::string_view film) {
  auto refuse = [&](std::string_view why) {
    return Error(fmt::format("Checkpoint {} {}: delete it to start from an earlier one, or from frame 0.",
                             path.string(), why));
  };
  std::string file;
  try {
    file = readBoundedFile(path, kMaxCheckpointBytes);
  } catch (const FileRefused& refused) {
    throw refuse(fmt::format("cannot be read: {}", refused.why));
  }
  const size_t eol = file.find('\n');
  const std::string header = file.substr(0, eol);
  if (eol == std::string::npos || !header.starts_with("vitrine checkpoint ")) throw refuse("is not a checkpoint");
  uint32_t version = 0;
  uint64_t size = 0;
  char sum[17] = {};
  if (std::sscanf(header.c_str(), "vitrine checkpoint %" SCNu32 " %" SCNu64 " %16s", &version, &size, sum) != 3)
    throw refuse("has a damaged header");
  if (version != kCheckpointVersion)
    throw refuse(fmt::format("was written in format {}; this build reads {}", version, kCheckpointVersion));
  const uint64_t onDisk = file.size() - (eol + 1);
  if (onDisk != size)
    throw refuse(fmt::format("is cut short or padded: {} bytes where its header says {}", onDisk, size));
  const auto* start = reinterpret_cast<const std::byte*>(file.data() + eol + 1);
  const std::vector<std::byte> payload(start, start + size);
  if (fingerprint(textOf(payload)) != sum) throw refuse("is corrupt: its checksum does not match");
  Checkpoint checkpoint;
  try {
    StateArchive state = StateArchive::restoring(payload);
    walk(state, checkpoint);
    if (!state.finished()) throw Error("bytes are left over");
  } catch (const Error& e) {
    throw refuse(fmt::format("cannot be read ({})", printable(e.what())));
  }
  if (checkpoint.film != film) throw refuse("belongs to another film (its record.json differs)");
  return checkpoint;
}

std::optional<uint32_t> latestCheckpointFrame(const std::filesystem::path& folder, uint32_t frame) {
  static const std::regex name(R"(checkpoint_(\d{6,})\.state)");
  std::optional<uint32_t> latest;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    std::smatch match;
    const std::string file = entry.path().filename().string();
    if (!std::regex_match(file, match, name)) continue;
    uint32_t at = 0;
    const std::string digits = match[1];
    if (std::from_chars(digits.data(), digits.data() + digits.size(), at).ec != std::errc()) continue;
    if (at <= frame && (!latest || at > *latest)) latest = at;
  }
  return latest;
}

}  // namespace vitrine::host
