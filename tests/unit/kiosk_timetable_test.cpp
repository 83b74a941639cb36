// Kiosk mode's timetable: entries turned into scenes and presets, the schedule kept in step with the
// scene the gallery shows, a person's touch told from a cursor at rest. No GPU.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/error.h"
#include "host/gallery/kiosk_timetable.h"

namespace vitrine::host {
namespace {

const SceneInfo& scene(std::string_view name) {
  const SceneInfo* info = findScene(name);
  EXPECT_TRUE(info) << name;
  return *info;
}

// Advances in 0.1 s frames for `seconds`; the last entry a fade began with.
std::optional<size_t> run(KioskTimetable& kiosk, double seconds, bool touched = false) {
  std::optional<size_t> begun;
  for (int frame = 0; frame < int(seconds * 10.0 + 0.5); ++frame)
    if (const auto plan = kiosk.advance(0.1, touched); plan.begin) begun = plan.begin;
  return begun;
}

TEST(KioskTimetable, WithoutAPlaylistEveryRegisteredSceneTakesItsTurnFromTheFirst) {
  const auto scenes = sceneRegistry();
  ASSERT_GE(scenes.size(), 3u);
  KioskTimetable kiosk({}, scenes[1], 10.0);
  EXPECT_FALSE(kiosk.playlist());
  EXPECT_EQ(kiosk.entries(), scenes.size());
  EXPECT_EQ(kiosk.current(), 1u);
  EXPECT_FALSE(run(kiosk, 9.8));
  const auto begun = run(kiosk, 0.4);
  ASSERT_TRUE(begun);
  EXPECT_EQ(&kiosk.sceneOf(*begun), &scenes[2]);
  EXPECT_EQ(kiosk.presetOf(*begun, scenes[2].name), nullptr);  // no playlist, no preset
}

TEST(KioskTimetable, APlaylistsLinesAreItsEntriesWithTheirPresetsAndDwells) {
  KioskTimetable kiosk({{"kifs", "sphere", 5.0}, {"noodles", "", 40.0}, {"kifs", "final", 40.0}}, scene("kifs"), 45.0);
  EXPECT_TRUE(kiosk.playlist());
  ASSERT_EQ(kiosk.entries(), 3u);
  EXPECT_EQ(&kiosk.sceneOf(1), &scene("noodles"));
  EXPECT_EQ(&kiosk.sceneOf(2), &scene("kifs"));
  ASSERT_TRUE(kiosk.presetOf(2, "kifs"));
  EXPECT_EQ(kiosk.presetOf(2, "kifs")->preset, "final");
  EXPECT_EQ(kiosk.presetOf(1, "noodles"), nullptr);  // a line without a preset
  EXPECT_EQ(kiosk.presetOf(0, "noodles"), nullptr);  // another scene started for the entry: not its preset
  EXPECT_EQ(run(kiosk, 5.2), 1u);  // the first line's own dwell, not --dwell's
  // The idle time follows the shortest dwell (10 s at least): after a touch, 10 s alone and the dwell.
  run(kiosk, 3.0);
  run(kiosk, 1.0, /*touched=*/true);
  EXPECT_FALSE(run(kiosk, 49.8));
  EXPECT_EQ(run(kiosk, 0.4), 2u);
}

TEST(KioskTimetable, AChosenSceneBecomesItsEntryTheOneShowingWhenItIsThatScenes) {
  KioskTimetable kiosk({{"kifs", "sphere", 5.0}, {"noodles", "", 40.0}, {"kifs", "final", 40.0}}, scene("kifs"), 45.0);
  EXPECT_EQ(kiosk.showing(scene("noodles")), 1u);
  EXPECT_EQ(kiosk.current(), 1u);
  EXPECT_EQ(kiosk.showing(scene("kifs")), 0u);  // the scene's first line
  run(kiosk, 5.2);
  run(kiosk, 2.0);
  ASSERT_EQ(kiosk.current(), 1u);
  run(kiosk, 40.0 + 2.2);
  ASSERT_EQ(kiosk.current(), 2u);
  EXPECT_EQ(kiosk.showing(scene("kifs")), 2u);  // a restart of the line showing keeps that line
}

TEST(KioskTimetable, ASceneThatFailsIsSkippedInEveryEntryOfIt) {
  KioskTimetable kiosk({{"kifs", "", 5.0}, {"noodles", "", 5.0}, {"kifs", "final", 5.0}, {"bloom", "", 5.0}},
                       scene("kifs"), 45.0);
  EXPECT_EQ(&kiosk.failed(scene("kifs")), &scene("noodles"));
  EXPECT_EQ(kiosk.current(), 1u);
  EXPECT_EQ(run(kiosk, 5.2), 3u);  // line 2 is kifs too: skipped
}

TEST(KioskTimetable, WhenTheOnlySceneFailsItIsTheOneLeft) {
  KioskTimetable kiosk({{"kifs", "", 5.0}}, scene("kifs"), 45.0);
  EXPECT_EQ(&kiosk.failed(scene("kifs")), &scene("kifs"));  // the gallery gives up and the kiosk restarts
}

TEST(KioskTimetable, ATouchIsAMovedMouseAClickAScrollOrAKeyNotACursorAtRest) {
  KioskTimetable kiosk({}, sceneRegistry().front(), 45.0);
  Pointer resting;
  resting.inside = true;
  resting.pixels = {100.0f, 50.0f};
  kiosk.rest(resting);
  EXPECT_FALSE(kiosk.touched(resting, false));
  Pointer nudged = resting;
  nudged.pixels.x += 2.0f;  // a hand on the desk, not a visitor
  EXPECT_FALSE(kiosk.touched(nudged, false));
  Pointer moved = nudged;
  moved.pixels.y += 10.0f;
  EXPECT_TRUE(kiosk.touched(moved, false));
  Pointer outside = moved;
  outside.inside = false;
  outside.pixels = {900.0f, 900.0f};  // elsewhere on the desktop
  EXPECT_FALSE(kiosk.touched(outside, false));
  Pointer clicked = outside;
  clicked.leftPressed = true;
  EXPECT_TRUE(kiosk.touched(clicked, false));
  Pointer scrolled = outside;
  scrolled.wheel = -1.0f;
  EXPECT_TRUE(kiosk.touched(scrolled, false));
  EXPECT_TRUE(kiosk.touched(outside, /*keysOrDrops=*/true));
}

TEST(KioskTimetable, APlaylistLineNamingASceneThisBuildLacksIsRefused) {
  EXPECT_THROW(KioskTimetable({{"kifs", "", 5.0}, {"nope", "", 5.0}}, scene("kifs"), 45.0), Error);
}

}  // namespace
}  // namespace vitrine::host
