// The GLSL field (shaders/kifs/field.glsl) and its C++ mirror (src/scenes/kifs/kifs_math.h) agree.
#include "gpu/resources.h"
#include "gpu/program.h"
#include "gpu/barriers.h"
#include "maths/hash.h"
#include "scenes/kifs/kifs_math.h"
#include "support/gpu_test.h"

#include <glm/vec4.hpp>

namespace vitrine::test {
namespace {

class KifsField : public GpuTest {};

TEST_F(KifsField, ShaderMatchesTheCppReference) {
  constexpr uint32_t kPerStage = 256;
  std::vector<glm::vec4> points;
  for (int stage = 1; stage <= kifs::kStepCount; ++stage)
    for (uint32_t i = 0; i < kPerStage; ++i) {
      const glm::vec3 p{maths::hash01({i, 1u, uint32_t(stage)}), maths::hash01({i, 2u, uint32_t(stage)}),
                        maths::hash01({i, 3u, uint32_t(stage)})};
      points.emplace_back((p - 0.5f) * 4.0f, float(stage));
    }
  const VkDeviceSize bytes = points.size() * sizeof(glm::vec4);
  gpu::Buffer input(device(), bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryUse::Upload, "probe points");
  gpu::Buffer output(device(), bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryUse::Readback, "probe samples");
  std::copy(points.begin(), points.end(), input.view<glm::vec4>().begin());

  gpu::ProgramLibrary library(device());
  gpu::ComputeProgram probe(library, "kifs/field_probe.comp");
  device().submitNow([&](VkCommandBuffer cmd) {
    probe.bind(cmd);
    probe.push(cmd, gpu::Bindings().storageBuffer("Points", input.handle()).storageBuffer("Samples", output.handle()));
    output.use(cmd, gpu::use::ComputeWriteBuffer);
    probe.dispatchOver(cmd, uint32_t(points.size()));
    output.use(cmd, gpu::use::HostReadBuffer);
  });
  output.invalidate();
  const auto samples = output.view<glm::vec4>();
  for (size_t i = 0; i < points.size(); ++i) {
    const auto expected = kifs::field(glm::vec3(points[i]), int(points[i].w));
    // The warp multiplies sin's last-bit differences by up to 0.29 x 56.3 ~ 16: allow 1e-3.
    ASSERT_NEAR(samples[i].x, expected.distance, 1e-3f) << "stage " << points[i].w << " point " << i;
    ASSERT_NEAR(samples[i].y, expected.trap.x, 1e-3f);
    ASSERT_NEAR(samples[i].z, expected.trap.y, 1e-3f);
  }
}

}  // namespace
}  // namespace vitrine::test
