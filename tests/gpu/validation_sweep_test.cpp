// The validation sweep: every scene through every preset and every stage, with two frames in flight,
// output sizes changing under it and switches to another scene and back, the later half through the
// flash guard, all under the validation layer with its synchronisation checks. Any message fails the scene's test (GpuTest).
#include "support/frames_in_flight.h"
#include "support/gpu_test.h"

#include <array>

namespace vitrine::test {
namespace {

class ValidationSweep : public GpuTest, public ::testing::WithParamInterface<const SceneInfo*> {};

TEST_P(ValidationSweep, EveryPresetAndStageThroughResizesAndSwitches) {
  const SceneInfo& info = *GetParam();
  const SceneInfo& other = *findScene(info.name == "kifs" ? "glass" : "kifs");
  FramesInFlight run(device(), Assets::locate());
  // Small sizes: the sweep is about synchronisation and lifetimes, not pixels. noodles is drawn
  // with fewer strands so lavapipe gets through it in seconds.
  const params::KeyValues fewerStrands =
      info.name == "noodles" ? params::KeyValues{{"grid", "6"}, {"segments", "24"}} : params::KeyValues{};
  const std::array<VkExtent2D, 3> sizes{{{48, 27}, {64, 36}, {40, 40}}};
  run.renderer().setScene(info);
  ASSERT_EQ(run.renderer().applyParameters(fewerStrands), "");
  run.frames(3, sizes[0]);
  size_t n = 0;
  for (const params::Preset& preset : info.schema().presets()) {
    ASSERT_EQ(run.renderer().applyPreset(preset.name), "") << preset.name;
    ASSERT_EQ(run.renderer().applyParameters(fewerStrands), "");
    run.frames(2, sizes[++n % sizes.size()]);
  }
  // From here on through the flash guard: its held frame follows the output's size, and the card's
  // strobe makes it hold pixels back with two frames in flight.
  run.guard(true);
  if (info.name == "calibrate") {
    ASSERT_EQ(run.renderer().applyParameters({{"strobe", "on"}, {"strobe_hz", "25"}}), "");
    run.frames(12, sizes[0]);
    run.frames(2, sizes[1]);
  }
  if (const params::Param* stage = info.schema().find("stage"); stage && stage->kind == params::Kind::Choice)
    for (const std::string& choice : stage->choices) {
      ASSERT_EQ(run.renderer().applyParameters({{"stage", choice}}), "") << choice;
      run.frames(2, sizes[++n % sizes.size()]);
    }
  for (const char* tier : {"low", "medium", "high"}) {  // each tier's render scale resizes the scene's images
    if (!info.schema().find("tier")) break;  // the calibration card is drawn at the output's size only
    ASSERT_EQ(run.renderer().applyParameters({{"tier", tier}}), "") << tier;
    run.frames(2, sizes[++n % sizes.size()]);
  }
  run.renderer().setScene(other);  // away and back, with frames of the old scene still in flight
  run.frames(2, sizes[1]);
  run.renderer().setScene(info);
  ASSERT_EQ(run.renderer().applyParameters(fewerStrands), "");
  run.frames(3, sizes[2]);
}

// The cost estimate behind the guard against freezing changes (host/cost_guard.h), from live scenes.
class CostRatio : public GpuTest {};

TEST_F(CostRatio, ScenesSayHowMuchMoreWorkAChangeMakes) {
  FramesInFlight run(device(), Assets::locate());
  run.renderer().setScene(*findScene("noodles"));  // 16^3 strands of 64 segments
  EXPECT_DOUBLE_EQ(run.renderer().costRatio({{"grid", "64"}, {"segments", "256"}}), 256.0);
  EXPECT_DOUBLE_EQ(run.renderer().costRatio({{"grid", "8"}}), 0.125);
  EXPECT_DOUBLE_EQ(run.renderer().costRatio({{"grid", "nonsense"}}), 1.0);  // refused: applying says why
  run.renderer().setScene(*findScene("bloom"));
  EXPECT_GT(run.renderer().costRatio({{"lattice", "256"}}), 18.0);  // (256/96)^3
  run.renderer().setScene(*findScene("kifs"));
  EXPECT_DOUBLE_EQ(run.renderer().costRatio({{"step", "1"}}), 1.0);
}

std::vector<const SceneInfo*> everyScene() {
  std::vector<const SceneInfo*> scenes;
  for (const SceneInfo& info : sceneRegistry()) scenes.push_back(&info);
  return scenes;
}

INSTANTIATE_TEST_SUITE_P(Scenes, ValidationSweep, ::testing::ValuesIn(everyScene()),
                         [](const auto& test) { return std::string(test.param->name); });

}  // namespace
}  // namespace vitrine::test
