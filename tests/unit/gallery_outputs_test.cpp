// The gallery's outputs with no GPU: outputs of a kind that draws nothing stand for windows. Numbering
// and names, the pins the settings file keeps, and projector setup going round the outputs, keeping a
// pin in the settings (and the main window's in --output-warp's file) or putting it back.
#include <gtest/gtest.h>

#include <GLFW/glfw3.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "host/gallery/gallery_outputs.h"
#include "host/present/output_warp_file.h"
#include "support/temp_folder.h"

namespace vitrine::host {
namespace {

constexpr VkExtent2D kMainWindow{640, 360};

// An output that takes no frames: what the outputs room sees of any kind of output but the drawing.
class QuietOutput final : public Output {
 public:
  QuietOutput(std::string name, VkExtent2D extent, const maths::OutputWarp& warp = {})
      : Output(std::move(name), warp), extent_(extent) {}
  VkExtent2D extent() const override { return extent_; }
  bool acquire(uint32_t, bool) override { return false; }
  BlitDestination destination(VkPipelineStageFlags2) const override { return {}; }
  std::pair<VkSemaphore, VkSemaphore> semaphores(uint32_t) const override { return {}; }
  void present() override {}

 private:
  VkExtent2D extent_;
};

// A device that draws any frame, or none above `largest` pixels a side.
GalleryOutputs::FrameCheck drawsUpTo(uint32_t largest) {
  return [largest](VkExtent2D extent, const maths::OutputWarp& warp, std::string_view where) {
    const VkExtent2D frame = frameExtent(extent, &warp);
    if (frame.width > largest || frame.height > largest) throw Error(fmt::format("{}: too large", where));
  };
}

maths::OutputWarp regionOf(float x0, float x1) {
  maths::OutputWarp warp;
  warp.region = {x0, 0.0f, x1, 1.0f};
  return warp;
}

class GalleryOutputsTest : public test::TempFolderTest {
 protected:
  std::filesystem::path settingsPath() const { return folder_ / "settings.json"; }
};

TEST_F(GalleryOutputsTest, TheMainWindowIsOutputZeroAndTheOthersFollowInOrder) {
  GallerySettings settings(settingsPath(), false);
  GalleryOutputs outputs(settings, drawsUpTo(16384), "", std::nullopt, kMainWindow);
  outputs.add(std::make_unique<QuietOutput>("left", VkExtent2D{800, 600}), false, "outputs.json, output 1");
  outputs.add(std::make_unique<QuietOutput>("right", VkExtent2D{1024, 768}, regionOf(0.5f, 1.0f)), true, "output 2");
  EXPECT_EQ(outputs.count(), 3u);
  EXPECT_EQ(outputs.name(0), "main");
  EXPECT_EQ(outputs.name(2), "right");
  EXPECT_EQ(outputs.extent(0, kMainWindow).width, 640u);
  EXPECT_EQ(outputs.extent(1, kMainWindow).width, 800u);
  EXPECT_EQ(outputs.shownWarp(), nullptr);  // no warp anywhere for the main window: the whole frame
  EXPECT_FLOAT_EQ(outputs.warpOf(2).region[0], 0.5f);  // the warp it brought
  EXPECT_TRUE(outputs.warpOf(1).isIdentity());
}

TEST_F(GalleryOutputsTest, AnOutputWithoutAWarpShowsThePinTheSettingsKeepUnlessTheDeviceCannotDrawIt) {
  {
    GallerySettings settings(settingsPath(), false);
    settings.setWarp("left", outputWarpToJson(regionOf(0.0f, 0.5f)), GallerySettings::Clock::now());
    settings.setWarp("main", outputWarpToJson(regionOf(0.25f, 0.75f)), GallerySettings::Clock::now());
    // A region a thousandth of the frame wide asks for a frame a thousand outputs wide.
    settings.setWarp("tiny", outputWarpToJson(regionOf(0.0f, 0.001f)), GallerySettings::Clock::now());
  }
  GallerySettings settings(settingsPath(), false);
  GalleryOutputs outputs(settings, drawsUpTo(16384), "", std::nullopt, kMainWindow);
  outputs.add(std::make_unique<QuietOutput>("left", VkExtent2D{800, 600}), false, "output 1");
  outputs.add(std::make_unique<QuietOutput>("tiny", VkExtent2D{800, 600}), false, "output 2");
  ASSERT_NE(outputs.shownWarp(), nullptr);
  EXPECT_FLOAT_EQ(outputs.shownWarp()->region[0], 0.25f);
  EXPECT_FLOAT_EQ(outputs.warpOf(1).region[2], 0.5f);
  EXPECT_TRUE(outputs.warpOf(2).isIdentity()) << "a pin the device cannot draw: the whole frame";
  // A warp given on the command line wins over the settings file, and one past the device is refused.
  GalleryOutputs given(settings, drawsUpTo(16384), "pin.json", regionOf(0.0f, 1.0f), kMainWindow);
  EXPECT_FLOAT_EQ(given.shownWarp()->region[0], 0.0f);
  EXPECT_THROW(GalleryOutputs(settings, drawsUpTo(1000), "pin.json", regionOf(0.0f, 0.5f), kMainWindow), Error);
  EXPECT_THROW(outputs.add(std::make_unique<QuietOutput>("wide", VkExtent2D{800, 600}, regionOf(0.0f, 0.001f)), true,
                           "output 3"),
               Error);
}

TEST_F(GalleryOutputsTest, SetupGoesRoundTheOutputsKeepingEachPin) {
  const auto warpFile = folder_ / "pin.json";
  GallerySettings settings(settingsPath(), false);
  GalleryOutputs outputs(settings, drawsUpTo(16384), warpFile.string(), std::nullopt, kMainWindow);
  outputs.add(std::make_unique<QuietOutput>("right", VkExtent2D{1000, 500}), false, "output 1");
  EXPECT_FALSE(outputs.setupKey(GLFW_KEY_RIGHT, true, kMainWindow).used) << "not in setup";
  outputs.startSetup();
  ASSERT_TRUE(outputs.setupActive());
  EXPECT_EQ(outputs.setupNewlyShown(false), std::nullopt) << "the card is not built yet";
  EXPECT_EQ(outputs.setupNewlyShown(true), "main");
  EXPECT_EQ(outputs.setupNewlyShown(true), std::nullopt) << "said once";
  EXPECT_FALSE(outputs.setupKey(GLFW_KEY_A, false, kMainWindow).used);
  const GalleryOutputs::SetupKey nudge = outputs.setupKey(GLFW_KEY_RIGHT, true, kMainWindow);  // ten pixels right
  EXPECT_TRUE(nudge.used);
  EXPECT_FALSE(nudge.ended);
  EXPECT_NEAR(outputs.warpOf(0).corners[0].x, 10.0f / 640.0f, 1e-6f);

  const GalleryOutputs::SetupKey next = outputs.setupKey(GLFW_KEY_F7, false, kMainWindow);  // keep it, on to "right"
  EXPECT_FALSE(next.ended);
  EXPECT_EQ(next.note, "projector setup of main kept in " + warpFile.string() + " and the settings");
  EXPECT_NEAR(readOutputWarp(warpFile).corners[0].x, 10.0f / 640.0f, 1e-6f);
  ASSERT_NE(settings.warpFor("main"), nullptr);
  EXPECT_EQ(outputs.shownWarp(), &outputs.warpOf(1)) << "the main window shows what the output set up shows";
  EXPECT_EQ(outputs.setupNewlyShown(true), "right");

  outputs.setupKey(GLFW_KEY_RIGHT, false, kMainWindow);  // one pixel of the output's thousand
  EXPECT_NEAR(outputs.warpOf(1).corners[0].x, 0.001f, 1e-6f);
  const GalleryOutputs::SetupKey kept = outputs.setupKey(GLFW_KEY_ENTER, false, kMainWindow);
  EXPECT_TRUE(kept.ended);
  EXPECT_EQ(kept.note, "projector setup of right kept in the settings");
  EXPECT_NE(settings.warpFor("right"), nullptr);
  EXPECT_FALSE(outputs.setupActive());
  EXPECT_NE(outputs.shownWarp(), &outputs.warpOf(1));
  EXPECT_EQ(outputs.setupNewlyShown(true), std::nullopt);
}

TEST_F(GalleryOutputsTest, EscapePutsThePinBackAndKeepsNothing) {
  GallerySettings settings(settingsPath(), false);
  GalleryOutputs outputs(settings, drawsUpTo(16384), "", std::nullopt, kMainWindow);
  outputs.startSetup();
  outputs.setupKey(GLFW_KEY_DOWN, true, kMainWindow);
  EXPECT_FALSE(outputs.warpOf(0).isIdentity());
  const GalleryOutputs::SetupKey undone = outputs.setupKey(GLFW_KEY_ESCAPE, false, kMainWindow);
  EXPECT_TRUE(undone.used);
  EXPECT_TRUE(undone.ended);
  EXPECT_EQ(undone.note, "projector setup of main undone");
  EXPECT_TRUE(outputs.warpOf(0).isIdentity());
  EXPECT_EQ(settings.warpFor("main"), nullptr);
}

}  // namespace
}  // namespace vitrine::host
