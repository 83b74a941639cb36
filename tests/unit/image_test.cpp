// The golden metric's handling of bad values and sizes, and the image reader's handling of files that
// are not EXRs. No GPU.
#include "core/error.h"
#include "image/image_compare.h"
#include "image/image_file.h"
#include "image/image_io.h"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include "support/temp_folder.h"
#include "support/images.h"
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <cmath>
#include <fstream>
#include <limits>
#include <string>

namespace vitrine {
namespace {

using test::flatImage;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(CompareNonFinite, NaNInTheReferenceFails) {
  auto reference = flatImage(8, 8, 0.5f);
  reference.at(3, 4)[0] = kNaN;
  const auto r = compareImages(reference, flatImage(8, 8, 0.5f));
  EXPECT_FALSE(r.passed) << r.summary();
  EXPECT_EQ(r.nonFiniteReference, 1u);
  EXPECT_EQ(r.nonFinite, 0u);
  EXPECT_EQ(r.failing, 1u);
  EXPECT_TRUE(contains(r.summary(), "FAIL")) << r.summary();
  EXPECT_TRUE(contains(r.summary(), "1 non-finite in the reference")) << r.summary();
}

TEST(CompareNonFinite, InfinityInTheReferenceFailsAndIsCountedAsAFailingPixel) {
  auto reference = flatImage(8, 8, 0.5f);
  reference.at(0, 0)[2] = kInf;
  reference.at(1, 0)[1] = -kInf;
  const auto r = compareImages(reference, flatImage(8, 8, 0.5f));
  EXPECT_FALSE(r.passed);
  EXPECT_EQ(r.nonFiniteReference, 2u);
  EXPECT_EQ(r.failing, 2u);
  EXPECT_TRUE(std::isfinite(r.maxDifference)) << r.summary();  // not "max difference inf"
  EXPECT_TRUE(contains(r.summary(), "2 non-finite in the reference")) << r.summary();
}

TEST(CompareNonFinite, NonFiniteOnBothSidesIsCountedOnEach) {
  auto reference = flatImage(4, 4, 0.5f);
  auto candidate = reference;
  reference.at(0, 0)[0] = kNaN;
  candidate.at(0, 0)[0] = kNaN;  // the same NaN on both sides is still not a picture
  candidate.at(1, 1)[3] = kInf;
  const auto r = compareImages(reference, candidate);
  EXPECT_FALSE(r.passed);
  EXPECT_EQ(r.nonFiniteReference, 1u);
  EXPECT_EQ(r.nonFinite, 2u);
  EXPECT_TRUE(contains(r.summary(), "1 non-finite in the reference, 2 in the candidate")) << r.summary();
}

TEST(CompareSize, MismatchNamesBothSizes) {
  const auto r = compareImages(flatImage(192, 108, 0), flatImage(64, 36, 0));
  EXPECT_FALSE(r.passed);
  EXPECT_FALSE(r.sizeMatches);
  EXPECT_EQ(r.summary(), "size mismatch: reference 192x108, candidate 64x36");
}

class ImageFiles : public test::TempFolderTest {};

// A reference EXR holding NaN, written and read back as `vitrine compare` and the golden tests do.
TEST_F(ImageFiles, ANaNReferenceWrittenToExrFailsTheComparison) {
  auto reference = flatImage(8, 8, 0.25f);
  reference.at(2, 2)[1] = kNaN;
  reference.at(5, 5)[0] = kInf;
  const auto path = folder_ / "nan_reference.exr";
  writeImage(path, reference);
  const ImageRgba read = readImage(path);
  ASSERT_EQ(read.width, 8u);
  EXPECT_TRUE(std::isnan(read.at(2, 2)[1]));
  EXPECT_TRUE(std::isinf(read.at(5, 5)[0]));
  const auto r = compareImages(read, flatImage(8, 8, 0.25f));
  EXPECT_FALSE(r.passed) << r.summary();
  EXPECT_TRUE(contains(r.summary(), "2 non-finite in the reference")) << r.summary();
}

std::string readError(const std::filesystem::path& path) {
  try {
    readImage(path);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST_F(ImageFiles, ReadingADeviceIsRefusedAtOnce) {
  EXPECT_EQ(readError("/dev/zero"), "Cannot read /dev/zero: it is a character device, not a regular file.");
}

TEST_F(ImageFiles, ReadingAFolderOrAMissingFileSaysSo) {
  EXPECT_TRUE(contains(readError(folder_), "it is a folder")) << readError(folder_);
  EXPECT_TRUE(contains(readError(folder_ / "absent.exr"), "No such file or directory"));
}

TEST_F(ImageFiles, APngNamedExrIsCalledAPng) {
  const auto path = folder_ / "picture.exr";
  std::ofstream(path, std::ios::binary) << "\x89PNG\r\n\x1a\n\0\0\0\rIHDR";
  EXPECT_EQ(readError(path), "Cannot read " + path.string() + ": it is a PNG file, not an EXR.");
}

TEST_F(ImageFiles, EmptyAndUnknownFilesAreNotExrs) {
  const auto empty = folder_ / "empty.exr";
  std::ofstream(empty).close();
  EXPECT_TRUE(contains(readError(empty), "it is empty, not an EXR")) << readError(empty);
  const auto text = folder_ / "notes.exr";
  std::ofstream(text) << "just some text";
  EXPECT_TRUE(contains(readError(text), "it is not an EXR")) << readError(text);
}

// OpenImageIO's shared cache once remembered a file by its name and modification second, so a picture
// replaced under the same name was read with the old one's size, past the end of the pixels (found by
// fuzzing). The pairs kept in tests/fuzz-regressions are copied in turn over one file; each read must
// see the file as it is now (all three second files are 8 x 6).
TEST_F(ImageFiles, AFileReplacedUnderTheSameNameIsReadAsItIsNow) {
  const std::filesystem::path kept = VITRINE_FUZZ_REGRESSION_DIR;
  for (const char* format : {"png", "hdr", "exr"}) {
    const auto path = folder_ / fmt::format("backdrop.{}", format);
    for (int i : {1, 2}) {
      std::filesystem::copy_file(kept / fmt::format("image_{}/stale-cache-{}.{}", format, i, format), path,
                                 std::filesystem::copy_options::overwrite_existing);
      const Picture picture = readPicture(path, 2048);
      if (i == 2) {
        EXPECT_EQ(picture.width, 8u) << format;
        EXPECT_EQ(picture.height, 6u) << format;
      }
      if (std::string_view(format) == "exr") {
        EXPECT_EQ(readImage(path).width, i == 2 ? 8u : 7u);
      }
    }
  }
}

// OpenImageIO (~260 shared libraries, ~0.3 s of CPU to load) is loaded by the first picture in a format
// the image module does not read itself, never by EXR, PNG or JPEG. Checked in a fresh process (a
// threadsafe death test runs this test alone in a new one), so no earlier test has loaded it.
TEST_F(ImageFiles, OpenImageIoLoadsOnlyForAnOtherFormat) {
#if VITRINE_WITH_OIIO
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const auto loaded = [] {
    std::ifstream maps("/proc/self/maps");
    for (std::string line; std::getline(maps, line);)
      if (line.find("libOpenImageIO") != std::string::npos) return true;
    return false;
  };
  const std::filesystem::path folder = folder_, kept = VITRINE_FUZZ_REGRESSION_DIR;
  EXPECT_EXIT(
      {
        writeImage(folder / "a.png", flatImage(4, 4, 0.5f));
        writeImage(folder / "a.exr", flatImage(4, 4, 0.5f));
        const bool early = loaded() || readPicture(folder / "a.png", 64).width != 4 ||
                           readPicture(folder / "a.exr", 64).width != 4 || loaded();
        const Picture hdr = readPicture(kept / "image_hdr/stale-cache-2.hdr", 64);
        std::filesystem::remove_all(folder);  // the child's own (its SetUp made it); it ends without TearDown
        std::exit(early ? 1 : !loaded() ? 2 : hdr.width != 8 || hdr.height != 6 ? 3 : 0);
      },
      ::testing::ExitedWithCode(0), "");
#else
  GTEST_SKIP() << "this build reads no other formats";
#endif
}

// A fuzzed EXR (tests/fuzz-regressions/image_exr/huge-attribute-*, 857 bytes) whose first attribute
// claims 1 768 882 176 bytes: OpenEXR's C++ library, inside OpenImageIO, allocated and cleared that much
// before finding the file too short (over 10 s under ASan). OpenEXR's C core now reads the header
// first: both readers refuse the file at once, saying which attribute is wrong and how big the file is.
TEST_F(ImageFiles, AnExrHeaderClaimingMoreThanTheFileIsRefusedAtOnce) {
  const auto kept = std::filesystem::path(VITRINE_FUZZ_REGRESSION_DIR) / "image_exr" / "huge-attribute-0c69f309.exr";
  for (const char* name : {"panorama.exr", "backdrop.jpg"}) {  // readPicture judges by content, not name
    const auto path = folder_ / name;
    std::filesystem::copy_file(kept, path);
    const auto start = std::chrono::steady_clock::now();
    const std::string why = readError(path);
    std::string pictureWhy = "no error";
    try {
      readPicture(path, 2048);
    } catch (const Error& e) {
      pictureWhy = e.what();
    }
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
    for (const std::string& message : {why, pictureWhy}) {
      EXPECT_TRUE(contains(message, "Cannot read " + path.string() + ": its EXR header is inconsistent")) << message;
      EXPECT_TRUE(contains(message, "'Exif:ImageHistoring'")) << message;
      EXPECT_TRUE(contains(message, "1768882176")) << message;
      EXPECT_TRUE(contains(message, "the file is 857 bytes")) << message;
    }
  }
}

// Every EXR Vitrine ships or makes passes the header check: the seeds' compressions, the goldens.
TEST_F(ImageFiles, WellFormedExrHeadersPassTheCheck) {
  const auto path = folder_ / "written.exr";
  writeImage(path, flatImage(8, 8, 0.5f));
  EXPECT_NO_THROW(checkExrHeader(path));
  for (const char* pair : {"stale-cache-1.exr", "stale-cache-2.exr"})
    EXPECT_NO_THROW(checkExrHeader(std::filesystem::path(VITRINE_FUZZ_REGRESSION_DIR) / "image_exr" / pair));
}

TEST(ImageFormat, SniffsTheCommonFormats) {
  auto sniff = [](std::string_view bytes) {
    return sniffImageFormat(std::span(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size()));
  };
  using namespace std::string_view_literals;
  EXPECT_EQ(sniff("\x76\x2f\x31\x01\x02\0\0\0"sv), "EXR");
  EXPECT_EQ(sniff("\x89PNG\r\n\x1a\n"sv), "PNG");
  EXPECT_EQ(sniff("\xff\xd8\xff\xe0"sv), "JPEG");
  EXPECT_EQ(sniff("II*\0\x08\0\0\0"sv), "TIFF");
  EXPECT_EQ(sniff("#?RADIANCE\n"sv), "Radiance HDR");
  EXPECT_EQ(sniff("RIFF\0\0\0\0WEBPVP8 "sv), "WebP");
  EXPECT_EQ(sniff("\x76\x2f"sv), "");  // too short to tell
  EXPECT_EQ(sniff("hello"sv), "");
}

TEST(ImageFormat, OnePlaceDecidesTheFormatFromTheNameInAnyCase) {
  EXPECT_EQ(imageFormatFromName("a/x.exr"), ImageFormat::Exr);
  EXPECT_EQ(imageFormatFromName("x.EXR"), ImageFormat::Exr);
  EXPECT_EQ(imageFormatFromName("x.Png"), ImageFormat::Png);
  EXPECT_EQ(imageFormatFromName("x.pNg"), ImageFormat::Png);
  EXPECT_EQ(imageFormatFromName("x.png.bak"), std::nullopt);
  EXPECT_EQ(imageFormatFromName("png"), std::nullopt);
  EXPECT_EQ(imageFormatFromName("x.jpg"), std::nullopt);
}

// `--out x.Png` once wrote linear values into an sRGB PNG (too dark): the writer asked for ".png" or
// ".PNG" only. Linear 0.2 is sRGB 124 of 255, not 51.
TEST_F(ImageFiles, AMixedCasePngNameGetsSrgbPixels) {
  for (const char* name : {"lower.png", "mixed.Png", "upper.PNG"}) {
    const auto path = folder_ / name;
    ImageRgba grey = flatImage(4, 2, 0.2f);
    for (size_t i = 3; i < grey.pixels.size(); i += 4) grey.pixels[i] = 1.0f;  // opaque: PNG alpha is straight
    writeImage(path, grey);
    const Picture picture = readPicture(path, 16);
    ASSERT_EQ(picture.width, 4u) << name;
    EXPECT_NEAR(int(picture.rgba[0]), 124, 1) << name;
  }
}

// A resumed recording keeps only frames that decode whole at the film's size.
TEST_F(ImageFiles, AWholeImageIsToldFromATruncatedOrResizedOne) {
  for (const char* name : {"frame.exr", "frame.png"}) {
    const auto path = folder_ / name;
    ImageRgba image = flatImage(64, 36, 0.0f);
    for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = float((i * 2654435761u) % 1000) / 1000.0f;
    writeImage(path, image);
    EXPECT_TRUE(isWholeImage(path, 64, 36)) << name;
    EXPECT_FALSE(isWholeImage(path, 32, 18)) << name << ": another film's size";
    const auto bytes = std::filesystem::file_size(path);
    std::filesystem::resize_file(path, bytes * 2 / 3);  // cut short, as on a full disk
    EXPECT_FALSE(isWholeImage(path, 64, 36)) << name << " cut to " << bytes * 2 / 3 << " of " << bytes << " bytes";
    std::filesystem::resize_file(path, 0);
    EXPECT_FALSE(isWholeImage(path, 64, 36)) << name;
  }
  EXPECT_FALSE(isWholeImage(folder_ / "missing.exr", 64, 36));
}

}  // namespace
}  // namespace vitrine
