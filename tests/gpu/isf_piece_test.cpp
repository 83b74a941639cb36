// ISF generators as pieces, drawn headless on the GPU with the validation layer watching: every project
// file renders; a persistent buffer accumulates; an event is true for exactly one frame; the only
// point2D follows the cursor's drag; a vertex shader places the quad; an imported picture arrives the
// right way up; the loop guard ends an endless loop within its bound; a file edited in the gallery is
// taken up, a broken edit keeps the old version drawing and says why, and a mended one is drawn.
#include "audio/wav.h"
#include "host/live_link.h"
#include "host/offline/offscreen.h"
#include "image/image.h"
#include "isf_twins.h"
#include "scenes/pieces/piece_scene.h"
#include "support/gpu_test.h"
#include "support/test_scene.h"
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

namespace vitrine::test {
namespace {

namespace fs = std::filesystem;

const fs::path kIsfDir = fs::path(VITRINE_GOLDEN_DIR).parent_path() / "isf";

// The piece of a file, registered as the program does at start (once per file for the test binary).
pieces::Piece& piece(const fs::path& file) {
  if (pieces::Piece* known = pieces::findPieceByPath(file)) return *known;
  const auto added = pieces::addPieces(std::vector{file}, true);
  pieces::addPieceFactories(added);
  return *added.front();
}

host::OffscreenConfig config(const fs::path& file, VkExtent2D size = {64, 36}) {
  host::OffscreenConfig c;
  c.scene = piece(file).name;
  c.size = size;
  return c;
}

// A folder of this test's own, removed with it.
struct TempFolder {
  explicit TempFolder(const std::string& name)
      : where(fs::temp_directory_path() / ("vitrine-" + name + "-" + std::to_string(::getpid()))) {
    fs::remove_all(where);
    fs::create_directories(where);
  }
  ~TempFolder() { fs::remove_all(where); }
  const fs::path& path() const { return where; }
  fs::path where;
};

float linear(float encoded) { return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f); }

class IsfPiece : public GpuTest {};

TEST_F(IsfPiece, EveryProjectGeneratorRenders) {
  for (const char* name : {"every_input.fs", "gl3_style.fs", "audio.fs", "events.fs", "multipass.fs", "imported.fs",
                           "drag_point.fs", "inset.fs", "gles_feedback.fs"}) {
    SCOPED_TRACE(name);
    host::Offscreen run(device(), config(kIsfDir / name, {48, 27}));
    run.renderFrame();
    run.renderFrame();
    const ImageRgba image = run.readback();
    for (uint32_t y = 0; y < image.height; ++y)
      for (uint32_t x = 0; x < image.width; ++x) ASSERT_TRUE(std::isfinite(image.at(x, y)[0])) << x << "," << y;
  }
}

// events.fs counts strikes in a 1x1 FLOAT persistent buffer and shows the count as grey (n / 10 as
// ISF's display values); a strike's frame is white, and only that one.
TEST_F(IsfPiece, APersistentBufferAccumulatesAndAnEventFiresOnce) {
  host::Offscreen run(device(), config(kIsfDir / "events.fs", {16, 9}));
  const auto frame = [&](bool strike) {
    if (strike) run.addInput({ActionCall{"strike", {}}}, std::nullopt);
    run.renderFrame();
    return run.readback().at(8, 4)[0];
  };
  EXPECT_NEAR(frame(false), 0.0f, 1e-3f);
  EXPECT_NEAR(frame(true), 1.0f, 1e-3f);  // the strike's frame
  EXPECT_NEAR(frame(false), linear(0.1f), 2e-3f);  // not white again: one count kept
  EXPECT_NEAR(frame(false), linear(0.1f), 2e-3f);
  EXPECT_NEAR(frame(true), 1.0f, 1e-3f);
  EXPECT_NEAR(frame(true), 1.0f, 1e-3f);
  EXPECT_NEAR(frame(false), linear(0.3f), 2e-3f);  // three strikes counted over six frames
  run.addInput({ActionCall{"reset", {}}}, std::nullopt);
  run.renderFrame();
  EXPECT_NEAR(frame(false), 0.0f, 1e-3f);
}

// The bright spot's centre, in 0..1 from the top-left.
glm::vec2 spotCentre(const ImageRgba& image) {
  glm::vec2 sum{0.0f};
  float count = 0.0f;
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x)
      if (image.at(x, y)[0] > 0.5f) sum += glm::vec2(float(x) + 0.5f, float(y) + 0.5f), count += 1.0f;
  return count > 0.0f ? sum / count / glm::vec2(float(image.width), float(image.height)) : glm::vec2(-1.0f);
}

