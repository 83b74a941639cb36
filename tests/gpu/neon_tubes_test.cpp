// What makes the neon scene read as neon tubes, measured: at the default a handful of long tubes
// (counted and measured on screen from the chain state read back), in `dense` many distinct coloured
// tubes with dark gaps instead of a white haze, and a drawn stroke that glows along all of its path
// at the release and fades over a couple of seconds after it.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "neon_render.h"
#include "scenes/neon/camera.h"
#include "support/gpu_test.h"

namespace vitrine::test {
namespace neon_tubes {

using neon_frames::display;
using neon_frames::maxChannel;
using neon_frames::minChannel;
using neon_frames::tubeMask;

int intParameter(host::Offscreen& offscreen, const std::string& key) {
  for (const auto& [name, value] : params::snapshot(offscreen.parameters(), true))
    if (name == key) return std::stoi(value);
  ADD_FAILURE() << "no parameter " << key;
  return 0;
}

// Every particle's position and life (chain-major vec4s), read back from the scene's saved simulation:
// the particle buffer is the last thing neon's simulationState walks, after its byte count.
std::vector<glm::vec4> particles(host::Offscreen& offscreen, size_t count) {
  const std::vector<std::byte> state = offscreen.saveSimulation();
  const size_t bytes = count * sizeof(glm::vec4);
  std::vector<glm::vec4> out(count);
  uint64_t stored = 0;
  if (state.size() < bytes + sizeof(stored)) {
    ADD_FAILURE() << "the saved state is shorter than the particles";
    return out;
  }
  std::memcpy(&stored, state.data() + state.size() - bytes - sizeof(stored), sizeof(stored));
  EXPECT_EQ(stored, bytes) << "the particles should be the saved state's last field";
  std::memcpy(out.data(), state.data() + state.size() - bytes, bytes);
  return out;
}

// The length of the segment a-b (pixels) inside the frame [0, w] x [0, h] (Liang-Barsky clipping).
double clippedLength(glm::vec2 a, glm::vec2 b, float w, float h) {
  const glm::vec2 d = b - a;
  double t0 = 0.0, t1 = 1.0;
  const float p[4] = {-d.x, d.x, -d.y, d.y}, q[4] = {a.x, w - a.x, a.y, h - a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0.0f) {
      if (q[i] < 0.0f) return 0.0;
      continue;
    }
    const double t = double(q[i]) / double(p[i]);
    if (p[i] < 0.0f)
      t0 = std::max(t0, t);
    else
      t1 = std::min(t1, t);
  }
  return t1 > t0 ? (t1 - t0) * double(glm::length(d)) : 0.0;
}

struct Tubes {
  int count = 0;        // tubes on screen: alive and longer than a dot
  double median = 0.0;  // their median on-screen length, in frame widths
};

// The tubes a viewer sees now: chains whose life is above kSeenLife and whose on-screen length (the
// polyline through their particles, clipped to the frame) is at least kDot of the frame's width.
Tubes tubesOnScreen(host::Offscreen& offscreen) {
  constexpr float kSeenLife = 0.15f;
  constexpr double kDot = 0.01;
  const auto perChain = size_t(intParameter(offscreen, "particles"));
  const auto chains = size_t(intParameter(offscreen, "chains"));
  const std::vector<glm::vec4> all = particles(offscreen, chains * perChain);
  const float w = float(offscreen.size().width), h = float(offscreen.size().height);
  const glm::mat4 viewProjection = neon::projectionMatrix(w / h) * neon::viewMatrix();
  const auto pixel = [&](glm::vec3 p) {
    const glm::vec4 clip = viewProjection * glm::vec4(p, 1.0f);
    return glm::vec2((clip.x / clip.w * 0.5f + 0.5f) * w, (clip.y / clip.w * 0.5f + 0.5f) * h);
  };
  std::vector<double> lengths;
  for (size_t chain = 0; chain < chains; ++chain) {
    const glm::vec4* p = &all[chain * perChain];
    if (p[0].w < kSeenLife) continue;
    double length = 0.0;
    for (size_t k = 1; k < perChain; ++k) length += clippedLength(pixel(p[k - 1]), pixel(p[k]), w, h);
    if (length / w >= kDot) lengths.push_back(length / w);
  }
  Tubes tubes{int(lengths.size()), 0.0};
  if (!lengths.empty()) {
    std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
    tubes.median = lengths[lengths.size() / 2];
  }
  return tubes;
}

class NeonTubes : public GpuTest {};

// The default autopilot keeps a handful of long tubes on screen, each sweeping a good part of the frame,
// rather than clusters of short strokes. Read at 4, 7 and 10 s.
TEST_F(NeonTubes, TheDefaultShowsAHandfulOfLongTubes) {
  host::Offscreen offscreen(device(), neon_frames::neonConfig({{160, 90}}));
  int frame = 0;
  for (const int seconds : {4, 7, 10}) {
    for (; frame < seconds * 60; ++frame) offscreen.renderFrame(1, false);
    const Tubes tubes = tubesOnScreen(offscreen);
    std::printf("t=%d s: %d tubes on screen, median length %.3f of the frame's width\n", seconds, tubes.count,
                tubes.median);
    RecordProperty(fmt::format("tubes_{}s", seconds), tubes.count);
    RecordProperty(fmt::format("median_length_{}s", seconds), fmt::format("{:.3f}", tubes.median));
    EXPECT_GE(tubes.count, 3) << seconds << " s: a handful of tubes";
    EXPECT_LE(tubes.count, 14) << seconds << " s: a handful of tubes, not a swarm";
    EXPECT_GE(tubes.median, 0.2) << seconds << " s: each tube spans at least a fifth of the frame";
  }
}

struct Haze {
  double white = 0.0;        // share of the frame near white
  double desaturated = 0.0;  // share of the pixels the tubes light where the light they add is pale
  double dark = 0.0;         // share of the frame the tubes leave dark: the gaps between them
};

// `frame` against `facade` (the same without tubes), both the tone-mapped linear light the scene
// writes: where the tubes visibly change the picture (tubeMask, on display values), the light they
// add should be a neon colour, not the pale mix of many hues that reads as haze (the facade's own
// colour, under a halo, is not judged).
Haze haze(const ImageRgba& frame, const ImageRgba& facade) {
  const std::vector<bool> lit = tubeMask(display(frame), display(facade));
  size_t white = 0, tube = 0, pale = 0, dark = 0;
  for (size_t i = 0; i < lit.size(); ++i) {
    white += linearToSrgb(minChannel(&frame.pixels[i * 4])) > 0.8f;
    dark += !lit[i];
    if (!lit[i]) continue;
    ++tube;
    float added[3];
    for (int c = 0; c < 3; ++c) added[c] = std::max(frame.pixels[i * 4 + c] - facade.pixels[i * 4 + c], 0.0f);
    const float hi = maxChannel(added), lo = minChannel(added);
    pale += hi > 0.0f && (hi - lo) / hi < 0.5f;
  }
  const double pixels = double(lit.size());
  return {double(white) / pixels, tube ? double(pale) / double(tube) : 0.0, double(dark) / pixels};
}

// `dense` is many distinct neon tubes with dark gaps between them: almost nothing near white, the
// tubes' light saturated, and much of the frame left dark. Seen as the viewer does (stage final; the
// facade with the same look but no tubes to speak of: glow at its minimum, 0.1).
TEST_F(NeonTubes, DenseIsManyColouredTubesWithDarkGaps) {
  const VkExtent2D size{240, 135};
  constexpr double kSeconds = 4.0;
  const ImageRgba frame = neon_frames::neonRender(device(), {size, 1.0 / 60.0, kSeconds, {}, nullptr, {"dense"}});
  const ImageRgba facade =
      neon_frames::neonRender(device(), {size, 1.0 / 60.0, kSeconds, {{"glow", "0.1"}}, nullptr, {"dense"}});
  const Haze h = haze(frame, facade);
  std::printf("dense: %.4f of the frame near white, %.3f of the lit pixels pale, %.3f of the frame dark\n", h.white,
              h.desaturated, h.dark);
  RecordProperty("white", fmt::format("{:.4f}", h.white));
  RecordProperty("desaturated", fmt::format("{:.3f}", h.desaturated));
  RecordProperty("dark", fmt::format("{:.3f}", h.dark));
  EXPECT_LT(h.white, 0.002) << "dense should not blow out to white";
  EXPECT_LT(h.desaturated, 0.15) << "dense's tubes should be saturated neon, not a pale haze";
  EXPECT_GT(h.dark, 0.4) << "dense should leave dark gaps between its tubes";
}

// A 2 s drag along an S across the facade, moving the cursor every 1/20 s, then released.
constexpr double kStrokeStart = 0.05, kStrokeSeconds = 2.0;
glm::vec2 strokeAt(double s) {  // s in 0..1 along the stroke, normalised output coordinates
  return {float(0.15 + 0.7 * s), float(0.4 + 0.15 * std::sin(2.0 * std::numbers::pi * s))};
}
std::string strokeScript() {
  std::string script =
      fmt::format("{:.2f} move {:.4f} {:.4f}\n{:.2f} down\n", 0.0, strokeAt(0).x, strokeAt(0).y, kStrokeStart);
  for (int i = 1; i <= 40; ++i) {
    const glm::vec2 at = strokeAt(i / 40.0);
    script += fmt::format("{:.2f} move {:.4f} {:.4f}\n", kStrokeStart + kStrokeSeconds * i / 40.0, at.x, at.y);
  }
  return script + fmt::format("{:.2f} up\n", kStrokeStart + kStrokeSeconds);
}

// The share of the stroke's path (sampled along it) within 2 pixels of a pixel the tube lights.
double strokeCovered(const ImageRgba& frame, const ImageRgba& facade) {
  const std::vector<bool> lit = tubeMask(frame, facade);
  const int w = int(frame.width), h = int(frame.height);
  constexpr int kSamples = 400, kReach = 2;
  int covered = 0;
  for (int i = 0; i < kSamples; ++i) {
    const glm::vec2 at = strokeAt((i + 0.5) / kSamples) * glm::vec2(w, h);
    bool near = false;
    for (int dy = -kReach; dy <= kReach && !near; ++dy)
      for (int dx = -kReach; dx <= kReach && !near; ++dx) {
        const int x = int(at.x) + dx, y = int(at.y) + dy;
        near = x >= 0 && y >= 0 && x < w && y < h && lit[size_t(y) * w + x];
      }
    covered += near;
  }
  return double(covered) / kSamples;
}

// A drawn tube keeps the whole stroke: at the release it glows along all of a 2 s drag's path, a
// second later it still holds the stroke's shape, and a few seconds later it has faded away.
TEST_F(NeonTubes, ADrawnTubeKeepsItsWholeStrokeAndFadesAfterTheRelease) {
  const VkExtent2D size{320, 180};
  const std::string script = strokeScript();
  const params::KeyValues values{{"stage", "tubes"}, {"autopilot_idle", "60"}};
  const ImageRgba facade =
      display(neon_frames::neonRender(device(), {size, 1.0 / 60.0, 1.0 / 60.0, {{"stage", "base"}}}));
  const double release = kStrokeStart + kStrokeSeconds;
  double share[3];
  for (int i = 0; const double after : {0.0, 1.0, 4.0}) {
    const ImageRgba frame =
        display(neon_frames::neonRender(device(), {size, 1.0 / 60.0, release + after, values, script.c_str()}));
    share[i++] = strokeCovered(frame, facade);
  }
  double pathPixels = 0.0;
  for (int i = 1; i <= 400; ++i)
    pathPixels += glm::length((strokeAt(i / 400.0) - strokeAt((i - 1) / 400.0)) * glm::vec2(size.width, size.height));
  std::printf(
      "a 2 s stroke (%.0f px): glowing along %.3f of it at the release (%.0f px), %.3f 1 s after, %.3f 4 s "
      "after\n",
      pathPixels, share[0], share[0] * pathPixels, share[1], share[2]);
  RecordProperty("glowing_at_release", fmt::format("{:.3f}", share[0]));
  RecordProperty("glowing_1s_after", fmt::format("{:.3f}", share[1]));
  RecordProperty("glowing_4s_after", fmt::format("{:.3f}", share[2]));
  EXPECT_GT(share[0], 0.9) << "the whole stroke glows at the release";
  EXPECT_GT(share[1], 0.7) << "a second after the release the tube still holds the stroke";
  EXPECT_LT(share[2], 0.05) << "the drawn tube fades within a few seconds of the release";
}

}  // namespace neon_tubes
}  // namespace vitrine::test
