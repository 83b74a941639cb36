// Films (src/film/): the container and codec a name and the flags ask for, every refusal's sentence, the
// bitrate's spelling, and the one sRGB conversion a film's frame shares with the PNG writer.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "app/options.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "film/film_format.h"
#include "film/video_encoder.h"
#include "image/image_io.h"
#include "support/temp_folder.h"

namespace vitrine::film {
namespace {

std::string refusal(const std::string& name, const FilmRequest& request, uint32_t width = 64, uint32_t height = 36) {
  try {
    resolveFilm(name, request, width, height);
  } catch (const Error& e) {
    return e.what();
  }
  return "accepted";
}

FilmRequest codec(Codec c) {
  FilmRequest request;
  request.codec = c;
  return request;
}

TEST(FilmFormat, TheContainerComesFromTheExtensionInAnyCase) {
  EXPECT_EQ(containerFromName("film.mp4"), Container::Mp4);
  EXPECT_EQ(containerFromName("out/Film.MOV"), Container::Mov);
  EXPECT_EQ(containerFromName("film.mkv"), Container::Mkv);
  EXPECT_FALSE(containerFromName("film.avi"));
  EXPECT_FALSE(containerFromName("film"));
  EXPECT_FALSE(isFilmName("frames/"));
  EXPECT_EQ(refusal("film.webm", {}), "A film is written as .mp4, .mov or .mkv, not 'film.webm'.");
}

TEST(FilmFormat, EachContainerHasItsDefaultCodec) {
  const FilmFormat mp4 = resolveFilm("a.mp4", {}, 64, 36);
  EXPECT_EQ(mp4.codec, Codec::H264);
  EXPECT_EQ(mp4.encoder, "libx264");
  EXPECT_EQ(mp4.muxer, "mp4");
  EXPECT_EQ(mp4.pixelFormat, "yuv420p");
  EXPECT_EQ(mp4.crf, 18);
  EXPECT_FALSE(mp4.bitrate);
  EXPECT_FALSE(mp4.fullRange);
  EXPECT_EQ(mp4.audioEncoder, "aac");

  const FilmFormat mov = resolveFilm("a.mov", {}, 64, 36);
  EXPECT_EQ(mov.codec, Codec::Prores);
  EXPECT_EQ(mov.encoder, "prores_ks");
  EXPECT_EQ(mov.proresProfile, "hq");
  EXPECT_EQ(mov.pixelFormat, "yuv422p10le");
  EXPECT_TRUE(mov.deep);
  EXPECT_EQ(mov.audioEncoder, "pcm_s24le");

  const FilmFormat mkv = resolveFilm("a.mkv", {}, 64, 36);
  EXPECT_EQ(mkv.codec, Codec::Ffv1);
  EXPECT_EQ(mkv.muxer, "matroska");
  EXPECT_EQ(mkv.pixelFormat, "bgr0");  // 8-bit RGB, lossless
  EXPECT_TRUE(mkv.rgb);
  EXPECT_TRUE(mkv.fullRange);
  EXPECT_FALSE(mkv.deep);

  const FilmFormat hevc = resolveFilm("a.mp4", codec(Codec::Hevc), 64, 36);
  EXPECT_EQ(hevc.encoder, "libx265");
  EXPECT_EQ(hevc.crf, 20);
  const FilmFormat p4444 = resolveFilm("a.mov", codec(Codec::Prores4444), 63, 35);  // 4:4:4: any size
  EXPECT_EQ(p4444.proresProfile, "4444");
  EXPECT_EQ(p4444.pixelFormat, "yuv444p10le");
}

TEST(FilmFormat, RefusesCodecsTheContainerDoesNotHold) {
  EXPECT_EQ(refusal("a.mp4", codec(Codec::Ffv1)), "A .mp4 film holds h264 or hevc, not ffv1; name it .mkv for ffv1.");
  EXPECT_EQ(refusal("a.mp4", codec(Codec::Prores)),
            "A .mp4 film holds h264 or hevc, not prores; name it .mov (or .mkv) for prores.");
  EXPECT_EQ(refusal("a.mov", codec(Codec::Ffv1)),
            "A .mov film holds h264, hevc, prores or prores4444, not ffv1; name it .mkv for ffv1.");
  EXPECT_EQ(refusal("a.mkv", codec(Codec::Prores)), "accepted");
  EXPECT_EQ(refusal("a.mov", codec(Codec::H264)), "accepted");
}

TEST(FilmFormat, SubsampledChromaNeedsEvenSides) {
  EXPECT_EQ(refusal("a.mp4", {}, 63, 36),
            "yuv420p halves the colour across and down, so it needs an even width and height, not 63x36; record at "
            "64x36 or use --pix-fmt yuv444p.");
  EXPECT_NE(refusal("a.mp4", {}, 64, 35).find("not 64x35"), std::string::npos);
  FilmRequest full;
  full.pixelFormat = "yuv444p";
  EXPECT_EQ(refusal("a.mp4", full, 63, 35), "accepted");
  EXPECT_EQ(refusal("a.mov", {}, 63, 36),
            "yuv422p10le halves the colour across, so it needs an even width, not 63x36; record at 64x36 or use "
            "--codec prores4444.");
  EXPECT_EQ(refusal("a.mov", {}, 64, 35), "accepted");  // 4:2:2 keeps every row
  EXPECT_EQ(refusal("a.mkv", {}, 63, 35), "accepted");
}

TEST(FilmFormat, QualityIsForTheCodecsThatHaveIt) {
  FilmRequest request;
  request.crf = 23;
  EXPECT_EQ(resolveFilm("a.mp4", request, 64, 36).crf, 23);
  EXPECT_EQ(refusal("a.mov", request), "--crf is for h264 and hevc, not prores: its quality is its profile's.");
  EXPECT_EQ(refusal("a.mkv", request), "--crf is for h264 and hevc, not ffv1: it is lossless.");
  request.bitrate = 8'000'000;
  EXPECT_EQ(refusal("a.mp4", request), "--crf and --bitrate both set the quality: give one of them.");
  request.crf.reset();
  const FilmFormat byRate = resolveFilm("a.mp4", request, 64, 36);
  EXPECT_EQ(byRate.bitrate, 8'000'000);
  EXPECT_FALSE(byRate.crf);
  EXPECT_EQ(refusal("a.mkv", request), "--bitrate is for h264 and hevc, not ffv1: it is lossless.");
}

TEST(FilmFormat, PixelFormatsAndRange) {
  FilmRequest request;
  request.pixelFormat = "yuv420p10le";
  request.fullRange = true;
  request.codec = Codec::Hevc;
  const FilmFormat deep = resolveFilm("a.mkv", request, 64, 36);
  EXPECT_TRUE(deep.deep);
  EXPECT_TRUE(deep.fullRange);
  EXPECT_FALSE(deep.rgb);
  request.codec.reset();
  request.pixelFormat = "rgb24";
  EXPECT_EQ(refusal("a.mp4", request),
            "--pix-fmt for h264 takes yuv420p, yuv444p, yuv420p10le or yuv444p10le, not 'rgb24'.");
  request.pixelFormat = "yuv444p";
  EXPECT_EQ(refusal("a.mov", request), "--pix-fmt is for h264 and hevc; prores is always yuv422p10le (ProRes 422 HQ).");
  EXPECT_EQ(refusal("a.mkv", request), "--pix-fmt is for h264 and hevc; ffv1 is always 8-bit RGB (bgr0), lossless.");
}

TEST(FilmCodec, NamesInAnyCase) {
  EXPECT_EQ(parseCodec("h264"), Codec::H264);
  EXPECT_EQ(parseCodec("HEVC"), Codec::Hevc);
  EXPECT_EQ(parseCodec("prores4444"), Codec::Prores4444);
  EXPECT_EQ(codecName(Codec::Ffv1), "ffv1");
  try {
    parseCodec("vp9");
    FAIL() << "vp9 accepted";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "--codec takes h264, hevc, prores, prores4444 or ffv1, not 'vp9'.");
  }
}

TEST(FilmBitrate, KiloAndMega) {
  EXPECT_EQ(parseBitrate("8M"), 8'000'000);
  EXPECT_EQ(parseBitrate("2500k"), 2'500'000);
  EXPECT_EQ(parseBitrate("2500K"), 2'500'000);
  EXPECT_EQ(parseBitrate("1.5M"), 1'500'000);
  EXPECT_EQ(parseBitrate("192000"), 192'000);
  EXPECT_EQ(parseBitrate("1000M"), 1'000'000'000);
  for (const char* bad : {"", "M", "0", "-1M", "8G", "8 M", "8MB", "abc", "999", "1001M", "nanM", "infk"}) {
    try {
      parseBitrate(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()),
                std::string("--bitrate expects bits a second from 1k to 1000M, as 8M, 2500k or 1.5M, not '") + bad + "'.");
    }
  }
}

// A frame with every kind of value: below 0, the linear toe, mid-tones, past 1, partial alpha.
ImageRgba ramp() {
  ImageRgba image{37, 5, {}};
  image.pixels.resize(size_t(image.width) * image.height * 4);
  for (size_t i = 0; i < image.pixels.size(); ++i)
    image.pixels[i] = i % 4 == 3 ? 1.0f : -0.05f + 1.3f * std::pow(float(i % 148) / 147.0f, 2.2f);
  return image;
}

using FilmSrgb = test::TempFolderTest;

TEST_F(FilmSrgb, AFilmFrameHasThePngFramesBytes) {
  const ImageRgba image = ramp();
  const auto png = folder_ / "frame.png";
  writeImage(png, image);
  const Picture written = readPicture(png, 4096);
  ASSERT_EQ(written.width, image.width);
  EXPECT_EQ(written.rgba, srgb8(image));
}

TEST(FilmSrgbDeep, SixteenBitsFollowTheSameCurve) {
  const ImageRgba image = ramp();
  const std::vector<uint8_t> narrow = srgb8(image);
  const std::vector<uint16_t> deep = srgb16(image);
  ASSERT_EQ(narrow.size(), deep.size());
  for (size_t i = 0; i < deep.size(); ++i) EXPECT_LE(std::abs(double(deep[i]) / 257.0 - narrow[i]), 0.5 + 1.0 / 257.0) << i;
  EXPECT_EQ(deep[0], 0);  // below 0: black
  EXPECT_EQ(*std::max_element(deep.begin(), deep.end()), 65535);
}

// The command line's side: which runs take the film flags, and what a film's record run refuses.
std::string optionsRefusal(std::vector<const char*> args) {
  args.insert(args.begin(), "vitrine");
  try {
    parseOptions(int(args.size()), args.data());
  } catch (const Error& e) {
    return e.what();
  }
  return "accepted";
}

TEST(FilmOptions, EncodeTakesAFolderAndAFilm) {
  const char* argv[] = {"vitrine", "encode", "frames", "--out", "film.mov", "--codec", "prores4444"};
  const Options options = parseOptions(7, argv);
  EXPECT_EQ(options.mode, Mode::Encode);
  EXPECT_EQ(options.sequence, "frames");
  EXPECT_EQ(options.film.codec, Codec::Prores4444);
  EXPECT_EQ(optionsRefusal({"encode", "--out", "film.mp4"}),
            "encode needs the FOLDER of a recorded sequence: vitrine encode FOLDER --out film.mp4.");
  EXPECT_EQ(optionsRefusal({"encode", "a", "b", "--out", "film.mp4"}), "encode takes one FOLDER, not both a and b.");
  EXPECT_EQ(optionsRefusal({"encode", "frames", "--out", "film.avi"}),
            "encode writes a film: --out NAME.mp4, .mov or .mkv, not 'film.avi'.");
  EXPECT_EQ(optionsRefusal({"encode", "frames", "--out", "film.mp4", "--scene", "kifs"}),
            "--scene is only for the gallery, --headless, bench and record runs, not encode.");
  EXPECT_EQ(optionsRefusal({"--headless", "--scene", "kifs", "--codec", "h264", "--out", "x.exr"}),
            "--codec is only for record and encode runs, not --headless.");
}

TEST(FilmOptions, AFilmsRecordRunRefusesWhatIsForFrames) {
  const std::vector<const char*> film{"record", "--scene", "kifs", "--seconds", "1", "--out", "film.mp4"};
  auto with = [&](std::vector<const char*> more) {
    std::vector<const char*> args = film;
    args.insert(args.end(), more.begin(), more.end());
    return optionsRefusal(args);
  };
  EXPECT_EQ(with({}), "accepted");
  EXPECT_EQ(with({"--range", "0:5"}).substr(0, 62),
            "--range is for a sequence of frames in a folder; film.mp4 is a");
  EXPECT_EQ(with({"--format", "png"}),
            "--format picks the frames' files in a folder; film.mp4 is a film, encoded as --codec says.");
  EXPECT_EQ(with({"--size", "63x36"}).substr(0, 38), "yuv420p halves the colour across and d");
  EXPECT_EQ(with({"--crf", "52"}), "--crf expects a whole number from 0 to 51, not '52'.");
  EXPECT_EQ(with({"--codec", "ffv1"}), "A .mp4 film holds h264 or hevc, not ffv1; name it .mkv for ffv1.");
  EXPECT_EQ(optionsRefusal({"record", "--scene", "kifs", "--seconds", "1", "--out", "film.mkv", "--crf", "10"}),
            "--crf is for h264 and hevc, not ffv1: it is lossless.");
  EXPECT_EQ(optionsRefusal({"record", "--scene", "kifs", "--seconds", "1", "--out", "frames", "--codec", "h264"}),
            "--codec is for a film: --out NAME.mp4, .mov or .mkv, not the folder frames.");
  EXPECT_EQ(optionsRefusal({"record", "--scene", "kifs", "--seconds", "1", "--out", "/nonexistent/film.mkv"}),
            "Cannot write /nonexistent/film.mkv: the folder /nonexistent does not exist.");
}

using FilmPendingFile = test::TempFolderTest;

TEST_F(FilmPendingFile, HiddenBesideTheTargetUntilCommitted) {
  const auto target = folder_ / "film.mp4";
  {
    PendingFile pending(target);
    EXPECT_EQ(pending.path().parent_path(), folder_);
    EXPECT_TRUE(pending.path().filename().string().starts_with(".film.mp4."));
    EXPECT_EQ(pending.path().extension(), ".mp4");  // muxers that sniff the name see the target's
    EXPECT_TRUE(std::filesystem::exists(pending.path()));
    EXPECT_FALSE(std::filesystem::exists(target));
  }
  EXPECT_TRUE(std::filesystem::is_empty(folder_)) << "an uncommitted file is removed";
  PendingFile pending(target);
  pending.commit();
  EXPECT_TRUE(std::filesystem::exists(target));
  EXPECT_FALSE(std::filesystem::exists(pending.path()));
}

using FilmEncoder = test::TempFolderTest;

ImageRgba grey(uint32_t width, uint32_t height, float value) {
  ImageRgba image{width, height, std::vector<float>(size_t(width) * height * 4, value)};
  for (size_t i = 3; i < image.pixels.size(); i += 4) image.pixels[i] = 1.0f;
  return image;
}

TEST_F(FilmEncoder, AFinishedFilmIsTheOnlyFileLeft) {
  const auto target = folder_ / "film.mkv";
  {
    VideoEncoder encoder(target, resolveFilm(target, {}, 16, 8), 16, 8, 24.0);
    encoder.addSoundTrack();
    for (int frame = 0; frame < 3; ++frame) encoder.addFrame(grey(16, 8, 0.1f * float(frame)));
    EXPECT_EQ(encoder.frames(), 3u);
    const std::vector<float> sound(48000 / 8 * 2, 0.25f);  // an eighth of a second, the film's length
    encoder.addSound(sound);
    encoder.finish();
  }
  EXPECT_GT(std::filesystem::file_size(target), 0u);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(folder_), {}), 1);
}

