// MIDI clock and MIDI timecode through a real ALSA sequencer: a virtual output port made by RtMidi (as a
// DJ program's clock out is) and Vitrine's MIDI input (src/live/midi_input.h) reading it into the
// clocks (src/host/live_clocks.h). Machines without /dev/snd/seq (containers, CI) skip it, saying why;
// the byte-stream tests (rig_midi_timing_test.cpp) cover the same parsing there.
#include <gtest/gtest.h>

#include <RtMidi.h>

#include <chrono>
#include <filesystem>
#include <thread>
#include <vector>

#include "host/live_clocks.h"
#include "live/midi_input.h"
#include "live/source_bank.h"

namespace vitrine::host {
namespace {

TEST(MidiClockPort, AVirtualClockOutReachesTheClocks) {
  if (!std::filesystem::exists("/dev/snd/seq"))
    GTEST_SKIP() << "no ALSA sequencer (/dev/snd/seq is missing): a virtual MIDI port cannot be made here";
  RtMidiOut out(RtMidi::LINUX_ALSA, "Vitrine test clock");
  out.openVirtualPort("clock out");
  live::MidiInput input(live::MidiInput::Options{.rescanSeconds = 0.0});
  input.poll();
  ASSERT_FALSE(input.ports().empty()) << input.status();
  LiveClocks clocks;
  live::SourceBank sources;
  // Two seconds of 120 BPM clock after a start, each pulse on its own deadline (no drift).
  const auto interval = std::chrono::microseconds(20833);
  auto next = std::chrono::steady_clock::now();
  std::vector<unsigned char> start{0xFA}, pulse{0xF8};
  out.sendMessage(&start);
  for (int i = 0; i < 96; ++i) {
    std::this_thread::sleep_until(next);
    out.sendMessage(&pulse);
    next += interval;
    clocks.midiBytes(input.drainSystem());
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  clocks.midiBytes(input.drainSystem());
  clocks.write(sources, live::MidiInput::clockSeconds());
  const auto statuses = clocks.statuses(live::MidiInput::clockSeconds());
  ASSERT_FALSE(statuses.empty());
  EXPECT_EQ(statuses[0].name, "midi clock");
  ASSERT_TRUE(statuses[0].bpm);
  EXPECT_NEAR(*statuses[0].bpm, 120.0, 0.5);
  EXPECT_NEAR(sources.value("midi.clock.tempo"), 0.5f, 0.003f);
  EXPECT_EQ(sources.value("midi.clock.running"), 1.0f);
}

}  // namespace
}  // namespace vitrine::host
