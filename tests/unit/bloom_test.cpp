// The bloom scene's maths (src/scenes/bloom/bloom_math.h): the CPU reference diffusion, the stability
// bound, the phase colours, the cursor's vapour, the seed's proxy and the phase detector.
#include "scenes/bloom/bloom_math.h"
#include "scenes/bloom/settings.h"

#include <gtest/gtest.h>

#include <numeric>

namespace vitrine::bloom {
namespace {

std::vector<float> filled(uint32_t n, float value) {
  std::vector<float> lattice(size_t(n) * n * n, 0.0f);
  for (uint32_t z = 0; z < n; ++z)
    for (uint32_t y = 0; y < n; ++y)
      for (uint32_t x = 0; x < n; ++x)
        if (insideCrystal(voxelCentre({x, y, z}, n))) lattice[(size_t(z) * n + y) * n + x] = value;
  return lattice;
}

double mass(const std::vector<float>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }

TEST(BloomDiffusion, WithoutSourceOrDecayMassOnlyLeavesThroughTheMask) {
  const uint32_t n = 24;
  // A bump well inside the crystal: diffusion alone moves it about without creating or losing any
  // until it reaches the surface.
  std::vector<float> in(size_t(n) * n * n, 0.0f), out;
  in[(size_t(12) * n + 12) * n + 12] = 1.0f;
  DiffusionParams p;
  p.diffusion = 10.0f;
  p.dt = 0.01f;
  diffuseLattice(in, out, n, p);
  EXPECT_NEAR(mass(out), 1.0, 1e-5);
  EXPECT_NEAR(out[(size_t(12) * n + 12) * n + 13], 0.1f, 1e-6) << "D dt = 0.1 of the bump to each neighbour";
  // Decay takes exactly its share.
  p.decay = 0.5f;
  diffuseLattice(in, out, n, p);
  EXPECT_NEAR(mass(out), 1.0 * (1.0 - 0.5 * 0.01), 1e-5);
  // A full crystal loses vapour only at its surface, where the outside is kept at zero.
  const auto full = filled(n, 0.5f);
  p.decay = 0.0f;
  diffuseLattice(full, out, n, p);
  EXPECT_LT(mass(out), mass(full));
  EXPECT_FLOAT_EQ(out[(size_t(12) * n + 12) * n + 12], 0.5f) << "the inside of a uniform crystal does not change";
  for (uint32_t x = 0; x < n; ++x) EXPECT_EQ(out[x], 0.0f) << "outside the octahedron stays empty";
}

TEST(BloomDiffusion, ACentredSourceStaysSymmetric) {
  const uint32_t n = 20;
  std::vector<float> a(size_t(n) * n * n, 0.0f), b;
  DiffusionParams p{8.0f, 0.1f, 0.02f, true, glm::vec3(10.0f), 3.0f, 2.0f};
  for (int step = 0; step < 20; ++step) {
    diffuseLattice(a, b, n, p);
    std::swap(a, b);
  }
  const auto at = [&](uint32_t x, uint32_t y, uint32_t z) { return a[(size_t(z) * n + y) * n + x]; };
  EXPECT_GT(at(10, 10, 10), 0.1f);
  for (uint32_t d = 1; d < 6; ++d) {
    const float ref = at(10 + d - 1, 10, 10);
    EXPECT_FLOAT_EQ(at(10 - d, 10, 10), ref);
    EXPECT_FLOAT_EQ(at(10, 10 + d - 1, 10), ref);
    EXPECT_FLOAT_EQ(at(10, 10, 10 - d), ref);
  }
}

TEST(BloomDiffusion, TheSubstepsKeepTheSchemeStableAtAnySizeAndRate) {
  for (uint32_t n : {48u, 96u, 128u, 256u})
    for (float d : {0.5f, 30.0f, 200.0f})
      for (float frame : {1.0f / 240.0f, 1.0f / 60.0f, 1.0f / 15.0f}) {
        const float scaled = scaledDiffusion(d, n);
        const uint32_t steps = substepsFor(scaled, frame);
        EXPECT_LE(6.0f * scaled * frame / float(steps), kStabilityLimit + 1e-5f) << n << " " << d << " " << frame;
      }
  EXPECT_EQ(substepsFor(scaledDiffusion(30.0f, 96), 1.0f / 60.0f), 4u);
  // And it is stable: a checkerboard (the fastest mode) decays instead of growing.
  const uint32_t n = 16;
  std::vector<float> a(size_t(n) * n * n), b;
  for (size_t i = 0; i < a.size(); ++i) a[i] = ((i + i / n + i / (n * n)) % 2) ? 0.6f : 0.4f;
  DiffusionParams p;
  p.diffusion = 100.0f;
  p.dt = kStabilityLimit / (6.0f * p.diffusion);
  const auto peak = [](const std::vector<float>& v) { return *std::max_element(v.begin(), v.end()); };
  for (int i = 0; i < 50; ++i) diffuseLattice(a, b, n, p), std::swap(a, b);
  EXPECT_LE(peak(a), 0.6f);
}

TEST(BloomColour, PhasesFlipSharplyAtTheirThresholds) {
  EXPECT_EQ(phaseColour(0.0f), kPristine);
  EXPECT_EQ(phaseColour(0.30f), kAmber);
  EXPECT_EQ(phaseColour(0.50f), kRose);
  EXPECT_EQ(phaseColour(1.0f), kCrimson);
  // Within 0.03 of a threshold the colour is already (almost) the next one: a flip, not a fade.
  EXPECT_EQ(phaseColour(0.2301f), kAmber);
  EXPECT_EQ(phaseColour(0.1699f), kPristine);
}

TEST(BloomCursor, TheCentreOfTheViewPointsAtTheCrystal) {
  const CursorVapour centre = cursorVapour(cameraRay(0.5f, 0.5f, 16.0f / 9.0f));
  EXPECT_LT(centre.distance, 0.1f);
  const CursorVapour corner = cursorVapour(cameraRay(0.02f, 0.02f, 16.0f / 9.0f));
  EXPECT_GT(corner.distance, 1.3f * kCrystalRadius) << "a corner of the view is out of reach";
  EXPECT_EQ(worldToVoxel(glm::vec3(0.0f), 96), glm::vec3(48.0f));
  // Projection is the inverse of the camera ray: a point along a pixel's ray shows at that pixel.
  const Ray ray = cameraRay(0.3f, 0.7f, 1.5f);
  const glm::vec2 back = projectToView(ray.origin + ray.direction * 2.5f, 1.5f);
  EXPECT_NEAR(back.x, 0.3f, 1e-5f);
  EXPECT_NEAR(back.y, 0.7f, 1e-5f);
  EXPECT_EQ(worldToVoxel(glm::vec3(5.0f), 96), glm::vec3(96.0f)) << "clamped into the lattice";
}

TEST(BloomProxy, RisesAndVentsAtTheSeedsRates) {
  float v = 0.0f;
  for (int i = 0; i < 60; ++i) v = proxyStep(v, true, 1.0f / 60.0f);
  EXPECT_NEAR(v, 2.0f * (1.0f - std::exp(-0.1f)), 2e-3f) << "dV/dt = 0.2 - 0.1 V for one second";
  for (int i = 0; i < 600; ++i) v = proxyStep(v, false, 1.0f / 60.0f);
  EXPECT_LT(v, 0.19f * std::exp(-3.9f)) << "venting at 0.4/s for ten seconds";
}

TEST(BloomPhases, UpInOrderDownInReverseWithHysteresis) {
  PhaseDetector d;
  const std::array<Hysteresis, 4> bands{{{0.5f, 0.3f}, {0.5f, 0.3f}, {0.5f, 0.3f}, {0.5f, 0.3f}}};
  auto names = [](const std::vector<PhaseEvent>& events) {
    std::vector<std::string> out;
    for (const auto& e : events) out.push_back(std::string(e.name()) + (e.kind == PhaseEvent::Kind::Vent ? ":" + std::string(e.left()) : ""));
    return out;
  };
  EXPECT_TRUE(d.observe({0.49f, 0, 0, 0}, bands).empty());
  EXPECT_EQ(names(d.observe({0.5f, 0, 0, 0}, bands)), std::vector<std::string>{"amber"});
  // Noise around the threshold does not chatter: it must fall below 0.3 to vent.
  EXPECT_TRUE(d.observe({0.45f, 0, 0, 0}, bands).empty());
  EXPECT_TRUE(d.observe({0.51f, 0, 0, 0}, bands).empty());
  // A jump reports every phase passed, in order, and the climax last.
  EXPECT_EQ(names(d.observe({1, 1, 1, 0.6f}, bands)), (std::vector<std::string>{"rose", "crimson", "chroma"}));
  EXPECT_TRUE(d.climax());
  // Rose cannot vent before the climax and crimson have.
  EXPECT_TRUE(d.observe({1, 0.1f, 1, 0.4f}, bands).empty());
  EXPECT_EQ(names(d.observe({0, 0, 0, 0}, bands)),
            (std::vector<std::string>{"vent:chroma", "vent:crimson", "vent:rose", "vent:amber"}));
  EXPECT_EQ(d.phase(), Phase::Pristine);
}

TEST(BloomSettings, TheSchemaCoversThePanelTheIssueAsksFor) {
  for (const char* key : {"lattice", "diffusion", "decay_rising", "decay_venting", "source", "sigma", "phase_source",
                          "threshold_amber", "threshold_rose", "threshold_crimson", "threshold_chroma",
                          "trace_steps", "samples", "volume", "mute", "reverb_wet", "vent"})
    EXPECT_NE(schema().find(key), nullptr) << key;
  EXPECT_TRUE(schema().find("vent")->has(params::kTransient));
}

}  // namespace
}  // namespace vitrine::bloom
