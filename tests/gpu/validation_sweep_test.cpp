// The validation sweep: every scene through every preset and every stage, with two frames in flight,
// output sizes changing under it and switches to another scene and back, all under the validation
// layer with its synchronisation checks. Any message fails the scene's test (GpuTest).
#include "gpu/sync_objects.h"
#include "host/scene_renderer.h"
#include "support/gpu_test.h"

#include <array>

namespace vitrine::test {
namespace {

// A gallery's frame loop without the window: two frames in flight, any output size each frame.
class TwoInFlight {
 public:
  explicit TwoInFlight(const gpu::Device& device)
      : device_(device), programs_(device), renderer_(device, programs_, assets_, 2),
        pool_(gpu::createCommandPool(device, VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT, "sweep frames")) {
    const VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO, nullptr, pool_,
                                            VK_COMMAND_BUFFER_LEVEL_PRIMARY, 2};
    vkAllocateCommandBuffers(device, &alloc, cmds_.data());
  }
  ~TwoInFlight() { device_.waitIdle(); }

  host::SceneRenderer& renderer() { return renderer_; }

  void frames(int count, VkExtent2D size) {
    for (int i = 0; i < count; ++i) frame(size);
  }

 private:
  void frame(VkExtent2D size) {
    const uint32_t slot = uint32_t(input_.frame % 2);
    if (serials_[slot]) device_.wait(serials_[slot]);
    gpu::Image& output = outputs_[slot];
    if (!output || output.extent2d().width != size.width || output.extent2d().height != size.height) {
      if (output) device_.retire(std::move(output));
      gpu::ImageDesc desc;
      desc.extent = {size.width, size.height, 1};
      desc.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
      output = gpu::Image(device_, desc, "sweep output");
    }
    VkCommandBuffer cmd = cmds_[slot];
    vkResetCommandBuffer(cmd, 0);
    const VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO, nullptr,
                                         VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    vkBeginCommandBuffer(cmd, &begin);
    renderer_.scene().update(input_);
    output.discard();
    renderer_.record(cmd, slot, input_,
                     host::BlitDestination{output.handle(), size, output.lastUse(), gpu::use::TransferSrc, output.view()});
    output.assumeUse(gpu::use::TransferSrc);
    vkEndCommandBuffer(cmd);
    serials_[slot] = device_.submit({cmd, {}, {}});
    input_.time += input_.dt;
    ++input_.frame;
  }

  const gpu::Device& device_;
  Assets assets_ = Assets::locate();
  gpu::ProgramLibrary programs_;
  host::SceneRenderer renderer_;
  gpu::Unique<VkCommandPool> pool_;
  std::array<VkCommandBuffer, 2> cmds_{};
  std::array<uint64_t, 2> serials_{};
  std::array<gpu::Image, 2> outputs_;
  FrameInput input_;
};

class ValidationSweep : public GpuTest, public ::testing::WithParamInterface<const SceneInfo*> {};

TEST_P(ValidationSweep, EveryPresetAndStageThroughResizesAndSwitches) {
  const SceneInfo& info = *GetParam();
  const SceneInfo& other = *findScene(info.name == "kifs" ? "glass" : "kifs");
  TwoInFlight run(device());
  // Small sizes: the sweep is about synchronisation and lifetimes, not pixels. noodles is drawn
  // with fewer strands so lavapipe gets through it in seconds.
  const params::KeyValues light = info.name == "noodles" ? params::KeyValues{{"grid", "6"}, {"segments", "24"}}
                                                         : params::KeyValues{};
  const std::array<VkExtent2D, 3> sizes{{{48, 27}, {64, 36}, {40, 40}}};
  run.renderer().setScene(info);
  ASSERT_EQ(run.renderer().applyParameters(light), "");
  run.frames(3, sizes[0]);
  size_t n = 0;
  for (const params::Preset& preset : info.schema().presets()) {
    ASSERT_EQ(run.renderer().applyPreset(preset.name), "") << preset.name;
    ASSERT_EQ(run.renderer().applyParameters(light), "");
    run.frames(2, sizes[++n % sizes.size()]);
  }
  if (const params::Param* stage = info.schema().find("stage"); stage && stage->kind == params::Kind::Choice)
    for (const std::string& choice : stage->choices) {
      ASSERT_EQ(run.renderer().applyParameters({{"stage", choice}}), "") << choice;
      run.frames(2, sizes[++n % sizes.size()]);
    }
  for (const char* tier : {"low", "medium", "high"}) {  // each tier's render scale resizes the scene's images
    ASSERT_EQ(run.renderer().applyParameters({{"tier", tier}}), "") << tier;
    run.frames(2, sizes[++n % sizes.size()]);
  }
  run.renderer().setScene(other);  // away and back, with frames of the old scene still in flight
  run.frames(2, sizes[1]);
  run.renderer().setScene(info);
  ASSERT_EQ(run.renderer().applyParameters(light), "");
  run.frames(3, sizes[2]);
}

std::vector<const SceneInfo*> everyScene() {
  std::vector<const SceneInfo*> scenes;
  for (const SceneInfo& info : sceneRegistry()) scenes.push_back(&info);
  return scenes;
}

INSTANTIATE_TEST_SUITE_P(Scenes, ValidationSweep, ::testing::ValuesIn(everyScene()),
                         [](const auto& info) { return std::string(info.param->name); });

}  // namespace
}  // namespace vitrine::test
