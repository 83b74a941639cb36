// The glass presets are complete: each sets every value that makes its look, so it gives the same settings
// whatever was chosen before it (physical optics, then the diamond preset, must give the original's
// diamond), and each turns on the original's smooth curvature.
#include "params/schema.h"
#include "params/schema_impl.h"
#include "scenes/glass/input.h"
#include "scenes/glass/settings.h"
#include "scenes/glass/studio.h"

#include <gtest/gtest.h>

namespace vitrine::test {
namespace {

using glass::Settings;

Settings withPreset(Settings start, const std::string& name) {
  const std::string why = params::applyPreset(params::bindSettings(glass::schema(), start), name);
  EXPECT_EQ(why, "") << name;
  return start;
}

std::vector<std::string> presetNames() {
  std::vector<std::string> names;
  for (const auto& preset : glass::schema().presets()) names.push_back(preset.name);
  return names;
}

// Everything a user may have changed that is part of a look: optics, dispersion, curvature, the
// environment and its exposure, the material, the camera, accumulation, the diamond's walk.
const params::KeyValues kElsewhere{
    {"optics", "physical"},   {"dispersion", "sellmeier"}, {"smooth_curvature", "off"}, {"environment", "on"},
    {"panorama", "studio"},   {"exposure", "3"},            {"env_rotation", "2"},       {"material", "sapphire"},
    {"n", "64"},              {"mode", "approx"},           {"jitter", "off"},           {"aa", "taa"},
    {"fov", "90"},            {"projection", "orthographic"}, {"history_alpha", "0.2"},  {"strength", "0.9"},
    {"depth", "1000"},        {"bounces", "32"},            {"diamond_view", "top"},     {"diamond_debug", "tir"},
    {"stop_world", "on"},     {"show_proxy", "on"},
};

TEST(GlassPresets, EachGivesTheSameSettingsWhateverCameBefore) {
  ASSERT_EQ(presetNames().size(), 5u);
  Settings elsewhere;
  ASSERT_EQ(params::applyValues(params::bindSettings(glass::schema(), elsewhere), kElsewhere), "");
  for (const std::string& name : presetNames()) {
    const Settings alone = withPreset(Settings{}, name);
    EXPECT_TRUE(withPreset(elsewhere, name) == alone) << name << " after other values";
    for (const std::string& before : presetNames())
      EXPECT_TRUE(withPreset(withPreset(Settings{}, before), name) == alone) << name << " after " << before;
  }
}

TEST(GlassPresets, PhysicalOpticsThenTheDiamondIsThePresetsSeedDiamond) {
  Settings physical;
  ASSERT_EQ(params::applyValues(params::bindSettings(glass::schema(), physical), {{"optics", "physical"}}), "");
  const Settings diamond = withPreset(physical, "diamond");
  EXPECT_EQ(diamond.optics, glass::Optics::Seed);
  EXPECT_EQ(diamond.dispersion, glass::Dispersion::Abbe);
  EXPECT_EQ(diamond.shape, glass::ShapeKind::Diamond);
  EXPECT_FLOAT_EQ(diamond.ior, 2.418f);
  EXPECT_FLOAT_EQ(diamond.abbe, 55.0f);
  EXPECT_FLOAT_EQ(diamond.strength, glass::kDiamondStrength);
  EXPECT_EQ(diamond.bounces, 6);
  EXPECT_TRUE(diamond.environment);
  EXPECT_EQ(diamond.panorama, glass::kStudioPanorama);
  EXPECT_TRUE(diamond == withPreset(Settings{}, "diamond"));
}

// With jitter on, a lower tier traces fewer wavelengths a frame (the history averages the strata the
// frames take); with jitter off the stratum centres are the picture and stay.
TEST(GlassTiers, LowerTiersTraceFewerJitteredWavelengths) {
  EXPECT_EQ(glass::tierWavelengths(16, Tier::High, true), 16);
  EXPECT_EQ(glass::tierWavelengths(16, Tier::Medium, true), 12);
  EXPECT_EQ(glass::tierWavelengths(16, Tier::Low, true), 8);
  EXPECT_EQ(glass::tierWavelengths(64, Tier::Low, true), 32);
  EXPECT_EQ(glass::tierWavelengths(8, Tier::Low, true), 8) << "never under 8";
  EXPECT_EQ(glass::tierWavelengths(3, Tier::Low, true), 3) << "nor over what is set";
  EXPECT_EQ(glass::tierWavelengths(16, Tier::Low, false), 16) << "fixed strata are the picture";
}

TEST(GlassPresets, AllTurnOnSmoothCurvatureAsTheOriginalsDo) {
  for (const std::string& name : presetNames()) {
    Settings round;
    round.smoothCurvature = false;
    EXPECT_TRUE(withPreset(round, name).smoothCurvature) << name;
  }
  EXPECT_TRUE(Settings{}.smoothCurvature) << "the original's default";
}

// T, S, B and F always do what they say: with pills showing, T shows the diamond from the top.
TEST(GlassKeys, AViewKeyShowsTheDiamond) {
  Settings settings;
  settings.shape = glass::ShapeKind::Pill;
  glass::KeyRequests keys;
  glass::applyDiamondView(keys, settings);
  EXPECT_EQ(settings.shape, glass::ShapeKind::Pill);  // no key, no change
  keys.diamondView = glass::DiamondView::Top;
  glass::applyDiamondView(keys, settings);
  EXPECT_EQ(settings.shape, glass::ShapeKind::Diamond);
  EXPECT_EQ(settings.diamondView, glass::DiamondView::Top);
}

}  // namespace
}  // namespace vitrine::test
