// A program's interface comes from its shader's SPIR-V: the layout, the local size and the push
// block's size are reflected, and what a scene binds is checked against them before any GPU work,
// with a message that names the shader, the binding and what it expected.
#include "core/error.h"
#include "gpu/program.h"
#include "gpu/program_variants.h"
#include "gpu/resources.h"
#include "shaders/kifs/march_push.h"
#include "support/gpu_test.h"


namespace vitrine::test {
namespace {

class ProgramInterface : public GpuTest {
 protected:
  // Records into a throw-away command buffer and returns the Error's message ("" when none).
  template <typename F> std::string errorWhileRecording(F&& record) {
    std::string message;
    device().submitNow([&](VkCommandBuffer cmd) {
      try {
        record(cmd);
      } catch (const Error& e) {
        message = e.what();
      }
    });
    return message;
  }
  gpu::ProgramLibrary library_{device()};
};

TEST_F(ProgramInterface, TheLayoutAndLocalSizeComeFromTheShader) {
  const gpu::ComputeProgram probe(library_, "kifs/field_probe.comp");
  ASSERT_EQ(probe.interface().bindings.size(), 2u);
  EXPECT_EQ(probe.interface().bindings[0].name, "Points");
  EXPECT_EQ(probe.interface().bindings[0].type, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
  EXPECT_EQ(probe.interface().bindings[1].name, "Samples");
  EXPECT_EQ(probe.localSize(), (std::array<uint32_t, 3>{64, 1, 1}));
  EXPECT_EQ(probe.interface().pushConstantBytes, 0u);

  const gpu::ComputeProgram march(library_, "kifs/kifs.comp");
  ASSERT_EQ(march.interface().bindings.size(), 1u);
  EXPECT_EQ(march.interface().bindings[0].name, "target");
  EXPECT_EQ(march.interface().bindings[0].type, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE);
  EXPECT_EQ(march.localSize(), (std::array<uint32_t, 3>{8, 8, 1}));
  EXPECT_EQ(march.interface().pushConstantBytes, sizeof(shader::KifsMarchPush));
}

TEST_F(ProgramInterface, BindingsAreCheckedByNameAndTypeBeforeAnyGpuWork) {
  const gpu::ComputeProgram probe(library_, "kifs/field_probe.comp");
  gpu::Buffer buffer(device(), 256, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryUse::Device, "probe buffer");
  const auto push = [&](const gpu::Bindings& bindings) {
    return errorWhileRecording([&](VkCommandBuffer cmd) {
      probe.bind(cmd);
      probe.push(cmd, bindings);
    });
  };
  EXPECT_EQ(push(gpu::Bindings().storageBuffer("Samples", buffer.handle()).storageBuffer("Points", buffer.handle())),
            "");  // any order: by name
  EXPECT_EQ(push(gpu::Bindings().storageBuffer("Points", buffer.handle())),
            "kifs/field_probe.comp: binding 1 'Samples' (storage buffer) was not given");
  EXPECT_EQ(push(gpu::Bindings().storageBuffer("Points", buffer.handle()).storageBuffer("Sample", buffer.handle())),
            "kifs/field_probe.comp: binding 1 'Samples' (storage buffer) was not given");
  EXPECT_EQ(push(gpu::Bindings()
                     .storageBuffer("Points", buffer.handle())
                     .storageBuffer("Samples", buffer.handle())
                     .storageBuffer("Extra", buffer.handle())),
            "kifs/field_probe.comp: the shader has no binding 'Extra' (it has: Points, Samples)");
  EXPECT_EQ(push(gpu::Bindings().uniformBuffer("Points", buffer.handle()).storageBuffer("Samples", buffer.handle())),
            "kifs/field_probe.comp: binding 0 'Points' is a storage buffer in the shader, given a uniform buffer");
}

TEST_F(ProgramInterface, APushBlockOfAnotherSizeIsRefused) {
  const gpu::ComputeProgram march(library_, "kifs/kifs.comp");
  struct Short {
    float angles[2];
  };
  EXPECT_EQ(errorWhileRecording([&](VkCommandBuffer cmd) {
              march.bind(cmd);
              march.constants(cmd, Short{});
            }),
            "kifs/kifs.comp: the push block is 32 bytes in the shader, 8 given");
}

// A scene's options that choose shader paths are specialization constants: one pipeline for each set
// of them, built the first time it is asked for and handed out again after that.
TEST_F(ProgramInterface, AVariantIsBuiltOnceForEachSetOfConstants) {
  const gpu::ComputeVariants marches(library_, "kifs/kifs.comp");
  const gpu::ComputeProgram& stageOne = marches({1});
  EXPECT_EQ(&marches({1}), &stageOne);
  const gpu::ComputeProgram& stageTwo = marches({2});
  EXPECT_NE(&stageTwo, &stageOne);
  EXPECT_NE(stageTwo.pipeline(), stageOne.pipeline());
  EXPECT_EQ(&marches({1}), &stageOne);  // still there after another was built
  EXPECT_THROW(marches({1, 0, 0, 0, 0}), Error);
}

}  // namespace
}  // namespace vitrine::test
