// The guard against changes that would freeze the window: asked about only when the change both
// multiplies the work and would make frames take seconds here.
#include <gtest/gtest.h>

#include "host/cost_guard.h"

namespace vitrine::host {
namespace {

TEST(CostGuard, AsksOnlyWhenAFrameWouldTakeSeconds) {
  EXPECT_EQ(freezeWarning(64.0, 2.0), "");   // 128 ms a frame: slow, not frozen
  EXPECT_EQ(freezeWarning(1.5, 1200.0), "");  // already slow, hardly slower
  const std::string why = freezeWarning(64.0, 50.0);  // 3.2 s a frame
  EXPECT_NE(why.find("about 64 times the work: about 3.2 s a frame"), std::string::npos) << why;
}

}  // namespace
}  // namespace vitrine::host
