#include "rig/rig_report.h"

#include <gtest/gtest.h>

namespace vitrine::rig {

TEST(RigReport, ClockLineSaysLockTempoTimeAndJitter) {
  ClockStatus link{.name = "link", .locked = true, .bpm = 128.04, .jitterMs = 0.37, .note = "2 peers"};
  EXPECT_EQ(describeClock(link), (RigLine{"link", true, "locked 128.0 BPM, jitter 0.37 ms, 2 peers"}));
  ClockStatus ltc{.name = "ltc", .locked = false, .timecode = "01:00:00:00", .note = "lost 3 s ago: own clock"};
  EXPECT_EQ(describeClock(ltc), (RigLine{"ltc", false, "not locked 01:00:00:00, lost 3 s ago: own clock"}));
}

TEST(RigReport, OutputIsWellWhileTakenAndDroppingLittle) {
  const RigLine fine = describeOutput({"pipewire", "vitrine", "obs 1920x1080 BGRx", 1000, 10, true});
  EXPECT_TRUE(fine.ok);
  EXPECT_EQ(fine.name, "pipewire vitrine");
  EXPECT_EQ(fine.text, "obs 1920x1080 BGRx, 1000 frames, 10 dropped (1.0 %)");
  EXPECT_FALSE(describeOutput({"pipewire", "vitrine", "", 500, 500, true}).ok);  // half of them dropped
  const RigLine gone = describeOutput({"stream", "srt://a:9000", "", 0, 0, false});
  EXPECT_FALSE(gone.ok);
  EXPECT_EQ(gone.text, "nobody taking frames, 0 frames");
  EXPECT_EQ(describeOutput({"stream", "stream", "", 1, 0, true}).name, "stream");  // not "stream stream"
}

TEST(RigReport, TimecodeLabelsWholeFrames) {
  EXPECT_EQ(formatTimecode(0.0, 25.0), "00:00:00:00");
  EXPECT_EQ(formatTimecode(3723.0 + 4.0 / 25.0, 25.0), "01:02:03:04");
  EXPECT_EQ(formatTimecode(1.0 - 1e-9, 24.0), "00:00:01:00");  // a hair under a second is that second's first frame
  EXPECT_EQ(formatTimecode(-5.0, 30.0), "00:00:00:00");
}

TEST(RigReport, DropFrameSkipsTwoLabelsAMinuteButEachTenth) {
  const double fps = 30000.0 / 1001.0;
  EXPECT_EQ(formatTimecode(1799.0 / fps, fps), "00:00:59;29");
  EXPECT_EQ(formatTimecode(1800.0 / fps, fps), "00:01:00;02");  // ;00 and ;01 do not exist
  EXPECT_EQ(formatTimecode(17982.0 / fps, fps), "00:10:00;00");  // every tenth minute keeps them
  EXPECT_EQ(formatTimecode(107892.0 / fps, fps), "01:00:00;00");  // an hour of labels is an hour of frames
}

}  // namespace vitrine::rig
