// The gate every file Vitrine reads passes: a regular file of bounded size, or a refusal in words. A
// fifo with no writer, /dev/zero and links to them are refused at once instead of blocking or growing.
#include "core/bounded_file.h"
#include "support/temp_folder.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>

namespace vitrine {
namespace {

namespace fs = std::filesystem;

class BoundedFileTest : public test::TempFolderTest {
 protected:
  std::string refusal(const fs::path& path, uintmax_t maxBytes = 1 << 20) {
    try {
      readBoundedFile(path, maxBytes);
    } catch (const FileRefused& refused) {
      return refused.why;
    }
    return "read";
  }
};

TEST_F(BoundedFileTest, ReadsARegularFileWhole) {
  std::ofstream(folder_ / "a.txt", std::ios::binary) << "hello";
  EXPECT_EQ(readBoundedFile(folder_ / "a.txt", 5), "hello");
  EXPECT_EQ(refusal(folder_ / "a.txt", 4), "it is larger than 4 bytes");
}

TEST_F(BoundedFileTest, RefusesWhatIsNotARegularFileWithoutBlocking) {
  ASSERT_EQ(::mkfifo((folder_ / "fifo").c_str(), 0600), 0);
  EXPECT_EQ(refusal(folder_ / "fifo"), "it is a fifo, not a regular file");
  EXPECT_EQ(refusal("/dev/zero"), "it is a character device, not a regular file");
  fs::create_symlink("/dev/zero", folder_ / "zero.state");
  EXPECT_EQ(refusal(folder_ / "zero.state"), "it is a character device, not a regular file");
  EXPECT_EQ(refusal(folder_), "it is a folder, not a regular file");
  EXPECT_EQ(refusal(folder_ / "nope"), "it does not exist");
}

TEST(BoundedFile, StatesLimitsInWholeUnits) {
  EXPECT_EQ(bytesInWords(1 << 20), "1 MiB");
  EXPECT_EQ(bytesInWords(64 << 10), "64 KiB");
  EXPECT_EQ(bytesInWords(1000), "1000 bytes");
}

}  // namespace
}  // namespace vitrine
