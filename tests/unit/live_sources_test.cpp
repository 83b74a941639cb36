// The live sources' table: values clamped, LFOs from the time, and a bounded number of names however
// many a client invents (/vitrine/mod/<name> in a loop), without losing the ones mappings read.
#include "live/source_bank.h"

#include <gtest/gtest.h>

#include <string>

namespace vitrine::live {
namespace {

TEST(LiveSources, ValuesAreClampedAndUnknownNamesReadZero) {
  SourceBank bank;
  bank.set("osc.fader", 2.0f);
  EXPECT_EQ(bank.value("osc.fader"), 1.0f);
  EXPECT_EQ(bank.value("osc.nobody"), 0.0f);
}

TEST(LiveSources, AFloodOfNewNamesKeepsTheTableBoundedAndTheMappedNames) {
  SourceBank bank;
  bank.set("osc.mapped", 0.25f);
  EXPECT_EQ(bank.value("osc.mapped"), 0.25f);  // a mapping reads it every step
  bank.set("osc.recent", 0.5f);
  for (int i = 0; i < 100000; ++i) bank.set("osc.flood" + std::to_string(i), 0.5f);
  EXPECT_LE(bank.values().size(), 4096u);
  EXPECT_EQ(bank.value("osc.mapped"), 0.25f);
  EXPECT_EQ(bank.value("osc.flood99999"), 0.5f);  // the newest names are there
  EXPECT_EQ(bank.value("osc.flood0"), 0.0f);       // the oldest unread ones made room
  EXPECT_EQ(bank.value("osc.recent"), 0.0f);
}

}  // namespace
}  // namespace vitrine::live
