// The noodles maths the shaders mirror: noise and its analytic gradient, the divergence-free
// fields (shared with neon, in src/maths/), the integrators, the frames, the node packing, the buffer
// plan, the camera.
#include "gpu/check.h"
#include "maths/flow_field.h"
#include "params/schema.h"
#include "scenes/noodles/camera.h"
#include "scenes/noodles/frames.h"
#include "scenes/noodles/integrate.h"
#include "scenes/noodles/packing.h"
#include "scenes/noodles/palette.h"
#include "scenes/noodles/settings.h"
#include "scenes/noodles/strand.h"
#include "scenes/noodles/strand_layout.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace vitrine::noodles {
namespace {

using maths::driftOffset, maths::FieldKind, maths::FieldSettings, maths::fieldAtTime, maths::flowVelocity,
    maths::gradientNoise, maths::kDriftRadius, maths::latticeGradient;

constexpr float kPi = std::numbers::pi_v<float>;

// Reproducible points in a box that straddles zero, so negative cells are exercised too.
std::vector<glm::vec3> randomPoints(size_t count, float extent, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> coordinate(-extent, extent);
  std::vector<glm::vec3> points(count);
  for (auto& p : points) p = {coordinate(rng), coordinate(rng), coordinate(rng)};
  return points;
}

// Central differences of f's three components: column i is d f / d x_i.
template <typename F>
glm::mat3 jacobian(const F& f, glm::vec3 p, float h) {
  glm::mat3 j;
  for (int i = 0; i < 3; ++i) {
    glm::vec3 step(0.0f);
    step[i] = h;
    j[i] = (f(p + step) - f(p - step)) / (2.0f * h);
  }
  return j;
}

float frobenius(const glm::mat3& m) {
  float sum = 0.0f;
  for (int c = 0; c < 3; ++c) sum += glm::dot(m[c], m[c]);
  return std::sqrt(sum);
}

// ------------------------------------------------------------------------------------------- noise

TEST(NoodlesNoise, AnalyticGradientMatchesFiniteDifferences) {
  // h = 2e-3: truncation error h^2 f'''/6 ~ 1e-4 and float rounding ~1e-7 / h ~ 5e-5, against
  // gradients of order 1; a wrong term in the derivative is off by O(1).
  constexpr float h = 2e-3f;
  for (const glm::vec3& p : randomPoints(2000, 40.0f, 1)) {
    const glm::vec3 analytic = gradientNoise(p).gradient;
    glm::vec3 numeric;
    for (int i = 0; i < 3; ++i) {
      glm::vec3 step(0.0f);
      step[i] = h;
      numeric[i] = (gradientNoise(p + step).value - gradientNoise(p - step).value) / (2.0f * h);
    }
    ASSERT_LT(glm::length(analytic - numeric), 2e-3f) << "at " << p.x << ", " << p.y << ", " << p.z;
  }
}

TEST(NoodlesNoise, SmoothAcrossNegativeCellFaces) {
  // Where the write-up's first version creased: the faces of cells with negative coordinates.
  for (float face : {-3.0f, -1.0f, 0.0f, 2.0f}) {
    const glm::vec3 below{face - 1e-4f, -2.3f, -0.7f}, above{face + 1e-4f, -2.3f, -0.7f};
    EXPECT_NEAR(gradientNoise(below).value, gradientNoise(above).value, 1e-3f) << face;
    EXPECT_LT(glm::length(gradientNoise(below).gradient - gradientNoise(above).gradient), 1e-2f) << face;
  }
}

TEST(NoodlesNoise, VanishesAtLatticePointsAndVaries) {
  EXPECT_EQ(gradientNoise({-4.0f, 7.0f, 0.0f}).value, 0.0f);  // gradient noise is zero on the lattice
  float lo = 0.0f, hi = 0.0f;
  for (const glm::vec3& p : randomPoints(2000, 50.0f, 2)) {
    lo = std::min(lo, gradientNoise(p).value);
    hi = std::max(hi, gradientNoise(p).value);
  }
  EXPECT_LT(lo, -0.3f);
  EXPECT_GT(hi, 0.3f);
}

TEST(NoodlesNoise, LatticeGradientsAreCentredAndExact) {
  glm::vec3 mean(0.0f);
  constexpr int n = 20000;
  for (uint32_t i = 0; i < n; ++i) {
    const glm::vec3 g = latticeGradient({i, i * 7u, 3u});
    ASSERT_TRUE(glm::all(glm::greaterThanEqual(g, glm::vec3(-1.0f))) && glm::all(glm::lessThan(g, glm::vec3(1.0f))));
    mean += g / float(n);
  }
  EXPECT_LT(glm::length(mean), 0.02f);
}

// ------------------------------------------------------------------------------------------- field

FieldSettings driftedField(FieldKind kind) { return fieldAtTime(kind, 0.5f, 0.0f, 3.7); }

// |div v| against the size of v's derivatives, at random points.
template <typename F>
float worstDivergenceRatio(const F& field, uint32_t seed) {
  float worst = 0.0f;
  for (const glm::vec3& p : randomPoints(500, 12.0f, seed)) {
    const glm::mat3 j = jacobian(field, p, 1e-3f);
    const float divergence = j[0][0] + j[1][1] + j[2][2];
    worst = std::max(worst, std::fabs(divergence) / (frobenius(j) + 1e-3f));
  }
  return worst;
}

TEST(NoodlesField, CurlNoiseIsDivergenceFree) {
  const FieldSettings s = driftedField(FieldKind::Curl);
  EXPECT_LT(worstDivergenceRatio([&](glm::vec3 p) { return flowVelocity(p, s); }, 3), 0.01f);
}

TEST(NoodlesField, BitangentNoiseIsDivergenceFree) {
  const FieldSettings s = driftedField(FieldKind::Bitangent);
  EXPECT_LT(worstDivergenceRatio([&](glm::vec3 p) { return flowVelocity(p, s); }, 4), 0.01f);
}

TEST(NoodlesField, DivergenceMeasureSeesAGradientField) {
  // The control: the noise gradient itself has divergence = its Laplacian, which the same measure
  // must flag, or the two tests above prove nothing.
  EXPECT_GT(worstDivergenceRatio([](glm::vec3 p) { return gradientNoise(p * 0.5f).gradient; }, 5), 0.3f);
}

TEST(NoodlesField, LiftAddsAUniformUpwardFlow) {
  FieldSettings s = driftedField(FieldKind::Curl);
  const glm::vec3 p{0.3f, -1.2f, 2.0f};
  const glm::vec3 still = flowVelocity(p, s);
  s.lift = 2.0f;
  EXPECT_EQ(flowVelocity(p, s), still + glm::vec3(0.0f, 0.0f, 2.0f));
}

TEST(NoodlesField, TimeMovesTheFieldAndTheDriftStaysBounded) {
  const glm::vec3 p{1.0f, 2.0f, -0.5f};
  EXPECT_GT(glm::length(flowVelocity(p, fieldAtTime(FieldKind::Curl, 0.5f, 0.0f, 0.0)) -
                        flowVelocity(p, fieldAtTime(FieldKind::Curl, 0.5f, 0.0f, 0.5))),
            1e-2f);
  // Starts along +y like the write-up's drift, at one noise unit per unit of time...
  const glm::vec3 early = driftOffset(1e-3);
  EXPECT_NEAR(early.y, 1e-3f, 1e-6f);
  EXPECT_NEAR(early.x, 0.0f, 1e-6f);
  // ...and after a day of drifting is still within the circle.
  for (double t : {1e3, 86400.0, 1e7}) EXPECT_LE(glm::length(driftOffset(t)), 2.0f * float(kDriftRadius) + 1e-3f);
}

// ------------------------------------------------------------------------------------- integration

// Rigid rotation about z: every streamline is a circle, travelled at speed |p| in raw mode.
glm::vec3 rotationField(glm::vec3 p) { return {-p.y, p.x, 0.0f}; }

glm::vec3 follow(glm::vec3 p, int steps, float h, Integrator integrator, TangentMode mode) {
  for (int i = 0; i < steps; ++i) p = advance(p, travel(rotationField(p), mode), h, integrator, mode, rotationField);
  return p;
}

TEST(NoodlesIntegrate, Rk4FollowsCirclesFarBetterThanEuler) {
  constexpr float h = 0.05f;
  constexpr int steps = 200;  // t = 10: more than one and a half turns
  const glm::vec3 exact{std::cos(10.0f), std::sin(10.0f), 0.0f};
  const float euler = glm::length(follow({1, 0, 0}, steps, h, Integrator::Euler, TangentMode::Raw) - exact);
  const float rk4 = glm::length(follow({1, 0, 0}, steps, h, Integrator::Rk4, TangentMode::Raw) - exact);
  EXPECT_GT(euler, 0.1f);  // Euler spirals outwards by (1 + h^2)^(1/2) a step
  EXPECT_LT(rk4, 1e-4f);
  EXPECT_LT(rk4 * 1000.0f, euler);
}

TEST(NoodlesIntegrate, NormalizedTangentWalksAtUnitSpeed) {
  // On the circle of radius 2 the raw field moves at speed 2; the normalised one at 1, so after
  // arc length s the angle is s / 2.
  constexpr float h = 0.01f;
  const glm::vec3 end = follow({2, 0, 0}, 300, h, Integrator::Rk4, TangentMode::Normalized);
  EXPECT_NEAR(std::atan2(end.y, end.x), 3.0f / 2.0f, 1e-4f);
  EXPECT_NEAR(glm::length(end), 2.0f, 1e-4f);
}

TEST(NoodlesIntegrate, NormalizedStrandsHaveEqualSegmentsAndRawOnesDoNot) {
  StrandSettings s;
  s.grid = {3, 3, 1};
  s.segments = 40;
  s.field = driftedField(FieldKind::Curl);
  std::vector<PackedNode> nodes(s.segments + 1);
  for (TangentMode mode : {TangentMode::Normalized, TangentMode::Raw}) {
    s.tangent = mode;
    integrateStrand(s, 4, nodes);
    EXPECT_EQ(nodePosition(nodes[0]), strandStart(s, 4));
    float shortest = 1e9f, longest = 0.0f;
    for (uint32_t k = 0; k < s.segments; ++k) {
      const float length = glm::length(nodePosition(nodes[k + 1]) - nodePosition(nodes[k]));
      shortest = std::min(shortest, length), longest = std::max(longest, length);
    }
    if (mode == TangentMode::Normalized) {
      EXPECT_NEAR(shortest, s.step, 1e-5f);
      EXPECT_NEAR(longest, s.step, 1e-5f);
    } else {
      EXPECT_GT(longest - shortest, 0.1f * s.step);
    }
  }
}

TEST(NoodlesIntegrate, StrandStartsFormACentredGrid) {
  StrandSettings s;
  s.grid = {4, 3, 2};
  s.spacing = 0.5f;
  EXPECT_EQ(strandStart(s, 0), glm::vec3(-0.75f, -0.5f, -0.25f));
  EXPECT_EQ(strandStart(s, 4 * 3 * 2 - 1), glm::vec3(0.75f, 0.5f, 0.25f));
  EXPECT_EQ(strandStart(s, 5), glm::vec3(-0.25f, 0.0f, -0.25f));  // x = 1, y = 1, z = 0
}

// ------------------------------------------------------------------------------------------ frames

struct Helix {
  float radius, turnRate, climb;  // r(s) = (R cos ws, R sin ws, c s)
  glm::vec3 point(float s) const { return {radius * std::cos(turnRate * s), radius * std::sin(turnRate * s), climb * s}; }
  glm::vec3 tangent(float s) const {
    return glm::normalize(glm::vec3(-radius * turnRate * std::sin(turnRate * s), radius * turnRate * std::cos(turnRate * s), climb));
  }
};

// Rotates v by the smallest rotation taking unit a onto unit b (Rodrigues).
glm::vec3 rotateOnto(glm::vec3 v, glm::vec3 a, glm::vec3 b) {
  const glm::vec3 axis = glm::cross(a, b);
  const float c = glm::dot(a, b);
  return v * c + glm::cross(axis, v) + axis * (glm::dot(axis, v) / (1.0f + c));
}

// How far the frame spins about the strand from one node to the next: the angle between the new
// normal and the old one carried over by the smallest rotation of the tangent.
float twist(const Frame& from, const Frame& to) {
  const glm::vec3 carried = rotateOnto(from.normal, from.tangent, to.tangent);
  return std::atan2(glm::dot(glm::cross(carried, to.normal), to.tangent), glm::dot(carried, to.normal));
}

std::vector<Frame> helixFrames(const Helix& helix, FrameMethod method, int steps, float ds) {
  std::vector<Frame> frames{upVectorFrame(helix.tangent(0.0f))};
  for (int i = 1; i <= steps; ++i) {
    const float s = float(i) * ds;
    frames.push_back(method == FrameMethod::Up
                         ? upVectorFrame(helix.tangent(s))
                         : transportFrame(frames.back(), helix.point(s - ds), helix.point(s), helix.tangent(s)));
  }
  return frames;
}

void expectOrthonormal(const Frame& f, float tolerance) {
  EXPECT_NEAR(glm::length(f.normal), 1.0f, tolerance);
  EXPECT_NEAR(glm::length(f.binormal), 1.0f, tolerance);
  EXPECT_NEAR(glm::length(f.tangent), 1.0f, tolerance);
  EXPECT_NEAR(glm::dot(f.normal, f.binormal), 0.0f, tolerance);
  EXPECT_NEAR(glm::dot(f.normal, f.tangent), 0.0f, tolerance);
  EXPECT_NEAR(glm::dot(f.binormal, f.tangent), 0.0f, tolerance);
  EXPECT_GT(glm::dot(glm::cross(f.normal, f.binormal), f.tangent), 0.0f);  // right-handed
}

TEST(NoodlesFrames, RotationMinimisingFramesStayOrthonormalAndTwistFarLess) {
  // A steep helix, like a strand with lift: near-vertical tangent circling the up axis, where the
  // up-vector frame spins once per turn.
  const Helix helix{0.15f, 2.0f * kPi, 1.0f};
  constexpr int steps = 3000;
  const float ds = 3.0f / steps;  // three turns
  const auto rmf = helixFrames(helix, FrameMethod::RotationMinimizing, steps, ds);
  const auto up = helixFrames(helix, FrameMethod::Up, steps, ds);
  float rmfTwist = 0.0f, upTwist = 0.0f;
  for (int i = 0; i < steps; ++i) {
    rmfTwist += std::fabs(twist(rmf[i], rmf[i + 1]));
    upTwist += std::fabs(twist(up[i], up[i + 1]));
  }
  for (const Frame& f : rmf) expectOrthonormal(f, 1e-5f);
  // The up-vector frame turns with the helix: about 2 pi * turns * cos(slope) in all.
  const float slope = std::atan2(helix.radius * helix.turnRate, helix.climb);
  EXPECT_NEAR(upTwist, 3.0f * 2.0f * kPi * std::cos(slope), 0.05f);
  EXPECT_LT(rmfTwist, 0.01f);
  EXPECT_LT(rmfTwist * 100.0f, upTwist);
}

TEST(NoodlesFrames, UpVectorFrameSurvivesAVerticalTangent) {
  expectOrthonormal(upVectorFrame({0.0f, 0.0f, 1.0f}), 1e-6f);
  expectOrthonormal(upVectorFrame({0.0f, 0.0f, -1.0f}), 1e-6f);
  expectOrthonormal(upVectorFrame(glm::normalize(glm::vec3(0.3f, -0.2f, 0.9f))), 1e-6f);
}

TEST(NoodlesFrames, TransportHandlesAZeroLengthStep) {
  const Frame from = upVectorFrame(glm::normalize(glm::vec3(1.0f, 0.2f, 0.1f)));
  const glm::vec3 p{1.0f, 2.0f, 3.0f};
  const Frame same = transportFrame(from, p, p, from.tangent);
  EXPECT_LT(glm::length(same.normal - from.normal), 1e-6f);
  expectOrthonormal(transportFrame(from, p, p, glm::normalize(glm::vec3(0.0f, 1.0f, 0.3f))), 1e-5f);
}

TEST(NoodlesFrames, QuaternionRoundTripCoversEveryBranch) {
  // Half turns about x, y and z make the trace negative and pick each of Shepperd's other branches.
  const std::vector<glm::mat3> rotations = {
      glm::mat3(1.0f),
      glm::mat3(glm::rotate(glm::mat4(1.0f), 3.0f, glm::vec3(1, 0, 0))),
      glm::mat3(glm::rotate(glm::mat4(1.0f), 3.0f, glm::vec3(0, 1, 0))),
      glm::mat3(glm::rotate(glm::mat4(1.0f), 3.0f, glm::vec3(0, 0, 1))),
      glm::mat3(glm::rotate(glm::mat4(1.0f), 1.1f, glm::normalize(glm::vec3(1, -2, 0.5f))))};
  for (const glm::mat3& m : rotations) {
    const Frame f{m[0], m[1], m[2]};
    const glm::vec4 q = frameToQuaternion(f);
    EXPECT_NEAR(glm::length(q), 1.0f, 1e-5f);
    const Frame back = quaternionToFrame(q);
    EXPECT_LT(glm::length(back.normal - f.normal), 1e-5f);
    EXPECT_LT(glm::length(back.binormal - f.binormal), 1e-5f);
    EXPECT_LT(glm::length(back.tangent - f.tangent), 1e-5f);
  }
}

// ----------------------------------------------------------------------------------------- packing

TEST(NoodlesPacking, NodesRoundTrip) {
  std::mt19937 rng(7);
  std::normal_distribution<float> gauss;
  float worstAngle = 0.0f;
  for (int i = 0; i < 5000; ++i) {
    const glm::vec4 q = glm::normalize(glm::vec4(gauss(rng), gauss(rng), gauss(rng), gauss(rng)));
    const Frame frame = quaternionToFrame(q);
    const glm::vec3 position{gauss(rng) * 30.0f, gauss(rng) * 1e-3f, -gauss(rng) * 1e4f};
    const PackedNode node = packNode(position, frame);
    ASSERT_EQ(nodePosition(node), position);  // bit for bit
    const Frame back = nodeFrame(node);
    for (const auto& [a, b] : {std::pair{frame.normal, back.normal}, {frame.binormal, back.binormal},
                               {frame.tangent, back.tangent}})
      worstAngle = std::max(worstAngle, std::acos(std::clamp(glm::dot(a, b), -1.0f, 1.0f)));
    ASSERT_EQ(packQuaternion(q), packQuaternion(-q));  // one code per rotation
  }
  EXPECT_LT(worstAngle, 0.2f * kPi / 180.0f);  // the bound docs/NOODLES.md quotes
  EXPECT_GT(worstAngle, 0.0f);                 // it is lossy: the test would notice a float store
}

TEST(NoodlesPacking, SegmentCostsAtMostThirtyTwoBytes) {
  for (uint32_t segments : {1u, 2u, 8u, 64u, 4096u})
    EXPECT_LE(double(kNodeBytes) * (segments + 1) / segments, 32.0) << segments;
}

TEST(NoodlesPacking, NodesFillTheirChunkOnceInBlocksOfThirtyTwoStrands) {
  // 100 strands: three blocks of 32 and a last one of 4, each node-major.
  constexpr uint32_t strands = 100, nodes = 5;
  EXPECT_EQ(nodeSlot(strands, nodes, 7, 3), 3u * 32u + 7u);
  EXPECT_EQ(nodeSlot(strands, nodes, 40, 2), 32u * nodes + 2u * 32u + 8u);
  EXPECT_EQ(nodeSlot(strands, nodes, 97, 4), 96u * nodes + 4u * 4u + 1u);
  std::vector<int> seen(strands * nodes, 0);
  for (uint32_t local = 0; local < strands; ++local)
    for (uint32_t node = 0; node < nodes; ++node) {
      const uint64_t slot = nodeSlot(strands, nodes, local, node);
      ASSERT_LT(slot, seen.size());
      ++seen[slot];
    }
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), ptrdiff_t(seen.size()));  // every slot once
}

