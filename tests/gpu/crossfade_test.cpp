// Kiosk mode's cross-fade: the present pass mixes a second renderer's target into the output by the
// fade's weight, both scenes drawn in the same frame, with the validation layer watching; the kiosk's
// cross-fade runs the incoming scene on its own clock and swaps the renderers when it is over.
#include <functional>

#include "gpu/sync_objects.h"
#include "host/gallery/kiosk_crossfade.h"
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
  void update(const FrameInput& input) override {
    ++updates;
    last = input;
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

 public:
  int updates = 0;
  FrameInput last;  // the last step's
};

FlatScene<2>* dark = nullptr;
FlatScene<8>* light = nullptr;

class Crossfade : public GpuTest {
 protected:
  // The grey a 32x16 output shows when `outgoing` presents onto it mixed with what `incoming` records.
  std::vector<float> shown(host::SceneRenderer& outgoing, const std::function<host::Crossfade(VkCommandBuffer)>& incoming) {
    gpu::ImageDesc desc;
    desc.extent = {32, 16, 1};
    desc.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    gpu::Image output(device(), desc, "crossfade output");
    gpu::Buffer staging(device(), 32 * 16 * 8, VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUse::Readback, "readback");
    device().submitNow([&](VkCommandBuffer cmd) {
      const host::Crossfade fade = incoming(cmd);
      output.discard();
      outgoing.record(cmd, 0, FrameInput{},
                      host::BlitDestination{output.handle(), {32, 16}, output.lastUse(), gpu::use::TransferSrc,
                                            output.view()},
                      fade);
      output.assumeUse(gpu::use::TransferSrc);
      gpu::recordReadback(cmd, output, staging);
    });
    staging.invalidate();
    const ImageRgba image = imageFromHalves(32, 16, staging.view<const uint16_t>());
    std::vector<float> greys;
    for (const uint32_t x : {0u, 17u, 31u}) greys.push_back(image.at(x, 9)[0]);
    return greys;
  }
};

TEST_F(Crossfade, MixesTheIncomingScenesTargetByTheFadesWeight) {
  Assets assets("/nonexistent");
  gpu::ProgramLibrary programs(device());
  host::SceneRenderer outgoing(device(), programs, assets, 1), incoming(device(), programs, assets, 1);
  const TestSceneEntry &darkScene = testScene(dark), &lightScene = testScene(light);
  outgoing.setScene(darkScene.info, darkScene.create);
  incoming.setScene(lightScene.info, lightScene.create);
  for (const float weight : {0.0f, 0.25f, 1.0f}) {
    const auto greys = shown(outgoing, [&](VkCommandBuffer cmd) {
      incoming.recordTarget(cmd, 0, FrameInput{}, {32, 16});
      return host::Crossfade{&incoming.target(), weight};
    });
    const float expected = 0.2f * (1.0f - weight) + 0.8f * weight;
    for (const float grey : greys) EXPECT_NEAR(grey, expected, 2e-3f) << "weight " << weight;
  }
  device().waitIdle();
}

// The kiosk's cross-fade makes its renderer at the first fade, runs the incoming scene from zero with
// the run's seed, mixes it in by the weight it is given, and hands it over with its clock at the end.
TEST_F(Crossfade, TheKioskRunsTheIncomingSceneOnItsOwnClockThenSwapsTheRenderers) {
  Assets assets("/nonexistent");
  gpu::ProgramLibrary programs(device());
  int made = 0;
  host::KioskCrossfade crossfade([&] {
    ++made;
    return std::make_unique<host::SceneRenderer>(device(), programs, assets, 1);
  });
  auto showing = std::make_unique<host::SceneRenderer>(device(), programs, assets, 1);
  const TestSceneEntry &darkScene = testScene(dark), &lightScene = testScene(light);
  showing->setScene(darkScene.info, darkScene.create);
  EXPECT_FALSE(crossfade.fading());
  EXPECT_EQ(made, 0);  // no second renderer before a fade
  crossfade.step();    // nothing coming in: nothing runs

  crossfade.incoming().setScene(lightScene.info, lightScene.create);
  FrameInput run;
  run.seed = 7;
  run.time = 30.0;
  run.frame = 1800;
  crossfade.began(run);
  EXPECT_TRUE(crossfade.fading());
  for (int step = 0; step < 3; ++step) crossfade.step();
  EXPECT_EQ(light->updates, 3);
  EXPECT_EQ(light->last.frame, 2u);  // from zero, not the showing scene's 1800
  EXPECT_EQ(light->last.seed, 7u);
  crossfade.setWeight(0.25f);
  for (const float grey : shown(*showing, [&](VkCommandBuffer cmd) { return crossfade.record(cmd, 0, {32, 16}); }))
    EXPECT_NEAR(grey, 0.2f * 0.75f + 0.8f * 0.25f, 2e-3f);

  FrameInput input, last;
  ASSERT_TRUE(crossfade.finish(showing, input, last));
  EXPECT_EQ(&showing->scene(), static_cast<Scene*>(light));
  EXPECT_EQ(input.frame, 3u);  // the next step of the scene that came in
  EXPECT_EQ(last.frame, 2u);
  EXPECT_EQ(input.seed, 7u);
  EXPECT_FALSE(crossfade.fading());  // the scene that faded out is retired
  EXPECT_FALSE(crossfade.finish(showing, input, last));
  EXPECT_EQ(made, 1);
  // Nothing coming in: the showing scene alone, whatever weight was left.
  for (const float grey : shown(*showing, [&](VkCommandBuffer cmd) { return crossfade.record(cmd, 0, {32, 16}); }))
    EXPECT_NEAR(grey, 0.8f, 2e-3f);
  device().waitIdle();
}

}  // namespace
}  // namespace vitrine::test
