// Kiosk mode's timetable: dwell, cross-fade, a touch holding the scene, idle resumption, failures.
#include <gtest/gtest.h>

#include "host/gallery/kiosk.h"

namespace vitrine::host {
namespace {

constexpr KioskTiming kTiming{10.0, 2.0, 5.0};

// Advances in 0.1 s frames for `seconds`, collecting what was planned.
struct Plans {
  int begins = 0, finishes = 0;
  std::optional<size_t> lastBegun;
  std::optional<float> lastFade;
};
Plans run(KioskSchedule& kiosk, double seconds, bool touched = false) {
  Plans r;
  for (int frame = 0; frame < int(seconds * 10.0 + 0.5); ++frame) {
    const auto plan = kiosk.advance(0.1, touched);
    if (plan.begin) ++r.begins, r.lastBegun = plan.begin;
    if (plan.finish) ++r.finishes;
    if (plan.fade) r.lastFade = plan.fade;
  }
  return r;
}

TEST(Kiosk, EachSceneDwellsThenTheNextFadesIn) {
  KioskSchedule kiosk(3, 1, kTiming);
  EXPECT_EQ(run(kiosk, 9.8).begins, 0);  // the first dwell, no touch yet: cycling from the start
  const Plans fade = run(kiosk, 1.0);
  EXPECT_EQ(fade.begins, 1);
  EXPECT_EQ(fade.lastBegun, 2u);
  EXPECT_EQ(kiosk.incoming(), 2u);
  ASSERT_TRUE(fade.lastFade);
  EXPECT_GT(*fade.lastFade, 0.3f);
  EXPECT_LT(*fade.lastFade, 0.6f);
  EXPECT_EQ(run(kiosk, 1.4).finishes, 1);  // two seconds of fade in all
  EXPECT_EQ(kiosk.current(), 2u);
  EXPECT_FALSE(kiosk.incoming());
  run(kiosk, 12.2);
  EXPECT_EQ(kiosk.current(), 0u);  // wraps around after the last scene
}

TEST(Kiosk, ATouchHoldsTheSceneUntilNobodyTouchesForTheIdleTime) {
  KioskSchedule kiosk(3, 0, kTiming);
  run(kiosk, 8.0);
  run(kiosk, 20.0, /*touched=*/true);  // played with for twenty seconds: no fade
  EXPECT_EQ(kiosk.current(), 0u);
  EXPECT_FALSE(kiosk.incoming());
  EXPECT_EQ(run(kiosk, 14.9).begins, 0);  // 5 s idle + 10 s dwell from the last touch
  EXPECT_EQ(run(kiosk, 0.2).begins, 1);
}

TEST(Kiosk, ATouchDuringAFadeCompletesIt) {
  KioskSchedule kiosk(2, 0, kTiming);
  run(kiosk, 10.5);
  ASSERT_EQ(kiosk.incoming(), 1u);
  EXPECT_TRUE(kiosk.advance(0.1, true).finish);
  EXPECT_EQ(kiosk.current(), 1u);
}

TEST(Kiosk, FailedScenesAreSkippedAndTheKioskNeverRunsOut) {
  KioskSchedule kiosk(3, 0, kTiming);
  kiosk.failed(1);
  run(kiosk, 12.5);
  EXPECT_EQ(kiosk.current(), 2u);  // 1 skipped
  kiosk.failed(2);  // the current one fails: the next that works takes over
  EXPECT_EQ(kiosk.current(), 0u);
  kiosk.failed(0);  // all failed: every scene is tried again
  EXPECT_EQ(kiosk.current(), 1u);
  run(kiosk, 12.5);
  EXPECT_EQ(kiosk.current(), 2u);
}

TEST(Kiosk, AFailedIncomingSceneEndsItsFade) {
  KioskSchedule kiosk(3, 0, kTiming);
  run(kiosk, 10.5);
  ASSERT_EQ(kiosk.incoming(), 1u);
  kiosk.failed(1);
  EXPECT_FALSE(kiosk.incoming());
  EXPECT_EQ(kiosk.current(), 0u);
  EXPECT_EQ(run(kiosk, 10.5).lastBegun, 2u);
}

TEST(Kiosk, APlaylistShowsEachEntryForItsOwnDwell) {
  KioskSchedule kiosk(std::vector<double>{3.0, 20.0, 6.0}, 0, kTiming);
  EXPECT_EQ(run(kiosk, 2.9).begins, 0);
  EXPECT_EQ(run(kiosk, 0.2).lastBegun, 1u);  // after 3 s, not kTiming's 10
  run(kiosk, 2.0);
  EXPECT_EQ(kiosk.current(), 1u);
  EXPECT_EQ(run(kiosk, 19.8).begins, 0);  // entry 1 dwells 20 s
  EXPECT_EQ(run(kiosk, 0.3).lastBegun, 2u);
  run(kiosk, 2.0 + 6.1);
  EXPECT_EQ(kiosk.incoming(), 0u);  // and round again after entry 2's 6 s
}

TEST(Kiosk, APlaylistSkipsAFailedEntryAndStillHoldsOnATouch) {
  KioskSchedule kiosk(std::vector<double>{3.0, 3.0, 3.0}, 0, kTiming);
  kiosk.failed(1);
  run(kiosk, 3.1);
  EXPECT_EQ(kiosk.incoming(), 2u);
  run(kiosk, 2.0);
  run(kiosk, 30.0, /*touched=*/true);
  EXPECT_EQ(kiosk.current(), 2u);  // held
  EXPECT_EQ(run(kiosk, 7.9).begins, 0);  // 5 s idle + 3 s dwell
  EXPECT_EQ(run(kiosk, 0.2).lastBegun, 0u);
}

TEST(Kiosk, OneSceneNeverFades) {
  KioskSchedule kiosk(1, 0, kTiming);
  EXPECT_EQ(run(kiosk, 100.0).begins, 0);
}

// The restart pause doubles while failures repeat, stops at a minute, and starts again from a second
// after a gallery that ran for ten minutes.
TEST(KioskRestartPause, DoublesWhileFailuresRepeatAndForgetsThemAfterAHealthyRun) {
  using std::chrono::seconds;
  KioskRestartPause pauses;
  std::vector<long> quick;
  for (int i = 0; i < 8; ++i) quick.push_back(long(pauses.after(seconds(30)).count()));
  EXPECT_EQ(quick, (std::vector<long>{1, 2, 4, 8, 16, 32, 60, 60}));
  EXPECT_EQ(pauses.after(seconds(3 * 24 * 3600)), seconds(1)) << "days after the last failure";
  EXPECT_EQ(pauses.after(seconds(5)), seconds(2));
  EXPECT_EQ(pauses.after(KioskRestartPause::kSettled), seconds(1));
}

}  // namespace
}  // namespace vitrine::host