// --------------------------------------------------------------------------------------- the plan

// integrate.comp's and raster.comp's local sizes today; the plan takes whatever the shaders declare.
constexpr StrandWorkgroups kWorkgroups{.integrate = 64, .raster = 64};

DeviceBudget lavapipeLikeBudget() {
  DeviceBudget b;
  b.deviceName = "test device";
  b.maxStorageBufferRange = 128ull << 20;
  b.storageOffsetAlignment = 64;
  b.maxBufferSize = 2ull << 30;
  b.deviceLocalHeap = 2ull << 30;
  b.maxGroupCountX = b.maxGroupCountY = 65535;
  return b;
}

TEST(NoodlesLayout, TenMillionSegmentsSplitIntoAlignedChunks) {
  const DeviceBudget budget = lavapipeLikeBudget();
  const StrandLayout layout = planStrands({50, 50, 50}, 80, budget, kWorkgroups);
  EXPECT_EQ(layout.segmentCount, 10'000'000u);
  EXPECT_EQ(layout.bytes, 125000ull * 81 * 16);
  ASSERT_GT(layout.chunks.size(), 1u);
  uint64_t strands = 0;
  for (const StrandChunk& chunk : layout.chunks) {
    EXPECT_EQ(chunk.firstStrand, strands);
    EXPECT_EQ(chunk.offset, strands * layout.strandBytes);
    EXPECT_EQ(chunk.offset % budget.storageOffsetAlignment, 0u);
    EXPECT_LE(chunk.bytes, budget.maxStorageBufferRange);
    EXPECT_GE(uint64_t(chunk.integrateGroups.x) * chunk.integrateGroups.y * kWorkgroups.integrate, chunk.strandCount);
    EXPECT_GE(uint64_t(chunk.rasterGroups.x) * chunk.rasterGroups.y * kWorkgroups.raster,
              uint64_t(chunk.strandCount) * layout.segments);
    EXPECT_LE(chunk.rasterGroups.x, budget.maxGroupCountX);
    strands += chunk.strandCount;
  }
  EXPECT_EQ(strands, layout.strands);
}

