#include "gpu/drm_modifiers.h"

#include <gtest/gtest.h>

#include <array>

namespace vitrine::gpu::drm {
namespace {

constexpr uint64_t kNvidiaBlock = 0x0300000000606015ULL;  // an NVIDIA block-linear layout
constexpr uint64_t kCompressed = 0x0300000000e08015ULL;   // one with two memory planes, for the test

const std::array<DriverModifier, 3> kDriver{{{kLinear, 1}, {kNvidiaBlock, 1}, {kCompressed, 2}}};

TEST(DrmModifiers, AcceptableKeepsTheConsumersOrderAndDropsWhatTheDriverLacks) {
  const std::array<uint64_t, 4> consumer{kNvidiaBlock, 0x0100000000000001ULL, kLinear, kNvidiaBlock};
  EXPECT_EQ(acceptable(kDriver, consumer), (std::vector<uint64_t>{kNvidiaBlock, kLinear}));
}

TEST(DrmModifiers, ImplicitModifierIsNeverChosen) {
  const std::array<uint64_t, 2> consumer{kInvalid, kLinear};
  EXPECT_EQ(choose(kDriver, consumer), kLinear);
  const std::array<uint64_t, 1> onlyImplicit{kInvalid};
  EXPECT_EQ(choose(kDriver, onlyImplicit), std::nullopt);
}

TEST(DrmModifiers, NothingInCommonChoosesNothing) {
  const std::array<uint64_t, 1> intel{0x0100000000000001ULL};
  EXPECT_EQ(choose(kDriver, intel), std::nullopt);
  EXPECT_EQ(choose({}, std::array<uint64_t, 1>{kLinear}), std::nullopt);
}

TEST(DrmModifiers, PlanesOfTheModifier) {
  EXPECT_EQ(planesOf(kDriver, kCompressed), 2u);
  EXPECT_EQ(planesOf(kDriver, kLinear), 1u);
  EXPECT_EQ(planesOf(kDriver, 42), 0u);
}

TEST(DrmModifiers, ALinearPlaneThatHoldsTheImagePasses) {
  const std::array<Plane, 1> planes{{{0, 256 * 180, 256}}};
  EXPECT_EQ(checkPlanes(planes, 1, kLinear, 64, 180, 4, 256 * 180), "");
  // The last row need not be padded to the pitch.
  const std::array<Plane, 1> tight{{{0, 256 * 179 + 200, 256}}};
  EXPECT_EQ(checkPlanes(tight, 1, kLinear, 50, 180, 4, 1 << 20), "");
}

TEST(DrmModifiers, PlaneLayoutsThatCannotBeDescribedAreRefused) {
  const std::array<Plane, 1> narrow{{{0, 1 << 20, 128}}};
  EXPECT_NE(checkPlanes(narrow, 1, kLinear, 64, 180, 4, 1 << 20), "");  // rows of 256 bytes in a 128-byte pitch
  const std::array<Plane, 1> short_{{{0, 256 * 100, 256}}};
  EXPECT_NE(checkPlanes(short_, 1, kLinear, 64, 180, 4, 1 << 20), "");  // 100 rows' worth for 180
  const std::array<Plane, 1> outside{{{4096, 8192, 256}}};
  EXPECT_NE(checkPlanes(outside, 1, kNvidiaBlock, 64, 16, 4, 8192), "");  // past the memory's end
  const std::array<Plane, 1> hugeOffset{{{1ull << 33, 16, 256}}};
  EXPECT_NE(checkPlanes(hugeOffset, 1, kNvidiaBlock, 64, 16, 4, 1ull << 40), "");  // no 32-bit offset
  const std::array<Plane, 1> hugePitch{{{0, 16, 1ull << 31}}};
  EXPECT_NE(checkPlanes(hugePitch, 1, kNvidiaBlock, 64, 16, 4, 1ull << 40), "");  // no positive 32-bit stride
  const std::array<Plane, 1> one{{{0, 8192, 256}}};
  EXPECT_NE(checkPlanes(one, 2, kCompressed, 64, 16, 4, 8192), "");  // the modifier has two planes
  EXPECT_NE(checkPlanes({}, 0, kLinear, 64, 16, 4, 8192), "");
}

TEST(DrmModifiers, TwoPlanesInsideTheMemoryPass) {
  const std::array<Plane, 2> planes{{{0, 65536, 256}, {65536, 4096, 64}}};
  EXPECT_EQ(checkPlanes(planes, 2, kCompressed, 64, 180, 4, 69632), "");
}

TEST(DrmModifiers, ModifiersAreNamed) {
  EXPECT_EQ(describeModifier(kLinear), "linear");
  EXPECT_EQ(describeModifier(kNvidiaBlock), "nvidia 0x0300000000606015");
  EXPECT_EQ(describeModifier(kInvalid), "implicit");
}

}  // namespace
}  // namespace vitrine::gpu::drm
