// The neon chain pass (shaders/neon/chains.comp) and its C++ reference (src/scenes/neon/chains.h) agree
// bit for bit over frames of heads in every state, each side ping-ponging its own positions: the
// positions are integrated, so anything less than exact would grow over a run.
#include "gpu/resources.h"
#include "gpu/program.h"
#include "gpu/barriers.h"
#include "maths/hash.h"
#include "scenes/neon/chains.h"
#include "scenes/neon/particle_engine.h"
#include "support/gpu_test.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace vitrine::test {
namespace {

class NeonChainsGpu : public GpuTest {
 protected:
  static constexpr uint32_t kChains = 16, kPerChain = 32;
  static constexpr float kDt = 0.0625f;  // with a decay of 4 per second: life falls by exactly 0.25 a step

  // Releases per engine step. Steps 0-3 come before the first frame, so the pass meets heads already
  // alive, heads that die during the run (the releases of step 0 are freed in their sixth step, frame 1),
  // heads initialising in each frame, and slots that are never used. Later steps release from a hash.
  static constexpr std::array<uint32_t, 9> kReleases{2, 1, 0, 3, 2, 1, 2, 1, 0};
  static uint32_t releasesAt(uint32_t s) {
    return s < kReleases.size() ? kReleases[s] : uint32_t(maths::hash01({s, 5u, 9u}) * 1.2f);
  }

  // Runs `frames` frames on both sides with `groups` workgroups (chainGroups() when zero); heads lose
  // `decay` of their life per second once alive.
  void expectMatchesReference(glm::uvec2 groups, uint32_t frames = 5, float decay = 4.0f) {
    neon::ParticleEngine engine({kChains, decay}, neon::EngineMode::LockStep);
    uint32_t released = 0;
    auto step = [&](uint32_t s) {
      for (uint32_t i = 0; i < releasesAt(s); ++i, ++released)
        engine.release({maths::hash01({released, 1u, 9u}) * 6.0f - 3.0f,
                        maths::hash01({released, 2u, 9u}) * 6.0f - 3.0f,
                        maths::hash01({released, 3u, 9u}) * 6.0f - 3.0f});
      // A pen (a drag's steered head) from step 1 to frame 2, moved every step: the shader puts the
      // head where the CPU says.
      if (s == 1) engine.release({0.5f, 1.0f, 1.5f}, true);
      else if (s > 1 && s < 6) engine.steer({0.5f + 0.3f * float(s), 1.0f, 1.5f - 0.2f * float(s)});
      else if (s == 6) engine.endSteer();
      engine.step(kDt);
    };
    for (uint32_t s = 0; s < 4; ++s) step(s);

    constexpr uint32_t kParticles = kChains * kPerChain;
    const VkDeviceSize bytes = kParticles * sizeof(glm::vec4);
    gpu::Buffer heads(device(), kChains * sizeof(neon::HeadState), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                      gpu::MemoryUse::Upload, "neon heads");
    // Host-visible and coherent, so the test can seed the first and read every frame without copies.
    std::array<gpu::Buffer, 2> positions{
        gpu::Buffer(device(), bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryUse::Upload, "neon positions 0"),
        gpu::Buffer(device(), bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryUse::Upload, "neon positions 1")};

    // Scattered starting positions: a pass that ignored `previous` for inactive chains would show.
    std::vector<glm::vec4> cpu(kParticles), cpuNext(kParticles);
    for (uint32_t i = 0; i < kParticles; ++i)
      cpu[i] =
          glm::vec4(maths::hash01({i, 1u, 4u}), maths::hash01({i, 2u, 4u}), maths::hash01({i, 3u, 4u}), 0.0f) * 8.0f -
          glm::vec4(4.0f, 4.0f, 4.0f, 0.0f);
    std::copy(cpu.begin(), cpu.end(), positions[0].view<glm::vec4>().begin());

    gpu::ProgramLibrary library(device());
    gpu::ComputeProgram chains(library, "neon/chains.comp");
    if (groups == glm::uvec2(0u)) groups = neon::chainGroups(kParticles, chains.localSize()[0]);

    std::array<uint32_t, 3> statesSeen{};
    float headTravel = 0.0f;
    for (uint32_t frame = 0; frame < frames; ++frame) {
      step(4 + frame);
      const std::vector<neon::HeadState> snapshot = engine.latest().heads;
      for (const neon::HeadState& h : snapshot) ++statesSeen[h.state];
      std::copy(snapshot.begin(), snapshot.end(), heads.view<neon::HeadState>().begin());
      const neon::ChainParams params{kDt, neon::followerLerp(0.35f, kDt), 1.5f, 0.5f, 10.0 + 0.7 * frame};

      gpu::Buffer& previous = positions[frame % 2];
      gpu::Buffer& next = positions[(frame + 1) % 2];
      device().submitNow([&](VkCommandBuffer cmd) {
        chains.bind(cmd);
        chains.constants(cmd, neon::chainPush(kChains, kPerChain, params));
        chains.push(cmd, gpu::Bindings()
                             .storageBuffer("Heads", heads.handle())
                             .storageBuffer("Previous", previous.handle())
                             .storageBuffer("Next", next.handle()));
        previous.use(cmd, gpu::use::ComputeReadBuffer);
        next.use(cmd, gpu::use::ComputeWriteBuffer);
        chains.dispatchGroups(cmd, {groups.x, groups.y, 1});
        next.use(cmd, gpu::use::HostReadBuffer);
      });
      next.invalidate();

      neon::stepChains(snapshot, kPerChain, cpu, cpuNext, params);
      const auto gpu = next.view<const glm::vec4>();
      for (uint32_t i = 0; i < kParticles; ++i) {
        const std::string where = fmt::format("frame {} chain {} particle {} state {}", frame, i / kPerChain,
                                              i % kPerChain, snapshot[i / kPerChain].state);
        ASSERT_EQ(gpu[i], cpuNext[i]) << where;  // w: the head's life, copied
        if (i % kPerChain == 0 && snapshot[i / kPerChain].state == uint32_t(neon::ChainState::Alive))
          headTravel = std::max(headTravel, glm::length(glm::vec3(cpuNext[i]) - glm::vec3(cpu[i])));
      }
      std::swap(cpu, cpuNext);
    }
    // The run covered what it claims: every state, and heads that actually moved through the field.
    EXPECT_GT(statesSeen[0], 0u);
    EXPECT_GT(statesSeen[1], 0u);
    EXPECT_GT(statesSeen[2], 0u);
    EXPECT_GT(headTravel, 1e-2f);
  }
};

TEST_F(NeonChainsGpu, ShaderMatchesTheCppReference) { expectMatchesReference(glm::uvec2(0u)); }

// 150 steps of 1/16 s, heads that live for 40 of them: they swim far through the field, where a
// last-bit difference would have grown with every step.
TEST_F(NeonChainsGpu, AHundredAndFiftyFramesStayOnTheCppReferenceBitForBit) {
  expectMatchesReference(glm::uvec2(0u), 150, 0.4f);
}

TEST_F(NeonChainsGpu, StackedRowsOfWorkgroupsMatchTheCppReference) {
  // 3 x 3 groups of 64 for 512 particles: rows as chainGroups() stacks them past 65535 groups, with an
  // overhang that must write nothing.
  expectMatchesReference(glm::uvec2(3u, 3u));
}

}  // namespace
}  // namespace vitrine::test