TEST(NoodlesLayout, OneChunkWhenTheRangeAllows) {
  DeviceBudget budget = lavapipeLikeBudget();
  budget.maxStorageBufferRange = 0xffffffffull;
  EXPECT_EQ(planStrands({16, 16, 16}, 64, budget, kWorkgroups).chunks.size(), 1u);
}

TEST(NoodlesLayout, RefusesWhatTheDeviceCannotHoldWithAReason) {
  const DeviceBudget budget = lavapipeLikeBudget();
  const auto message = [&](glm::uvec3 grid, uint32_t segments) {
    try {
      planStrands(grid, segments, budget, kWorkgroups);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message({400, 400, 400}, 64).find("at most"), std::string::npos);           // > int32 instances
  EXPECT_NE(message({300, 300, 10}, 200).find("allows one buffer"), std::string::npos);  // > maxBufferSize
  EXPECT_NE(message({200, 200, 44}, 64).find("device memory"), std::string::npos);       // > 3/4 of the heap
  DeviceBudget narrow = budget;
  narrow.maxStorageBufferRange = 1024;
  EXPECT_THROW(planStrands({2, 2, 2}, 100, narrow, kWorkgroups), Error);  // one strand exceeds a binding
  EXPECT_EQ(message({16, 16, 16}, 64), "accepted");
}

// -------------------------------------------------------------------------------------- parameters

TEST(NoodlesSettings, GridForms) {
  glm::uvec3 grid;
  std::string error;
  ASSERT_TRUE(parseGrid("16", grid, &error));
  EXPECT_EQ(grid, glm::uvec3(16));
  ASSERT_TRUE(parseGrid("64x32", grid, &error));
  EXPECT_EQ(grid, glm::uvec3(64, 32, 1));
  ASSERT_TRUE(parseGrid("3x4x5", grid, &error));
  EXPECT_EQ(grid, glm::uvec3(3, 4, 5));
  for (const char* bad : {"", "0", "4x", "x4", "1x2x3x4", "-3", "5000", "4y4"}) EXPECT_FALSE(parseGrid(bad, grid, &error)) << bad;
}

TEST(NoodlesSettings, EveryNamedParameterParsesThroughTheSchema) {
  NoodleSettings s;
  const params::Bound bound{&schema(), &s};
  EXPECT_EQ(params::applyValues(bound, {{"frames", "up"}, {"integrator", "rk4"}, {"msaa", "off"}}), "");
  EXPECT_EQ(s.frames, FrameMethod::Up);
  EXPECT_EQ(s.integrator, Integrator::Rk4);
  EXPECT_FALSE(s.msaa);
  EXPECT_NE(params::applyValues(bound, {{"field", "gradient"}}).find("curl"), std::string::npos);
  EXPECT_NE(params::applyValues(bound, {{"step", "2"}}), "");
  EXPECT_NE(params::applyValues(bound, {{"nonsense", "1"}}), "");
  EXPECT_EQ(params::applyValues(bound, {{"grid", "32x16"}}), "");
  EXPECT_EQ(s.grid, glm::uvec3(32, 16, 1));
  EXPECT_EQ(schema().find("grid")->format(&s), "32x16x1");
  // Every key of the old command line is still there, so scripts and goldens keep working.
  for (const char* key : {"grid", "segments", "step", "noise_scale", "spacing", "radius", "speed", "lift", "field",
                          "integrator", "tangent", "frames", "colour", "stripe", "msaa", "orbit"})
    EXPECT_NE(schema().find(key), nullptr) << key;
}

// The memory check spans grid and segments: it judges the final pair once, so the order of --set
// (or of a preset's values) never decides whether a change is accepted.
TEST(NoodlesSettings, TheMemoryCheckJudgesFinalValuesWhateverTheOrder) {
  const DeviceBudget budget = lavapipeLikeBudget();
  NoodleSettings s;
  const params::Bound bound{&schema(), &s};
  const params::Check fits = [&] {
    try {
      planStrands(s.grid, uint32_t(s.segments), budget, kWorkgroups);
      return std::string();
    } catch (const Error& e) {
      return std::string(e.what());
    }
  };
  EXPECT_NE(params::applyValues(bound, {{"grid", "4096x4096"}}, fits), "") << "16.7M strands of 64 segments";
  EXPECT_EQ(s.grid, glm::uvec3(16)) << "a refused change leaves every value as it was";
  EXPECT_EQ(params::applyValues(bound, {{"grid", "4096x4096"}, {"segments", "4"}}, fits), "");
  s = {};
  EXPECT_EQ(params::applyValues(bound, {{"segments", "4"}, {"grid", "4096x4096"}}, fits), "");
  EXPECT_EQ(s.grid, glm::uvec3(4096, 4096, 1));
  EXPECT_EQ(s.segments, 4);
}

TEST(NoodlesSettings, OrbitPinsAndUnpins) {
  OrbitPin orbit;
  std::string error;
  EXPECT_TRUE(parseOrbit("0.5,-0.2,3", orbit, &error));
  EXPECT_TRUE(orbit.pinned);
  EXPECT_FLOAT_EQ(orbit.distance, 3.0f);
  EXPECT_EQ(formatOrbit(orbit), "0.5,-0.2,3");
  EXPECT_FALSE(parseOrbit("0.5,-0.2", orbit, &error));
  EXPECT_FALSE(parseOrbit("0.5,1.6,3", orbit, &error)) << "elevation beyond the look-at limit";
  EXPECT_FALSE(parseOrbit("0.5,0.2,0", orbit, &error)) << "distance must be positive";
  EXPECT_FALSE(parseOrbit("nan,0.2,1", orbit, &error));
  EXPECT_TRUE(parseOrbit("off", orbit, &error));
  EXPECT_FALSE(orbit.pinned);
  EXPECT_EQ(schema().find("orbit")->defaultText, "off");
  EXPECT_TRUE(schema().find("orbit")->has(params::kTransient)) << "a pinned camera is not saved";
}

// ------------------------------------------------------------------------------- camera and colour

TEST(NoodlesCamera, InfiniteReverseZ) {
  const glm::mat4 projection = reverseZPerspective(0.7f, 16.0f / 9.0f, 0.25f);
  const auto depthAt = [&](float distance) {
    const glm::vec4 clip = projection * glm::vec4(0.0f, 0.0f, -distance, 1.0f);
    EXPECT_GT(clip.w, 0.0f);
    return clip.z / clip.w;
  };
  EXPECT_NEAR(depthAt(0.25f), 1.0f, 1e-6f);  // the near plane is depth 1
  EXPECT_GT(depthAt(1.0f), depthAt(2.0f));   // nearer is greater: compare op GREATER
  EXPECT_GT(depthAt(1e7f), 0.0f);            // no far plane
  EXPECT_LT(depthAt(1e7f), 1e-6f);
  // World z up lands at the top of a Vulkan framebuffer (negative clip y).
  const glm::vec4 above = projection * lookAtZUp({5, 0, 0}, {0, 0, 0}) * glm::vec4(0, 0, 1, 1);
  EXPECT_LT(above.y, 0.0f);
}

TEST(NoodlesCamera, LookAtMatchesGlm) {
  const glm::vec3 eye{3.0f, -2.0f, 1.5f}, target{0.2f, 0.1f, -0.3f};
  const glm::mat4 ours = lookAtZUp(eye, target), theirs = glm::lookAtRH(eye, target, glm::vec3(0, 0, 1));
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(ours[c][r], theirs[c][r], 1e-5f);
}

TEST(NoodlesCamera, FlightGoesInAndOutButNeverOntoTheTarget) {
  constexpr float nest = 4.0f;
  float nearest = 1e9f, farthest = 0.0f;
  for (double t = 0.0; t < 600.0; t += 0.25) {
    const CameraPose pose = lissajousPose(t, nest);
    const float distance = glm::length(pose.eye);
    nearest = std::min(nearest, distance), farthest = std::max(farthest, distance);
    ASSERT_GT(glm::length(pose.eye - pose.target), 0.2f * nest) << t;
    const glm::vec3 view = glm::normalize(pose.target - pose.eye);
    ASSERT_LT(std::fabs(view.z), 0.95f) << t;  // never looking straight up or down
  }
  EXPECT_LT(nearest, 0.5f * nest);  // inside the nest
  EXPECT_GT(farthest, 2.4f * nest); // and well outside it
}

TEST(NoodlesCamera, OrbitStartsWhereTheFlightIs) {
  const glm::vec3 centre{0.0f, 0.0f, 1.0f};
  CameraPose flight = lissajousPose(12.0, 3.0f);
  flight.eye += centre;
  const CameraPose orbit = orbitPose(orbitThrough(flight, centre), centre);
  EXPECT_LT(glm::length(orbit.eye - flight.eye), 1e-4f);
}

TEST(NoodlesPalette, HsvPrimariesAndGradientEnds) {
  EXPECT_LT(glm::length(hsvToRgb({0.0f, 1.0f, 1.0f}) - glm::vec3(1, 0, 0)), 1e-6f);
  EXPECT_LT(glm::length(hsvToRgb({1.0f / 3.0f, 1.0f, 1.0f}) - glm::vec3(0, 1, 0)), 1e-5f);
  EXPECT_LT(glm::length(hsvToRgb({2.0f / 3.0f, 1.0f, 0.5f}) - glm::vec3(0, 0, 0.5f)), 1e-5f);
  EXPECT_EQ(hsvToRgb({0.3f, 0.0f, 0.8f}), glm::vec3(0.8f));
  EXPECT_EQ(strandColour(0, 100, Colouring::Gradient), kGradientFirst);
  EXPECT_EQ(strandColour(99, 100, Colouring::Gradient), kGradientLast);
  EXPECT_NE(strandColour(10, 100, Colouring::Hsv), strandColour(60, 100, Colouring::Hsv));
}

// Saturation as HSV has it: 0 for a grey, 1 for a pure hue.
float saturation(glm::vec3 c) {
  const float hi = std::max(c.r, std::max(c.g, c.b)), lo = std::min(c.r, std::min(c.g, c.b));
  return hi > 0.0f ? (hi - lo) / hi : 0.0f;
}

TEST(NoodlesPalette, GreyRunsFromGreyToWhiteByIndex) {
  constexpr uint32_t kStrands = 1024;
  EXPECT_EQ(strandColour(0, kStrands, Colouring::Grey), glm::vec3(kGreyFirst));
  EXPECT_EQ(strandColour(kStrands - 1, kStrands, Colouring::Grey), glm::vec3(1.0f));
  EXPECT_GT(kGreyFirst, 0.05f) << "the first strand must stay visible on the near-black background";
  float previous = -1.0f;
  for (uint32_t i = 0; i < kStrands; ++i) {
    const glm::vec3 c = strandColour(i, kStrands, Colouring::Grey);
    ASSERT_EQ(saturation(c), 0.0f) << "strand " << i;
    ASSERT_GT(c.g, previous) << "strand " << i << ": brighter by index";
    previous = c.g;
  }
  EXPECT_GT(saturation(strandColour(0, kStrands, Colouring::Gradient)), 0.5f);  // the default's blue is no grey
}

// The seed preset is the write-up's final look: grey strands by index, every seed on one flat sheet
// (the write-up's (x, 0, y): a vertical sheet in this z-up world), whatever was set before it.
TEST(NoodlesPresets, SeedIsGreyStrandsFromAFlatSheet) {
  NoodleSettings settings;
  settings.grid = {8, 8, 8};
  settings.colour = Colouring::Hsv;
  ASSERT_EQ(params::applyPreset(params::bindSettings(schema(), settings), "seed"), "");
  EXPECT_EQ(settings.colour, Colouring::Grey);
  StrandSettings strands;
  strands.grid = settings.grid;
  strands.spacing = settings.spacing;
  const uint32_t count = settings.grid.x * settings.grid.y * settings.grid.z;
  ASSERT_GE(count, 256u);
  glm::vec3 lo{1e9f}, hi{-1e9f};
  for (uint32_t i = 0; i < count; ++i) {
    const glm::vec3 p = strandStart(strands, i);
    lo = glm::min(lo, p), hi = glm::max(hi, p);
  }
  EXPECT_EQ(lo.y, hi.y) << "every seed on one plane";
  EXPECT_GT(hi.x - lo.x, 4.0f * settings.spacing);
  EXPECT_GT(hi.z - lo.z, 4.0f * settings.spacing) << "a sheet, not a row";
}

// ------------------------------------------------------------------------------ the baked flow

StrandSettings nestOf(glm::uvec3 grid, uint32_t segments) {
  StrandSettings s;
  s.grid = grid;
  s.segments = segments;
  s.field = fieldAtTime(FieldKind::Curl, 0.5f, 0.0f, 3.0);
  return s;
}

// Auto keeps the exact field where it is cheap (the default nest, RK4 too, and 10^6 segments) and
// bakes the big nests the bake was made for; Exact and Baked are obeyed.
TEST(NoodlesBake, AutoBakesOnlyBigNests) {
  StrandSettings s = nestOf(glm::uvec3(16), 64);
  EXPECT_FALSE(planFieldBake(s, FieldSource::Auto).baked()) << "the default nest";
  s.integrator = Integrator::Rk4;
  EXPECT_FALSE(planFieldBake(s, FieldSource::Auto).baked()) << "the default nest, RK4";
  EXPECT_TRUE(planFieldBake(s, FieldSource::Baked).baked());
  EXPECT_FALSE(planFieldBake(nestOf(glm::uvec3(25), 64), FieldSource::Auto).baked()) << "10^6";
  EXPECT_TRUE(planFieldBake(nestOf(glm::uvec3(50), 80), FieldSource::Auto).baked()) << "10^7";
  const FieldBake big = planFieldBake(nestOf(glm::uvec3(100), 100), FieldSource::Auto);
  ASSERT_TRUE(big.baked()) << "10^8";
  EXPECT_FALSE(planFieldBake(nestOf(glm::uvec3(100), 100), FieldSource::Exact).baked());
  // Eight texels a noise unit at noise scale 0.5: a quarter of a world unit; 10^8's nest is ~40 across.
  EXPECT_FLOAT_EQ(big.spacing, 0.25f);
  EXPECT_EQ(big.texels, glm::uvec3(160));
}

// The volume reaches a strand's length beyond every seed (and the lift's climb, for raw strands), and
// a forced bake of a box too big for the texel budget coarsens instead of growing past it.
TEST(NoodlesBake, TheVolumeCoversTheSeedsAndAStrandsReach) {
  StrandSettings s = nestOf(glm::uvec3(8, 6, 4), 40);
  s.field.lift = 2.0f;
  const FieldBake bake = planFieldBake(s, FieldSource::Baked);
  const float reach = float(s.segments) * s.step;
  for (uint32_t strand = 0; strand < 8 * 6 * 4; ++strand) {
    const glm::vec3 seed = strandStart(s, strand);
    for (const glm::vec3 offset : {glm::vec3(reach, reach, reach), glm::vec3(-reach, -reach, -reach),
                                   glm::vec3(0.0f, 0.0f, reach * (1.0f + s.field.lift))})
      EXPECT_TRUE(insideBake(bake, seed + offset * 0.999f)) << strand;
  }
  EXPECT_FALSE(insideBake(bake, strandStart(s, 0) - glm::vec3(reach * 1.1f)));
  const FieldBake huge = planFieldBake(nestOf(glm::uvec3(100, 100, 10), 1000), FieldSource::Baked);
  ASSERT_TRUE(huge.baked());
  EXPECT_LE(huge.count(), kBakeMostTexels);
  EXPECT_GT(huge.spacing, 0.25f);
  EXPECT_FALSE(planFieldBake(nestOf(glm::uvec3(100, 100, 10), 1000), FieldSource::Auto).baked())
      << "auto does not coarsen: it takes the exact field";
}

TEST(NoodlesBake, ComponentsKeepTenBitsOverTheRangeAndClampBeyond) {
  for (const float v : {-3.9f, -1.0f, -0.01f, 0.0f, 0.3f, 1.1f, 3.6f})
    EXPECT_NEAR(bakedComponent(v), v, kBakeRange / 1023.0f) << v;
  EXPECT_FLOAT_EQ(bakedComponent(9.0f), kBakeRange);
  EXPECT_FLOAT_EQ(bakedComponent(-9.0f), -kBakeRange);
}

// What the bake trades: the baked curl field is within ~5 % (rms) of the exact one at the planned
// spacing (measured 4.9 %), so strands follow the same swirls; a volume off by half a texel or a
// spacing twice as coarse fails this.
TEST(NoodlesBake, TheBakedFlowIsWithinFivePercentOfTheExactOne) {
  StrandSettings s = nestOf(glm::uvec3(20), 60);
  s.bake = planFieldBake(s, FieldSource::Baked);
  const std::vector<glm::vec3> texels = bakeField(s.bake, s.field);
  ASSERT_EQ(texels.size(), s.bake.count());
  double error = 0.0, speed = 0.0;
  for (const glm::vec3 p : randomPoints(20000, 5.0f, 11)) {
    ASSERT_TRUE(insideBake(s.bake, p));
    const glm::vec3 exact = flowVelocity(p, s.field), baked = strandVelocity(s, texels, p);
    error += glm::dot(baked - exact, baked - exact);
    speed += glm::dot(exact, exact);
  }
  const double relative = std::sqrt(error / speed);
  EXPECT_LT(relative, 0.055);
  EXPECT_GT(relative, 0.01) << "a bake this close would be worth making coarser";
  RecordProperty("rms_relative_error", std::to_string(relative));
  // At texel centres the sample is the texel, which is the exact flow to the storage's 10 bits.
  const glm::vec3 centre = s.bake.origin + glm::vec3(7, 9, 11) * s.bake.spacing;
  const glm::vec3 exact = flowVelocity(centre, s.field);
  for (int axis = 0; axis < 3; ++axis)
    EXPECT_NEAR(sampleBake(s.bake, texels, centre)[axis], exact[axis], kBakeRange / 1023.0f);
}

// The lift is added after sampling (the volume holds the noise alone), and outside the volume a strand
// takes the exact field.
TEST(NoodlesBake, LiftIsAddedAndOutsideIsExact) {
  StrandSettings s = nestOf(glm::uvec3(6), 20);
  s.field.lift = 1.5f;
  s.bake = planFieldBake(s, FieldSource::Baked);
  const std::vector<glm::vec3> texels = bakeField(s.bake, s.field);
  const glm::vec3 inside{0.3f, -0.2f, 0.1f};
  EXPECT_NEAR(strandVelocity(s, texels, inside).z - sampleBake(s.bake, texels, inside).z, 1.5f, 1e-6f);
  EXPECT_NEAR(strandVelocity(s, texels, inside).z, flowVelocity(inside, s.field).z, 0.3f);
  const glm::vec3 outside{40.0f, 0.0f, 0.0f};
  EXPECT_EQ(strandVelocity(s, texels, outside), flowVelocity(outside, s.field));
}

// Strands in the baked flow stay near their exact twins: over 60 steps (a strand 3 units long) their
// ends part by about a twentieth of their length on average (measured 5.6 %); they do part, since
// nearby streamlines of a swirling flow diverge.
TEST(NoodlesBake, BakedStrandsStayNearTheirExactTwins) {
  StrandSettings exact = nestOf(glm::uvec3(10), 60);
  StrandSettings baked = exact;
  baked.bake = planFieldBake(baked, FieldSource::Baked);
  const std::vector<glm::vec3> texels = bakeField(baked.bake, baked.field);
  std::vector<PackedNode> a(exact.segments + 1), b(exact.segments + 1);
  double parted = 0.0;
  const uint32_t strands = 10 * 10 * 10;
  for (uint32_t strand = 0; strand < strands; ++strand) {
    integrateStrand(exact, strand, a);
    integrateStrand(baked, strand, b, texels);
    parted += glm::length(nodePosition(a.back()) - nodePosition(b.back()));
  }
  const double meanParted = parted / strands, length = double(exact.segments) * exact.step;
  EXPECT_LT(meanParted, 0.08 * length);
  EXPECT_GT(meanParted, 0.0) << "the baked strands followed the exact field";
  RecordProperty("mean_parting_over_length", std::to_string(meanParted / length));
}

}  // namespace
}  // namespace vitrine::noodles
