// The GLSL shapes and diamond (shaders/glass/shapes.glsl, diamond.glsl) agree with their C++ mirrors
// (src/scenes/glass/shapes.h, diamond.h): the diamond's back exit, searched and tried on one facet, its first walk
// step, and every shape's distance.
#include "gpu/barriers.h"
#include "gpu/program.h"
#include "gpu/resources.h"
#include "maths/hash.h"
#include "scenes/glass/diamond.h"
#include "scenes/glass/diamond_rays.h"
#include "scenes/glass/diamond_walk.h"
#include "scenes/glass/shapes.h"
#include "shaders/glass/probe_blocks.h"
#include "support/gpu_test.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace vitrine::test {
namespace {

class GlassDiamondProbe : public GpuTest {};

glm::vec3 randomSigned(uint32_t i, uint32_t salt) {
  return glm::vec3(maths::hash01({i, salt, 1u}), maths::hash01({i, salt, 2u}), maths::hash01({i, salt, 3u})) * 2.0f -
         1.0f;
}

TEST_F(GlassDiamondProbe, ShaderMatchesTheCppReference) {
  constexpr float kDiameter = 400.0f, kEta = 2.4175f;  // the probe's eta
  constexpr uint32_t kProbes = 1024;
  const glass::DiamondGeometry stone = glass::makeDiamond(kDiameter);
  const std::vector<glass::ShapeDims> shapes = {
      glass::pillDims({400.0f, 115.0f, 62.0f}, 100.0f),
      glass::prismDims({393.0f, 149.0f, 117.0f}),
      glass::pillDims({400.0f, 115.0f, 62.0f}, 12.0f, true),  // smooth, its outline a rounded rectangle
      glass::cubeDims(230.0f, 44.0f),
      glass::cubeDims(230.0f, 44.0f, true),
      glass::plateDims({346.0f, 346.0f, 60.0f}, 10.5f, 17.0f, 535.0f, 0.7f),
      glass::plateDims({346.0f, 346.0f, 60.0f}, 10.5f, 17.0f, 535.0f, 0.7f, true),
      glass::diamondDims(kDiameter),  // the same diameter as the planes in the buffer
  };

  // Probes: a ray from a point inside the stone, and a sample point anywhere around the shapes.
  std::vector<shader::GlassDiamondProbe> probes;
  for (uint32_t i = 0; probes.size() < kProbes; ++i) {
    const glm::vec3 origin = randomSigned(i, 1u) * glm::vec3(200.0f, 200.0f, stone.culetDepth);
    if (glass::diamondSdf(stone, origin) > -1e-3f * kDiameter) continue;
    glm::vec3 direction = randomSigned(i, 2u);
    if (glm::length(direction) < 0.05f) continue;
    direction = glm::normalize(direction);
    probes.push_back({.origin = origin, .direction = direction, .point = randomSigned(i, 3u) * 300.0f});
  }

  const shader::GlassDiamond planes = glass::diamondBlock(stone);
  auto upload = [&](const void* data, VkDeviceSize bytes, const char* name) {
    gpu::Buffer buffer(device(), bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryUse::Upload, name);
    std::copy_n(static_cast<const std::byte*>(data), bytes, buffer.view<std::byte>().begin());
    return buffer;
  };
  gpu::Buffer planeBuffer = upload(&planes, sizeof(planes), "diamond planes");
  gpu::Buffer shapeBuffer = upload(shapes.data(), shapes.size() * sizeof(glass::ShapeDims), "probe shapes");
  gpu::Buffer probeBuffer = upload(probes.data(), probes.size() * sizeof(shader::GlassDiamondProbe), "probe rays");
  gpu::Buffer output(device(), kProbes * sizeof(shader::GlassDiamondProbeResult), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                     gpu::MemoryUse::Readback, "probe results");

  gpu::ProgramLibrary library(device());
  gpu::ComputeProgram probe(library, "glass/diamond_probe.comp");
  device().submitNow([&](VkCommandBuffer cmd) {
    probe.bind(cmd);
    probe.push(cmd, gpu::Bindings()
                        .storageBuffer("DiamondPlanes", planeBuffer.handle())
                        .storageBuffer("Shapes", shapeBuffer.handle())
                        .storageBuffer("Probes", probeBuffer.handle())
                        .storageBuffer("Results", output.handle()));
    output.use(cmd, gpu::use::ComputeWriteBuffer);
    probe.dispatchOver(cmd, kProbes);
    output.use(cmd, gpu::use::HostReadBuffer);
  });
  output.invalidate();
  const auto results = output.view<shader::GlassDiamondProbeResult>();

  int facetsCompared = 0;
  for (uint32_t i = 0; i < kProbes; ++i) {
    const glm::vec3 origin = probes[i].origin, direction = probes[i].direction;
    const shader::GlassDiamondProbeResult& r = results[i];
    float t;
    glm::vec3 n;
    int facet;
    ASSERT_TRUE(glass::diamondExit(stone, origin, direction, t, n, facet));
    ASSERT_EQ(r.found, 1u) << "probe " << i << ": the GPU found no exit";
    ASSERT_NEAR(r.t, t, 1e-3f * kDiameter) << "probe " << i;
    // Within a hair of an edge either facet is right; elsewhere they must agree, normal and first step too.
    if (glass::diamondEdgeDistance(stone, origin + t * direction) < 1e-3f * kDiameter) continue;
    ++facetsCompared;
    ASSERT_EQ(r.facet, facet) << "probe " << i;
    // Tried on a facet alone, the exit is accepted on its own facet (the girdle is never tried) and on no other.
    EXPECT_EQ(r.followed & 1u, facet == glass::kGirdleFacet ? 0u : 1u) << "probe " << i;
    EXPECT_EQ(r.followed & 2u, 0u) << "probe " << i;
    ASSERT_NEAR(glm::distance(r.normal, n), 0.0f, 1e-5f) << "probe " << i;
    glass::DiamondWalk walk = glass::diamondWalkStart(origin, direction, 1.0f, 6);
    glm::vec3 exitDir;
    float exitWeight;
    glass::diamondStep(stone, walk, kEta, true, exitDir, exitWeight);
    // Fresnel's transmittance falls like a square root at the critical angle: leave a margin around it.
    const float incidence = std::acos(glm::clamp(glm::dot(direction, n), -1.0f, 1.0f));
    if (std::fabs(incidence - std::asin(1.0f / kEta)) < 1e-3f) continue;
    ASSERT_NEAR(r.exitWeight, exitWeight, 2e-3f) << "probe " << i;
    if (exitWeight > 0.05f) {
      ASSERT_NEAR(glm::distance(r.exitDir, exitDir), 0.0f, 2e-3f) << "probe " << i;
    }
  }
  EXPECT_GT(facetsCompared, int(kProbes) * 3 / 4);

  for (uint32_t i = 0; i < kProbes; ++i) {
    const glm::vec3 point = probes[i].point;
    for (size_t k = 0; k < shapes.size(); ++k)
      // GPU sin and cos may be off by 2^-11 (the plate's wave): allow 1e-4 of the shape's size.
      ASSERT_NEAR(results[i].distances[k], glass::shapeSdf(shapes[k], point), 1e-4f * glass::shapeScale(shapes[k]))
          << "shape " << k << " probe " << i;
  }
}

}  // namespace
}  // namespace vitrine::test
