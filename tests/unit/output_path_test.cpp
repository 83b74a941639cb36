#include "core/error.h"
#include "core/output_path.h"

#include <gtest/gtest.h>

#include "support/temp_folder.h"
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>
#include <string>

namespace vitrine {
namespace {

class OutputPath : public test::TempFolderTest {};

std::string refusal(const std::filesystem::path& path) {
  try {
    checkWritable(path);
  } catch (const Error& e) {
    return e.what();
  }
  return "accepted";
}

TEST_F(OutputPath, AcceptsANewOrAWritableFileInAWritableFolder) {
  EXPECT_EQ(refusal(folder_ / "new.json"), "accepted");
  std::ofstream(folder_ / "old.json") << "{}";
  EXPECT_EQ(refusal(folder_ / "old.json"), "accepted");
}

TEST_F(OutputPath, RefusesAMissingFolderAndAFolder) {
  EXPECT_NE(refusal(folder_ / "missing" / "x.json").find("does not exist"), std::string::npos);
  EXPECT_NE(refusal(folder_).find("it is a folder"), std::string::npos);
}

// The output is replaced by a rename: over a device that would put a file where the device was.
TEST_F(OutputPath, RefusesADevice) {
  EXPECT_EQ(refusal("/dev/full"), "Cannot write /dev/full: it is a character device, not a regular file.");
}

TEST_F(OutputPath, RefusesAFifo) {
  const auto fifo = folder_ / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
  EXPECT_NE(refusal(fifo).find("it is a fifo, not a regular file"), std::string::npos) << refusal(fifo);
}

// By its mode bits: root (CI) may write anywhere, so access(W_OK) would always say yes.
TEST_F(OutputPath, RefusesAReadOnlyFileEvenForRoot) {
  const auto file = folder_ / "frozen.json";
  std::ofstream(file) << "{}";
  std::filesystem::permissions(file, std::filesystem::perms::owner_read | std::filesystem::perms::group_read |
                                         std::filesystem::perms::others_read);
  EXPECT_NE(refusal(file).find("it is read-only"), std::string::npos) << refusal(file);
}

}  // namespace
}  // namespace vitrine