// A film is on the disk as it is made, frame by frame, not held until its end: its temporary grows
// with every frame, sound and all.
TEST_F(FilmEncoder, TheTemporaryGrowsAsFramesAndSoundGoIn) {
  const auto target = folder_ / "film.mkv";
  VideoEncoder encoder(target, resolveFilm(target, {}, 16, 8), 16, 8, 24.0);
  encoder.addSoundTrack();
  const auto onDisk = [&] {
    const auto entry = *std::filesystem::directory_iterator(folder_);
    return std::filesystem::file_size(entry.path());
  };
  std::vector<uintmax_t> sizes;
  for (int frame = 0; frame < 48; ++frame) {
    encoder.addFrame(grey(16, 8, 0.02f * float(frame)));
    encoder.addSound(std::vector<float>(2000 * 2, 0.25f));  // a 24th of a second
    if (frame % 12 == 11) sizes.push_back(onDisk());
  }
  ASSERT_EQ(sizes.size(), 4u);
  for (size_t i = 1; i < sizes.size(); ++i) EXPECT_GT(sizes[i], sizes[i - 1]) << "after " << (i + 1) * 12 << " frames";
  // Two seconds in, over a second of the 24-bit sound is on the disk (Matroska holds a cluster back).
  EXPECT_GT(sizes[3], 48000u * 2 * 3);
  encoder.finish();
  EXPECT_FALSE(std::filesystem::is_empty(folder_));
}

