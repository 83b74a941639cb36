// Kiosk mode's cross-fade: the present pass mixes a second renderer's target into the output by the
// fade's weight, both scenes drawn in the same frame, with the validation layer watching.
#include "gpu/sync_objects.h"
#include "host/scene_renderer.h"
#include "image/image.h"
#include "shaders/test/accumulate_push.h"
#include "support/gpu_test.h"
#include "support/test_scene.h"

namespace vitrine::test {
namespace {

// Fills the target with one grey level, kTenths / 10.
template <int kTenths>
class FlatScene final : public TestScene {
 public:
  explicit FlatScene(const SceneContext& context)
      : device_(context.device), fill_(context.programs, "test/accumulate.comp") {
    unused_ = context.resources.declare({"unused source", VK_FORMAT_R16G16B16A16_SFLOAT, VK_IMAGE_USAGE_SAMPLED_BIT,
                                         gpu::ImageSize::absolute(1, 1), 1});
  }
  void record(const FrameContext& frame) override {
    const auto pass = frame.pass("flat");
    frame.transition(frame.image(unused_), gpu::use::ComputeSample);
    frame.transition(frame.target, gpu::use::ComputeWrite);
    fill_.bind(frame.cmd);
    fill_.push(frame.cmd, gpu::Bindings()
                              .sampledImage("source", frame.image(unused_).view(),
                                            device_.sampler(gpu::Device::Filter::Linear, gpu::Device::Address::Clamp),
                                            gpu::use::ComputeSample.layout)
                              .storageImage("destination", frame.target.view()));
    fill_.constants(frame.cmd, shader::TestAccumulatePush{.add = float(kTenths) / 10.0f, .useSource = 0u});
    fill_.dispatchOver(frame.cmd, frame.target.extent2d());
  }

 private:
  const gpu::Device& device_;
  gpu::ComputeProgram fill_;
  gpu::ImageHandle unused_;
};

FlatScene<2>* dark = nullptr;
FlatScene<8>* light = nullptr;

class Crossfade : public GpuTest {};

TEST_F(Crossfade, MixesTheIncomingScenesTargetByTheFadesWeight) {
  Assets assets("/nonexistent");
  gpu::ProgramLibrary programs(device());
  host::SceneRenderer outgoing(device(), programs, assets, 1), incoming(device(), programs, assets, 1);
  const TestSceneEntry &darkScene = testScene(dark), &lightScene = testScene(light);
  outgoing.setScene(darkScene.info, darkScene.create);
  incoming.setScene(lightScene.info, lightScene.create);
  gpu::ImageDesc desc;
  desc.extent = {32, 16, 1};
  desc.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  gpu::Image output(device(), desc, "crossfade output");

  for (const float weight : {0.0f, 0.25f, 1.0f}) {
    gpu::Buffer staging(device(), 32 * 16 * 8, VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUse::Readback, "readback");
    device().submitNow([&](VkCommandBuffer cmd) {
      const FrameInput input;
      incoming.recordTarget(cmd, 0, input, {32, 16});
      output.discard();
      outgoing.record(cmd, 0, input,
                      host::BlitDestination{output.handle(), {32, 16}, output.lastUse(), gpu::use::TransferSrc,
                                            output.view()},
                      host::Crossfade{&incoming.target(), weight});
      output.assumeUse(gpu::use::TransferSrc);
      gpu::recordReadback(cmd, output, staging);
    });
    staging.invalidate();
    const ImageRgba image = imageFromHalves(32, 16, staging.view<const uint16_t>());
    const float expected = 0.2f * (1.0f - weight) + 0.8f * weight;
    for (const uint32_t x : {0u, 17u, 31u}) EXPECT_NEAR(image.at(x, 9)[0], expected, 2e-3f) << "weight " << weight;
  }
  device().waitIdle();
}

}  // namespace
}  // namespace vitrine::test
