#include "host/ui/font_check.h"

#include <gtest/gtest.h>

#include "support/temp_folder.h"
#include "support/files.h"
#include <unistd.h>

#include <fstream>
#include <iterator>
#include <string>

namespace vitrine::host {
namespace {

class FontCheck : public test::TempFolderTest {
 protected:
  std::filesystem::path write(const std::string& name, const std::string& bytes) const {
    std::ofstream(folder_ / name, std::ios::binary) << bytes;
    return folder_ / name;
  }
};

// A font that a fetch cut short: the header promises tables the file no longer holds.
TEST_F(FontCheck, ATruncatedFontIsReportedWithFreeTypesReason) {
  const auto woff2 = write("Fraunces.woff2", std::string("wOF2\0\1\0\0", 8) + std::string(40, '\0'));
  EXPECT_FALSE(fontProblem(woff2).empty());
  const auto ttf = write("Cut.ttf", std::string("\0\1\0\0\0\x10\0\x80\0\x04\0\x30", 12));
  EXPECT_FALSE(fontProblem(ttf).empty());
  EXPECT_EQ(fontProblem(write("Text.ttf", "not a font at all")), "unknown file format");
  EXPECT_EQ(fontProblem(folder_ / "absent.ttf"), "cannot open resource");
}

// The same with a real font, cut in half (a system font, where the machine has one).
TEST_F(FontCheck, AFontCutInHalfIsReportedAndTheWholeOneIsNot) {
  const std::filesystem::path dejavu = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
  if (!std::filesystem::exists(dejavu)) GTEST_SKIP() << dejavu << " is not installed";
  EXPECT_EQ(fontProblem(dejavu), "");
  const std::string bytes = test::readFile(dejavu);
  const auto half = write("DejaVuSans.ttf", bytes.substr(0, bytes.size() / 2));
  EXPECT_FALSE(fontProblem(half).empty());
}

}  // namespace
}  // namespace vitrine::host
