#pragma once
// Standard MIDI Files (.mid): read for headless and record runs (--midi-in FILE.mid), written for
// tests and the docs' example files. Our own parser: Debian's libsmf, the usual C library for this,
// has been unmaintained since 2010, and the format is small enough to read carefully ourselves.
//
// What is read: formats 0 and 1 (format 2, independent sequences, is refused with the reason); a
// division in ticks per quarter note with the tempo map applied (meta event 0x51, from any track in
// format 1), or in SMPTE frames (-24, -25, -29 = 29.97 drop-frame, -30 x ticks per frame), where
// tempo events do not apply; running status. Only channel voice messages are kept: sysex (F0/F7) and
// meta events are skipped, and a note on with velocity 0 is kept as written (a consumer treats it as
// a note off). Chunks other than MThd and MTrk are skipped, as the standard asks; bytes after the last
// track the header announces are ignored (files in the wild often carry some).
//
// Running status survives meta and sysex events. The standard says they cancel it, but files that rely
// on it exist and every widespread reader accepts them; a stricter reading would only refuse them.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "live/midi_message.h"

namespace vitrine::live {

// Limits that keep a hostile file from taking much memory or time; real files are far below them.
inline constexpr size_t kSmfMaxBytes = size_t(16) << 20;
inline constexpr size_t kSmfMaxEvents = 1'000'000;  // events of every kind, meta and sysex included

struct MidiSequence {
  std::vector<MidiMessage> messages;  // every track merged, sorted by time (stable: file order within a time)
  double seconds = 0.0;               // time of the last event (end-of-track included)
};

// Parses a whole file. Throws vitrine::Error "NAME: byte OFFSET: REASON" for anything malformed (a
// truncated chunk, a bad header, a data byte where a status is needed, a variable-length number over
// 4 bytes, more than kSmfMaxBytes or kSmfMaxEvents, ...); `name` labels the bytes in errors.
MidiSequence parseSmf(std::span<const uint8_t> bytes, const std::string& name);

// Reads a file (refusing one over kSmfMaxBytes before reading it) and parses it; errors name the file.
MidiSequence readSmf(const std::filesystem::path& path);

// A format-0 file of these messages (times in seconds, any order: sorted first, stably), `ppq` ticks
// per quarter note at a constant `bpm`, times rounded to the nearest tick: for tests and the docs'
// example files. Uses running status. A program change or channel pressure carries data1 only, so
// its data2 reads back as 0. Throws vitrine::Error for what a file cannot hold: a status outside
// 0x80..0xEF, a data byte over 0x7F, a negative or non-finite time, ppq outside 1..32767, a tempo
// outside what the file's 24-bit tempo event holds, or a gap between messages over 0x0FFFFFFF ticks.
std::vector<uint8_t> writeSmf(std::span<const MidiMessage> messages, int ppq = 480, double bpm = 120.0);

// Plays a sequence against simulation time (headless and record runs: --midi-in FILE.mid).
class SmfPlayer {
 public:
  explicit SmfPlayer(MidiSequence sequence);

  // Every message with time < seconds not yet returned, in order. Time only moves forward: an
  // earlier time than one already asked returns nothing (as does NaN).
  std::vector<MidiMessage> until(double seconds);

  // True once every message has been returned and until() has reached the sequence's end (its last
  // event, end-of-track included), so a run that stops here plays the file's whole length.
  bool finished() const;

  const MidiSequence& sequence() const { return sequence_; }

 private:
  MidiSequence sequence_;
  size_t next_ = 0;
  double reached_ = 0.0;  // the latest time until() was asked for
};

}  // namespace vitrine::live
