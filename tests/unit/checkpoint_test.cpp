// Checkpoints: the archive a scene walks its state through (one walk saves and restores), and the file
// a checkpoint is kept in, which a run trusts only whole, unaltered and of its own film.
#include <gtest/gtest.h>

#include <deque>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "frame/state_archive.h"
#include "host/offline/checkpoint.h"
#include "support/temp_folder.h"

namespace vitrine {
namespace {

struct Plain {
  int a = 0;
  float b = 0.0f;
  bool operator==(const Plain&) const = default;
};

struct Everything {
  double time = 0.0;
  Plain plain;
  std::vector<float> values;
  std::deque<Plain> history;
  std::optional<double> last;
  std::string name;
  std::vector<std::pair<std::string, std::string>> pairs;
  void walk(StateArchive& state) { state(time, plain, values, history, last, name, pairs); }
  bool operator==(const Everything&) const = default;
};

Everything sample() {
  return {1.0 / 3.0, {7, -0.0f}, {1.5f, 2.5f}, {{1, 1.0f}, {2, 2.0f}}, 4.25, "bloom", {{"lattice", "96"}, {"fill", "0.4"}}};
}

TEST(StateArchive, RestoresWhatOneWalkSaved) {
  Everything saved = sample();
  StateArchive out = StateArchive::saving();
  saved.walk(out);
  Everything restored;
  restored.last = 9.0;  // overwritten, as is everything else
  StateArchive in = StateArchive::restoring(out.bytes());
  EXPECT_TRUE(in.isRestoring());
  restored.walk(in);
  EXPECT_TRUE(in.finished());
  EXPECT_EQ(restored, saved);
  EXPECT_TRUE(std::signbit(restored.plain.b));  // bit for bit, not merely equal

  Everything empty;  // an absent optional and empty containers come back absent and empty
  empty.last.reset();
  StateArchive out2 = StateArchive::saving();
  empty.walk(out2);
  Everything back = sample();
  StateArchive in2 = StateArchive::restoring(out2.bytes());
  back.walk(in2);
  EXPECT_EQ(back, empty);
}

TEST(StateArchive, RefusesStateThatEndsEarly) {
  Everything saved = sample();
  StateArchive out = StateArchive::saving();
  saved.walk(out);
  for (size_t cut : {size_t(0), size_t(5), out.bytes().size() - 1}) {
    const std::vector<std::byte> shorter(out.bytes().begin(), out.bytes().begin() + std::ptrdiff_t(cut));
    StateArchive in = StateArchive::restoring(shorter);
    Everything restored;
    EXPECT_THROW(restored.walk(in), Error) << cut;
  }
  std::vector<std::byte> huge(out.bytes().begin(), out.bytes().end());  // a length no file can hold
  const size_t lengthAt = sizeof(double) + sizeof(Plain);
  huge[lengthAt + 7] = std::byte{0x7f};
  StateArchive in = StateArchive::restoring(huge);
  Everything restored;
  EXPECT_THROW(restored.walk(in), Error);
}

class CheckpointFile : public test::TempFolderTest {
 protected:
  host::Checkpoint checkpoint() const {
    return {"0123456789abcdef", "neon", "llvmpipe", 40, {{audio::Command::Kind::Bell, 1200, 440.0f}},
            {std::byte{1}, std::byte{2}, std::byte{3}}};
  }
  std::string refusal(const std::filesystem::path& path, std::string_view film = "0123456789abcdef") {
    try {
      host::readCheckpoint(path, film);
    } catch (const Error& e) {
      return e.what();
    }
    return "accepted";
  }
};

TEST_F(CheckpointFile, ReadsBackWhatItWrote) {
  const auto path = host::checkpointPath(folder_, 40);
  EXPECT_EQ(path.filename(), "checkpoint_000040.state");
  host::writeCheckpoint(path, checkpoint());
  const host::Checkpoint back = host::readCheckpoint(path, "0123456789abcdef");
  EXPECT_EQ(back.scene, "neon");
  EXPECT_EQ(back.device, "llvmpipe");
  EXPECT_EQ(back.frame, 40u);
  ASSERT_EQ(back.sound.size(), 1u);
  EXPECT_EQ(back.sound[0].sample, 1200);
  EXPECT_EQ(back.simulation, checkpoint().simulation);
}

TEST_F(CheckpointFile, RefusesAnAlteredCutOrForeignFileNamingIt) {
  const auto path = host::checkpointPath(folder_, 40);
  host::writeCheckpoint(path, checkpoint());
  EXPECT_NE(refusal(path, "fedcba9876543210").find("belongs to another film"), std::string::npos);
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  auto rewrite = [&](const std::string& text) { std::ofstream(path, std::ios::binary | std::ios::trunc) << text; };
  std::string flipped = bytes;
  flipped[flipped.size() - 2] ^= 1;
  rewrite(flipped);
  const std::string corrupt = refusal(path);
  EXPECT_NE(corrupt.find(path.string()), std::string::npos) << corrupt;
  EXPECT_NE(corrupt.find("checksum does not match"), std::string::npos) << corrupt;
  rewrite(bytes.substr(0, bytes.size() - 1));
  EXPECT_NE(refusal(path).find("cut short"), std::string::npos);
  rewrite("vitrine checkpoint 99 3 0000000000000000\nabc");
  EXPECT_NE(refusal(path).find("format 99"), std::string::npos);
  rewrite("P6 64 36\n");
  EXPECT_NE(refusal(path).find("is not a checkpoint"), std::string::npos);
}

TEST_F(CheckpointFile, TheLatestAtOrBeforeAFrame) {
  EXPECT_FALSE(host::latestCheckpointFrame(folder_, 100));
  for (uint32_t frame : {0u, 30u, 60u, 90u}) host::writeCheckpoint(host::checkpointPath(folder_, frame), checkpoint());
  std::ofstream(folder_ / "checkpoint_000075.state.tmp") << "x";  // not a checkpoint's name
  EXPECT_EQ(host::latestCheckpointFrame(folder_, 100), 90u);
  EXPECT_EQ(host::latestCheckpointFrame(folder_, 89), 60u);
  EXPECT_EQ(host::latestCheckpointFrame(folder_, 60), 60u);
  EXPECT_EQ(host::latestCheckpointFrame(folder_, 29), 0u);
}

}  // namespace
}  // namespace vitrine
