// Live MIDI input: Standard MIDI Files read and written (src/live/smf.h), their player, and the
// device input without a MIDI system (src/live/midi_input.h).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>
#include <vector>

#include "core/error.h"
#include "live/midi_input.h"
#include "live/smf.h"
#include "support/temp_folder.h"

namespace vitrine::live {
namespace {

using Bytes = std::vector<uint8_t>;

void append(Bytes& out, std::initializer_list<uint8_t> bytes) { out.insert(out.end(), bytes); }

void appendChunk(Bytes& out, const char* type, const Bytes& data) {
  out.insert(out.end(), type, type + 4);
  const auto n = uint32_t(data.size());
  append(out, {uint8_t(n >> 24), uint8_t(n >> 16), uint8_t(n >> 8), uint8_t(n)});
  out.insert(out.end(), data.begin(), data.end());
}

Bytes header(uint16_t format, uint16_t tracks, uint16_t division) {
  Bytes out;
  appendChunk(out, "MThd",
              {uint8_t(format >> 8), uint8_t(format), uint8_t(tracks >> 8), uint8_t(tracks), uint8_t(division >> 8),
               uint8_t(division)});
  return out;
}

// A format-0 file of one track holding `events` (delta times included), at 96 ticks per quarter.
Bytes oneTrack(const Bytes& events) {
  Bytes file = header(0, 1, 96);
  appendChunk(file, "MTrk", events);
  return file;
}

std::string errorOf(const Bytes& bytes) {
  try {
    parseSmf(bytes, "t.mid");
  } catch (const Error& error) {
    return error.what();
  }
  return "(no error)";
}

MidiMessage message(double time, uint8_t status, uint8_t data1, uint8_t data2 = 0) {
  return {time, status, data1, data2};
}

TEST(LiveMidiMessage, NamesChannelAndType) {
  const MidiMessage m = message(0.0, 0x9F, 60, 100);
  EXPECT_EQ(m.channel(), 16);
  EXPECT_EQ(m.type(), 0x90);
  EXPECT_EQ(message(0.0, 0xB0, 1).channel(), 1);
  EXPECT_EQ(midiDataBytes(0xC3), 1);
  EXPECT_EQ(midiDataBytes(0xE0), 2);
  EXPECT_EQ(midiDataBytes(0xF8), 0);
}

TEST(LiveMidiSmf, WrittenMessagesReadBackWithinHalfATick) {
  // Several channels, note on/off (velocity 0 too), CCs, a program change and a pitch bend, given out of order.
  const std::vector<MidiMessage> written = {
      message(1.2345, 0x80, 60, 64), message(0.0, 0x90, 60, 100), message(0.3333, 0xB3, 7, 127),
      message(0.3333, 0xB3, 10, 0),  message(0.75, 0x9F, 72, 0),  message(0.5001, 0xC9, 5),
      message(2.0, 0xE1, 0, 64),     message(0.1, 0xB0, 1, 33),
  };
  const int ppq = 96;
  const double bpm = 90.0;
  const Bytes file = writeSmf(written, ppq, bpm);
  const MidiSequence read = parseSmf(file, "round.mid");

  std::vector<MidiMessage> expected = written;
  std::stable_sort(expected.begin(), expected.end(), [](auto& a, auto& b) { return a.time < b.time; });
  const double halfTick = 60.0 / bpm / ppq / 2.0;
  ASSERT_EQ(read.messages.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_NEAR(read.messages[i].time, expected[i].time, halfTick);
    EXPECT_EQ(read.messages[i].status, expected[i].status);
    EXPECT_EQ(read.messages[i].data1, expected[i].data1);
    EXPECT_EQ(read.messages[i].data2, expected[i].data2);
  }
  EXPECT_NEAR(read.seconds, 2.0, halfTick);
}

TEST(LiveMidiSmf, WriteRefusesWhatAFileCannotHold) {
  const auto refuses = [](std::vector<MidiMessage> messages, int ppq = 480, double bpm = 120.0) {
    EXPECT_THROW(writeSmf(messages, ppq, bpm), Error);
  };
  refuses({message(0.0, 0xF8, 0)});
  refuses({message(0.0, 0x90, 0x80, 1)});
  refuses({message(-1.0, 0x90, 60, 1)});
  refuses({message(NAN, 0x90, 60, 1)});
  refuses({}, 0);
  refuses({}, 480, 0.0);
  refuses({message(1e9, 0x90, 60, 1)});  // a gap no delta time holds
  EXPECT_NO_THROW(writeSmf({}));
}

// Format 1, 96 ticks per quarter. Track 0 sets 120 BPM, then 240 BPM at tick 192 (1 s), and changes
// program there; track 1 plays with running status, also across a text meta event and a sysex.
Bytes handBuiltFormat1() {
  Bytes file = header(1, 2, 96);
  appendChunk(file, "MTrk", {0x00, 0xFF, 0x51, 0x03, 0x07, 0xA1, 0x20,        // 500000 µs per quarter
                             0x81, 0x40, 0xFF, 0x51, 0x03, 0x03, 0xD0, 0x90,  // delta 192: 250000 µs per quarter
                             0x00, 0xC0, 0x05,                                // program change, channel 1
                             0x00, 0xFF, 0x2F, 0x00});
  appendChunk(file, "XFIH", {1, 2, 3});                                // an unknown chunk between tracks: skipped
  appendChunk(file, "MTrk", {0x00, 0x90, 0x3C, 0x64,                   // tick 0: note on C4
                             0x60, 0x3C, 0x00,                         // tick 96: running status, velocity 0
                             0x00, 0xB1, 0x07, 0x7F,                   // tick 96: CC 7 on channel 2
                             0x60, 0x08, 0x40,                         // tick 192: running status CC 8
                             0x00, 0xFF, 0x01, 0x03, 'a',  'b',  'c',  // a text event
                             0x30, 0x90, 0x40, 0x50,                   // tick 240: note on E4
                             0x00, 0xF0, 0x03, 0x7E, 0x7F, 0xF7,       // a sysex
                             0x30, 0x40, 0x00,                         // tick 288: running status after the sysex
                             0x60, 0xFF, 0x2F, 0x00});                 // tick 384: end of track
  return file;
}

TEST(LiveMidiSmf, Format1TracksMergeThroughTheTempoMap) {
  const MidiSequence sequence = parseSmf(handBuiltFormat1(), "hand.mid");
  const std::vector<MidiMessage> expected = {
      message(0.0, 0x90, 0x3C, 0x64),  message(0.5, 0x90, 0x3C, 0x00), message(0.5, 0xB1, 0x07, 0x7F),
      message(1.0, 0xC0, 0x05),        message(1.0, 0xB1, 0x08, 0x40), message(1.125, 0x90, 0x40, 0x50),
      message(1.25, 0x90, 0x40, 0x00),
  };
  EXPECT_EQ(sequence.messages, expected);
  EXPECT_EQ(sequence.seconds, 1.5);
}

TEST(LiveMidiSmf, SmpteDivisionCountsTicksInFrames) {
  // -25 frames per second x 40 ticks per frame: 1000 ticks a second, whatever the tempo says.
  Bytes file = header(0, 1, 0xE728);
  appendChunk(file, "MTrk",
              {0x00, 0xFF, 0x51, 0x03, 0x03, 0xD0, 0x90, 0x83, 0x74, 0x90, 0x3C, 0x64, 0x83, 0x74, 0xFF, 0x2F, 0x00});
  const MidiSequence sequence = parseSmf(file, "smpte.mid");
  ASSERT_EQ(sequence.messages.size(), 1u);
  EXPECT_DOUBLE_EQ(sequence.messages[0].time, 0.5);
  EXPECT_DOUBLE_EQ(sequence.seconds, 1.0);
}

TEST(LiveMidiSmf, MalformedFilesAreRefusedWithFileAndOffset) {
  const Bytes good = writeSmf(std::vector{message(0.0, 0x90, 60, 100), message(1.0, 0x80, 60, 0)});

  EXPECT_EQ(errorOf({}), "t.mid: byte 0: the file is empty, not a Standard MIDI File.");
  EXPECT_EQ(errorOf(Bytes(good.begin(), good.begin() + 10)),
            "t.mid: byte 4: the header chunk claims 6 bytes, only 2 remain in the file.");
  EXPECT_EQ(errorOf(Bytes(good.begin(), good.end() - 3)),
            "t.mid: byte 18: the \"MTrk\" chunk claims 20 bytes, only 17 remain in the file.");
  EXPECT_EQ(errorOf(Bytes(good.begin(), good.begin() + 14)),
            "t.mid: byte 14: the file ends after 0 of the 1 tracks its header announces.");
  EXPECT_EQ(errorOf(oneTrack({0x00, 0x90, 0x3C})), "t.mid: byte 25: the track ends inside a note on message.");

  Bytes riff = good;
  riff[0] = 'R', riff[1] = 'I', riff[2] = 'F', riff[3] = 'F';
  EXPECT_EQ(errorOf(riff), "t.mid: byte 0: the file does not start with \"MThd\": it is not a Standard MIDI File.");

  EXPECT_EQ(errorOf(oneTrack({0x81, 0x81, 0x81, 0x81, 0x00, 0x90, 0x3C, 0x64})),
            "t.mid: byte 22: a variable-length number in an event's delta time runs over 4 bytes, the most the "
            "standard allows.");
  EXPECT_EQ(errorOf(oneTrack({0x00, 0x3C, 0x40})),
            "t.mid: byte 23: a data byte (0x3C) where a status byte is needed, with no earlier channel message "
            "whose status it could reuse (running status).");
  EXPECT_EQ(errorOf(oneTrack({0x00, 0x90, 0x3C, 0x94})),
            "t.mid: byte 25: a status byte (0x94) where a data byte of a note on message is needed.");
  EXPECT_EQ(errorOf(oneTrack({0x00, 0xF2, 0x00, 0x00})),
            "t.mid: byte 23: status byte 0xF2 is a system message, which a MIDI file cannot hold (only channel "
            "messages, sysex 0xF0/0xF7 and meta 0xFF).");
  EXPECT_EQ(errorOf(oneTrack({0x00, 0xFF, 0x01, 0x10, 'a'})),
            "t.mid: byte 23: a meta event (type 0x01) claims 16 bytes, only 1 remain in the track.");
  EXPECT_EQ(errorOf(oneTrack({0x00, 0xFF, 0x51, 0x02, 0x01, 0x02})),
            "t.mid: byte 23: a tempo event of 2 bytes; a tempo is 3 bytes (µs per quarter note).");

  Bytes format2 = header(2, 1, 96);
  appendChunk(format2, "MTrk", {0x00, 0xFF, 0x2F, 0x00});
  EXPECT_EQ(errorOf(format2),
            "t.mid: byte 8: format 2 (independent sequences, one per track) is not supported; Vitrine plays formats "
            "0 and 1.");
  EXPECT_EQ(errorOf(header(0, 2, 96)), "t.mid: byte 10: a format-0 file holds one track, but the header announces 2.");
  EXPECT_EQ(errorOf(header(1, 1, 0)), "t.mid: byte 12: a division of 0 ticks per quarter note.");
  EXPECT_EQ(errorOf(header(1, 1, 0xE628)),
            "t.mid: byte 12: an SMPTE division of -26 frames per second; the standard has -24, -25, -29 and -30.");
}

TEST(LiveMidiSmf, TooManyEventsAreRefused) {
  // Two bytes an event (a delta and a running-status program change): just over the limit.
  Bytes events = {0x00, 0xC0, 0x01};
  events.resize(3 + 2 * kSmfMaxEvents, 0x00);
  const std::string error = errorOf(oneTrack(events));
  EXPECT_TRUE(error.starts_with("t.mid: byte 2000023: the file holds over 1000000 events")) << error;
}

class LiveMidiFile : public test::TempFolderTest {};

TEST_F(LiveMidiFile, ReadsAFileAndNamesItInErrors) {
  const std::filesystem::path path = folder_ / "song.mid";
  const Bytes bytes = writeSmf(std::vector{message(0.25, 0xB0, 1, 2)});
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  const MidiSequence sequence = readSmf(path);
  ASSERT_EQ(sequence.messages.size(), 1u);
  EXPECT_EQ(sequence.messages[0].data2, 2);

  std::ofstream(folder_ / "bad.mid", std::ios::binary) << "MThd";
  try {
    readSmf(folder_ / "bad.mid");
    FAIL() << "a truncated file was read";
  } catch (const Error& error) {
    EXPECT_EQ(std::string(error.what()),
              (folder_ / "bad.mid").string() + ": byte 4: the file ends inside the header chunk.");
  }
  try {
    readSmf(folder_ / "missing.mid");
    FAIL() << "a missing file was read";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("missing.mid: it does not exist"), std::string::npos) << error.what();
  }
  EXPECT_THROW(readSmf(folder_), Error);
}

TEST(LiveMidiPlayer, ReturnsEachMessageOnceAtItsStep) {
  MidiSequence sequence;
  sequence.messages = {message(0.0, 0x90, 60, 100), message(0.5, 0x80, 60, 0), message(0.5, 0xB0, 1, 2),
                       message(1.0, 0x90, 62, 100)};
  sequence.seconds = 2.0;
  SmfPlayer player(sequence);
  EXPECT_EQ(player.sequence().messages.size(), 4u);

  std::vector<MidiMessage> played;
  std::vector<int> stepOf;
  for (int step = 1; step <= 130; ++step) {
    EXPECT_EQ(player.finished(), step > 120) << step;
    for (const MidiMessage& m : player.until(step / 60.0)) {  // a step shows what happened before its time
      played.push_back(m);
      stepOf.push_back(step);
    }
  }
  EXPECT_EQ(played, sequence.messages);
  EXPECT_EQ(stepOf, (std::vector{1, 31, 31, 61}));  // 0.5 s is not before step 30's 0.5 s, but before step 31's
  EXPECT_TRUE(player.finished());
}

TEST(LiveMidiPlayer, TimeOnlyMovesForward) {
  MidiSequence sequence;
  sequence.messages = {message(0.1, 0x90, 60, 100), message(0.2, 0x80, 60, 0)};
  sequence.seconds = 0.2;
  SmfPlayer player(sequence);
  EXPECT_EQ(player.until(0.15).size(), 1u);
  EXPECT_TRUE(player.until(0.05).empty());
  EXPECT_TRUE(player.until(NAN).empty());
  EXPECT_FALSE(player.finished());
  EXPECT_EQ(player.until(0.3).size(), 1u);
  EXPECT_TRUE(player.finished());

  SmfPlayer empty{MidiSequence{}};
  EXPECT_TRUE(empty.finished());
}

TEST(LiveMidiInput, WithoutDevicesItIsOffAndQuiet) {
  testing::internal::CaptureStderr();
  MidiInput input({.useDevices = false});
  input.poll();
  input.poll();
  const std::string printed = testing::internal::GetCapturedStderr();
  EXPECT_EQ(printed, "vitrine: no MIDI input (not asked to use devices): MIDI off\n");
  EXPECT_FALSE(input.active());
  EXPECT_EQ(input.status(), "no MIDI (not asked to use devices)");
  EXPECT_TRUE(input.drain().empty());
  EXPECT_TRUE(input.ports().empty());
}

TEST(LiveMidiInput, WithoutASequencerItSaysSoOnce) {
  if (std::filesystem::exists("/dev/snd/seq")) GTEST_SKIP() << "this machine has an ALSA sequencer";
  testing::internal::CaptureStderr();
  {
    MidiInput input;
    input.poll();
    EXPECT_FALSE(input.active());
    EXPECT_EQ(input.status(), "no MIDI (no ALSA sequencer, /dev/snd/seq is missing)");
    EXPECT_TRUE(input.drain().empty());
  }
  EXPECT_EQ(testing::internal::GetCapturedStderr(),
            "vitrine: no MIDI input (no ALSA sequencer, /dev/snd/seq is missing): MIDI off\n");
}

}  // namespace
}  // namespace vitrine::live