TEST_F(FilmEncoder, TheSoundTrackComesBeforeTheFirstFrameAndEndsWithTheFilm) {
  const auto target = folder_ / "film.mkv";
  VideoEncoder encoder(target, resolveFilm(target, {}, 16, 8), 16, 8, 24.0);
  EXPECT_THROW(encoder.addSound(std::vector<float>(2, 0.0f)), Error);  // no track yet
  encoder.addSoundTrack();
  EXPECT_THROW(encoder.addSoundTrack(), Error);
  encoder.addFrame(grey(16, 8, 0.5f));
  encoder.addSound(std::vector<float>(48000 * 2, 0.25f));  // a whole second: more than the film's frame
  try {
    encoder.finish();
    ADD_FAILURE() << "a second of sound went into a film of one frame";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("past the film's 2000"), std::string::npos) << e.what();
  }
  VideoEncoder silent(folder_ / "silent.mkv", resolveFilm(target, {}, 16, 8), 16, 8, 24.0);
  silent.addFrame(grey(16, 8, 0.5f));
  EXPECT_THROW(silent.addSoundTrack(), Error);  // its header is written: no stream can join
}

TEST_F(FilmEncoder, AnUnfinishedFilmLeavesNothing) {
  const auto target = folder_ / "film.mp4";
  {
    VideoEncoder encoder(target, resolveFilm(target, {}, 16, 8), 16, 8, 30.0);
    encoder.addFrame(grey(16, 8, 0.5f));
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(folder_), {}), 1);  // the hidden temporary
    try {
      encoder.addFrame(grey(8, 8, 0.5f));
      ADD_FAILURE() << "a frame of another size was taken";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("Cannot add a 8x8 frame to"), std::string::npos) << e.what();
    }
  }
  EXPECT_TRUE(std::filesystem::is_empty(folder_));
}

}  // namespace
}  // namespace vitrine::film