TEST_F(IsfPiece, TheOnlyPoint2DFollowsTheDrag) {
  host::OffscreenConfig c = config(kIsfDir / "drag_point.fs", {96, 54});
  c.input = host::parseInputScript("0.1 move 0.7 0.3\n0.1 down\n0.15 move 0.8 0.6\n0.2 move 0.3 0.4\n0.25 up\n"
                                   "0.3 move 0.9 0.9\n",
                                   "drag");
  host::Offscreen run(device(), c);
  run.renderFrame();
  glm::vec2 at = spotCentre(run.readback());
  EXPECT_NEAR(at.x, 0.25f, 0.02f);  // the default, (0.25, 0.75) from the bottom-left
  EXPECT_NEAR(at.y, 0.25f, 0.03f);
  while (run.time() < 0.17) run.renderFrame();
  at = spotCentre(run.readback());
  EXPECT_NEAR(at.x, 0.8f, 0.02f);
  EXPECT_NEAR(at.y, 0.6f, 0.03f);
  while (run.time() < 0.35) run.renderFrame();  // released at 0.25: a move after does not carry it
  at = spotCentre(run.readback());
  EXPECT_NEAR(at.x, 0.3f, 0.02f);
  EXPECT_NEAR(at.y, 0.4f, 0.03f);
  EXPECT_EQ(params::snapshot(run.parameters()).front(), (std::pair<std::string, std::string>{"spot", "0.3,0.6"}));
}

TEST_F(IsfPiece, AVertexShaderPlacesTheQuad) {
  host::Offscreen run(device(), config(kIsfDir / "inset.fs", {64, 36}));
  run.renderFrame();
  const ImageRgba image = run.readback();
  EXPECT_EQ(image.at(2, 2)[3], 0.0f);  // outside the half-size quad: the cleared output
  EXPECT_EQ(image.at(61, 33)[1], 0.0f);
  EXPECT_GT(image.at(32, 18)[1], 0.2f);  // inside: shade.g (0.8) times 0.5..1
  EXPECT_EQ(image.at(32, 18)[3], 1.0f);
}

// stamp.png's top-left texel is red: drawn whole over the output, it lands top-left, as in any viewer.
TEST_F(IsfPiece, ImportedPicturesArriveTheRightWayUp) {
  const TempFolder folder("isf-imported");
  fs::copy_file(kIsfDir / "stamp.png", folder.path() / "stamp.png");
  std::ofstream(folder.path() / "whole_stamp.fs")
      << "/*{\"ISFVSN\": \"2\", \"IMPORTED\": {\"stamp\": {\"PATH\": \"stamp.png\"}}}*/\n"
         "void main() { gl_FragColor = IMG_NORM_PIXEL(stamp, isf_FragNormCoord); }\n";
  host::Offscreen run(device(), config(folder.path() / "whole_stamp.fs", {16, 16}));
  run.renderFrame();
  const ImageRgba image = run.readback();
  EXPECT_NEAR(image.at(0, 0)[0], 1.0f, 1e-3f);
  EXPECT_NEAR(image.at(0, 0)[2], 0.0f, 1e-3f);
  EXPECT_LT(image.at(0, 15)[0], 0.9f);  // bottom-left: the checker
}

// while (true) {} and for (;;) {} end once the invocation has spent kLoopGuard iterations: the file
// counts them, and white means exactly 65536.
TEST_F(IsfPiece, TheLoopGuardEndsAnEndlessLoop) {
  host::Offscreen run(device(), config(kIsfDir / "endless_loop.fs", {16, 9}));
  const auto start = std::chrono::steady_clock::now();
  run.renderFrame();
  const ImageRgba image = run.readback();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_NEAR(image.at(0, 0)[0], 1.0f, 1e-3f);
  EXPECT_NEAR(image.at(15, 8)[0], 1.0f, 1e-3f);
  EXPECT_LT(seconds, 30.0);
  std::printf("the loop guard's frame: %.2f s for 16x9 pixels of 65536 iterations each\n", seconds);
}

