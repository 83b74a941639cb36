// The GLSL optics (shaders/glass/optics.glsl) and its C++ mirror (src/scenes/glass/optics.h) agree.
#include "gpu/resources.h"
#include "gpu/program.h"
#include "gpu/barriers.h"
#include "maths/hash.h"
#include "scenes/glass/materials.h"
#include "scenes/glass/optics.h"
#include "shaders/glass/probe_blocks.h"
#include "support/gpu_test.h"

#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace vitrine::test {
namespace {

class GlassOptics : public GpuTest {};

// 1e-4 of the value, but never tighter than 1e-5: near-zero results (colour-matching tails, a channel that
// cancels in the XYZ -> sRGB matrix) carry the absolute error of the order-one terms they came from.
void expectClose(float gpu, float cpu, const char* what, size_t i) {
  EXPECT_LE(std::fabs(gpu - cpu), 1e-4f * std::max(std::fabs(cpu), 0.1f)) << what << " at input " << i;
}

TEST_F(GlassOptics, ShaderMatchesTheCppReference) {
  constexpr uint32_t kPerMaterial = 64;
  constexpr uint32_t kSeed = 1234u;
  const glass::Sellmeier& sellmeier = glass::kSellmeierSf11;  // the strongest dispersion with a published law
  std::vector<shader::GlassOpticsProbeInput> inputs;
  for (uint32_t m = 0; m < glass::kMaterials.size(); ++m)
    for (uint32_t i = 0; i < kPerMaterial; ++i) {
      const float lambda = 360.0f + 470.0f * maths::hash01({i, m, 1u});  // past the visible range both ways
      inputs.push_back({lambda, glass::kMaterials[m].nd, glass::kMaterials[m].vd, maths::hash01({i, m, 2u})});
    }
  gpu::Buffer input(device(), inputs.size() * sizeof(shader::GlassOpticsProbeInput), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                    gpu::MemoryUse::Upload, "probe inputs");
  gpu::Buffer output(device(), inputs.size() * sizeof(shader::GlassOpticsProbeResult),
                     VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryUse::Readback, "probe results");
  std::copy(inputs.begin(), inputs.end(), input.view<shader::GlassOpticsProbeInput>().begin());

  const shader::GlassOpticsProbePush push{.sellmeierB = {sellmeier.B[0], sellmeier.B[1], sellmeier.B[2]},
                                          .seed = kSeed,
                                          .sellmeierC = {sellmeier.C[0], sellmeier.C[1], sellmeier.C[2]}};
  gpu::ProgramLibrary library(device());
  gpu::ComputeProgram probe(library, "glass/optics_probe.comp");
  device().submitNow([&](VkCommandBuffer cmd) {
    probe.bind(cmd);
    probe.constants(cmd, push);
    probe.push(cmd, gpu::Bindings().storageBuffer("Inputs", input.handle()).storageBuffer("Results", output.handle()));
    output.use(cmd, gpu::use::ComputeWriteBuffer);
    probe.dispatchOver(cmd, uint32_t(inputs.size()));
    output.use(cmd, gpu::use::HostReadBuffer);
  });
  output.invalidate();
  const auto results = output.view<shader::GlassOpticsProbeResult>();
  for (size_t i = 0; i < inputs.size(); ++i) {
    const float lambda = inputs[i].lambda, nd = inputs[i].nd, vd = inputs[i].vd, phase = inputs[i].phase;
    const uint32_t n = uint32_t(i);
    const shader::GlassOpticsProbeResult& r = results[i];
    expectClose(r.cauchy, glass::cauchyIor(lambda, nd, vd), "cauchyIor", i);
    expectClose(r.sellmeier, glass::sellmeierIor(lambda, sellmeier), "sellmeierIor", i);
    expectClose(r.dielectric, glass::fresnelDielectric(phase, nd), "fresnelDielectric", i);
    expectClose(r.schlick, glass::fresnelSchlick(phase, nd), "fresnelSchlick", i);
    const glm::vec3 xyz = glass::cieXyz(lambda);
    for (int c = 0; c < 3; ++c) expectClose(r.cie[c], xyz[c], "cieXyz", i);
    expectClose(r.stratified, glass::stratifiedLambda(int(n % 16u), 16, phase), "stratifiedLambda", i);
    const glm::vec3 weight = glass::spectralWeight(lambda);
    for (int c = 0; c < 3; ++c) expectClose(r.weight[c], weight[c], "spectralWeight", i);
    // Integer maths down to one float conversion: the phase is the same bits on both sides.
    EXPECT_EQ(r.spectral, glass::spectralPhase({n, n / 7u}, n, kSeed, true)) << "spectralPhase at input " << i;
    const glm::vec3 mapped = glass::filmic({phase, 4.0f * phase, 16.0f * phase});
    for (int c = 0; c < 3; ++c) expectClose(r.toneMapped[c], mapped[c], "filmic", i);
    expectClose(r.hero, glass::heroLambda(n, kSeed, true), "heroLambda", i);
    if (HasFailure()) break;  // one input's report says enough
  }
}

}  // namespace
}  // namespace vitrine::test