// Loops whose counts are fixed are charged as they start: of a 1000 by 1000 nest the outer loop and 64
// inner ones fit the budget, the 65th inner one and the endless loop after it do not run.
TEST_F(IsfPiece, TheLoopBudgetChargesAFixedNestAsItEnters) {
  host::Offscreen run(device(), config(kIsfDir / "nested_loops.fs", {16, 9}));
  run.renderFrame();
  const ImageRgba image = run.readback();
  EXPECT_NEAR(image.at(0, 0)[0], 1.0f, 1e-3f);
  EXPECT_NEAR(image.at(15, 8)[0], 1.0f, 1e-3f);
  EXPECT_NEAR(image.at(7, 4)[1], 0.0f, 1e-3f);
}

// audio.fs draws the wave as a line and the spectrum as 32 bars: fed by an --audio-in file, frame-exact.
// A 1500 Hz tone is bin 32 of the analysis' 1024 at 48 kHz: the third bar, and no bar far from it.
TEST_F(IsfPiece, AudioInputsDrawTheSoundFile) {
  const TempFolder folder("isf-audio");
  std::vector<float> stereo;
  for (int i = 0; i < 48000; ++i) {
    const float s = 0.7f * float(std::sin(2.0 * 3.14159265358979 * 1500.0 * i / 48000.0));
    stereo.insert(stereo.end(), {s, s});
  }
  audio::writeWav(folder.path() / "tone.wav", stereo);
  // 96 columns over the wave's 512 texels: no column pattern repeats with the tone's period.
  host::OffscreenConfig c = config(kIsfDir / "audio.fs", {96, 36});
  host::LiveConfig liveConfig;
  liveConfig.audioFile = (folder.path() / "tone.wav").string();
  liveConfig.runScene = c.scene;
  host::LiveLink live(liveConfig);
  c.live = &live;
  host::Offscreen run(device(), c);
  for (int i = 0; i < 20; ++i) run.renderFrame();
  const ImageRgba image = run.readback();
  EXPECT_GT(image.at(7, 34)[2], 0.5f);   // the third bar, x = 2.5 / 32 of the width
  EXPECT_GT(image.at(7, 8)[2], 0.5f);    // three quarters up (the file samples between two bars)
  EXPECT_EQ(image.at(61, 34)[2], 0.0f);  // the 21st: nothing there
  // The wave: a line off the middle row somewhere (silence draws it along the middle).
  float offMiddle = 0.0f;
  for (uint32_t x = 0; x < 96; ++x)
    for (uint32_t y = 0; y < 36; ++y)
      if (y < 14 || y > 21) offMiddle = std::max(offMiddle, image.at(x, y)[0]);
  EXPECT_GT(offMiddle, 0.1f);
}

TEST(IsfPieceFolders, TheSettingsFileNamesFolders) {
  const TempFolder folder("isf-settings");
  std::ofstream(folder.path() / "settings.json") << R"({"pieces": ["/srv/isf", 3, "relative/too"], "scenes": {}})";
  EXPECT_EQ(pieces::settingsPieceFolders(folder.path() / "settings.json"),
            (std::vector<fs::path>{"/srv/isf", "relative/too"}));
  std::ofstream(folder.path() / "broken.json") << "{ not json";
  EXPECT_TRUE(pieces::settingsPieceFolders(folder.path() / "broken.json").empty());
  EXPECT_TRUE(fs::exists(folder.path() / "broken.json"));  // read only: never moved aside from here
  EXPECT_TRUE(pieces::settingsPieceFolders(folder.path() / "absent.json").empty());
}

std::string flatFile(const char* colour) {
  return std::string("/*{\"ISFVSN\": \"2\", \"INPUTS\": [{\"NAME\": \"level\", \"TYPE\": \"float\", \"DEFAULT\": 1.0}]}*/\n") +
         "void main() { gl_FragColor = vec4(" + colour + " * level, 1.0); }\n";
}

void writeLater(const fs::path& path, const std::string& text, fs::file_time_type after) {
  std::ofstream(path) << text;
  // A file system whose clock ticks coarsely may give the edit the old time: make it later.
  if (fs::last_write_time(path) <= after) fs::last_write_time(path, after + std::chrono::seconds(1));
}

// Renders until `done` or ten seconds (the edit is compiled on another thread).
template <typename F> bool renderUntil(host::Offscreen& run, F done) {
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (std::chrono::steady_clock::now() < give_up) {
    run.renderFrame();
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));  // the poll looks every 250 ms
  }
  return false;
}

TEST_F(IsfPiece, AnEditIsTakenUpAndABrokenOneKeepsTheOldVersion) {
  const TempFolder folder("isf-reload");
  const fs::path file = folder.path() / "flat.fs";
  std::ofstream(file) << flatFile("vec3(1.0, 0.0, 0.0)");
  pieces::Piece& flat = piece(file);
  host::Offscreen run(device(), config(file, {8, 8}));
  run.renderer().setRealtime(true);  // the gallery's scene: it watches its file
  run.renderer().setScene(*flat.info);
  run.renderer().applyParameters({{"level", "0.5"}});
  run.renderFrame();
  EXPECT_NEAR(run.readback().at(4, 4)[0], linear(0.5f), 2e-3f);

  writeLater(file, flatFile("vec3(0.0, 1.0, 0.0) * brokn"), flat.seen);
  ASSERT_TRUE(renderUntil(run, [&] { return !flat.error.empty(); }));
  EXPECT_NE(flat.error.find("flat.fs:2: error:"), std::string::npos) << flat.error;
  EXPECT_NE(flat.error.find("brokn"), std::string::npos) << flat.error;
  run.renderFrame();
  EXPECT_NEAR(run.readback().at(4, 4)[0], linear(0.5f), 2e-3f);  // the old version draws on

  writeLater(file, flatFile("vec3(0.0, 1.0, 0.0)"), flat.seen);
  ASSERT_TRUE(renderUntil(run, [&] { return flat.error.empty() && run.readback().at(4, 4)[1] > 0.1f; }));
  EXPECT_NEAR(run.readback().at(4, 4)[1], linear(0.5f), 2e-3f);  // the new one, its level kept
  EXPECT_NEAR(run.readback().at(4, 4)[0], 0.0f, 1e-3f);
  EXPECT_EQ(flat.versions.size(), 3u);  // the header read at start, the first showing, the mended edit
}

// An ISF pass costs no more than the same fragment work written natively: speed_field.fs and its native
// twin draw the same picture (within the runner's 8-bit buffers). With VITRINE_ISF_SPEED=WxH (the GPU
// machine, 1920x1080) each one's GPU time is printed, medians of 240 frames after 60, for
// docs/PERFORMANCE.md.
TEST_F(IsfPiece, ASpeedFieldDrawsWhatItsNativeTwinDraws) {
  const TwinRun run = twinRun();
  ASSERT_TRUE(run.valid) << std::getenv("VITRINE_ISF_SPEED");
  SpeedTwin* twin = nullptr;
  const TestSceneEntry& entry = testScene(twin);
  host::Offscreen isf(device(), config(kIsfDir / "speed_field.fs", run.size));
  host::Offscreen native(device(), twinConfig(run.size));
  native.renderer().setScene(entry.info, entry.create);
  const TwinTimes times = timeTwins(isf, native, run, "native twin");
  ASSERT_NE(twin, nullptr);
  std::printf("isf speed %ux%u on %s: isf pass %.4f ms + isf output %.4f ms; native twin %.4f ms\n", run.size.width,
              run.size.height, device().properties().deviceName, times.pass, times.output, times.twin);
  EXPECT_GT(times.pass, 0.0) << "the piece ran";
  const ImageRgba a = isf.readback(), b = native.readback();
  const TwinDifference d = displayDifference(a, b);
  std::printf("isf against its native twin: %.3f (mean) and %.3f (worst) of an 8-bit step\n", d.mean, d.worst);
  EXPECT_LE(d.worst, 1.0);  // the runner's rgba8 buffer rounds to the nearest 8-bit step
  EXPECT_LT(d.mean, 0.5);
}

}  // namespace
}  // namespace vitrine::test
