#include "live/smf.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string_view>
#include <system_error>
#include <utility>

#include "core/bounded_file.h"
#include "core/error.h"
#include "core/printable.h"

namespace vitrine::live {
namespace {

constexpr uint32_t kDefaultTempo = 500'000;  // µs per quarter note: 120 BPM, the standard's default
constexpr uint32_t kMaxVlq = 0x0FFF'FFFF;    // the most 4 bytes of 7 bits hold

// A position in the file: offsets are always from the file's start, so errors point at the byte a
// hex editor shows. `end` is where the current chunk ends (the file's end outside a chunk).
class Cursor {
 public:
  Cursor(std::span<const uint8_t> bytes, const std::string& name) : bytes_(bytes), name_(name), end_(bytes.size()) {}

  [[noreturn]] void fail(size_t offset, std::string_view reason) const {
    throw Error(fmt::format("{}: byte {}: {}", printable(name_), offset, reason));
  }

  size_t at() const { return at_; }
  size_t left() const { return end_ - at_; }
  void skip(size_t count) { at_ += count; }
  void seek(size_t offset) { at_ = offset; }

  // Reading stops at `end` (a track chunk's end) until leaveChunk().
  void enterChunk(size_t end) { end_ = end, in_ = "track"; }
  void leaveChunk() { end_ = bytes_.size(), in_ = "file"; }

  // `inside` says what a byte missing here would have belonged to, for the error.
  uint8_t byte(std::string_view inside) {
    if (at_ >= end_) fail(at_, fmt::format("the {} ends inside {}.", in_, inside));
    return bytes_[at_++];
  }

  uint32_t bigEndian(int count, std::string_view inside) {
    uint32_t value = 0;
    for (int i = 0; i < count; ++i) value = value << 8 | byte(inside);
    return value;
  }

  // A variable-length quantity: 7 bits a byte, most significant first, the top bit set on all but the last.
  uint32_t vlq(std::string_view inside) {
    const size_t start = at_;
    uint32_t value = 0;
    for (int i = 0; i < 4; ++i) {
      const uint8_t b = byte(inside);
      value = value << 7 | (b & 0x7F);
      if (!(b & 0x80)) return value;
    }
    fail(start, fmt::format("a variable-length number in {} runs over 4 bytes, the most the standard allows.", inside));
  }

 private:
  std::span<const uint8_t> bytes_;
  const std::string& name_;
  size_t at_ = 0;
  size_t end_;
  std::string_view in_ = "file";
};

struct TickMessage {
  uint64_t tick;
  MidiMessage message;
};

struct TempoChange {
  uint64_t tick;
  uint32_t microsPerQuarter;
};

struct Tracks {
  std::vector<TickMessage> messages;  // in file order: track by track
  std::vector<TempoChange> tempos;    // in file order
  uint64_t lastTick = 0;              // of any event, in any track
  size_t events = 0;
};

std::string hexByte(uint8_t b) { return fmt::format("0x{:02X}", b); }

std::string_view messageName(uint8_t status) {
  switch (status & 0xF0) {
    case 0x80:
      return "note off";
    case 0x90:
      return "note on";
    case 0xA0:
      return "polyphonic pressure";
    case 0xB0:
      return "control change";
    case 0xC0:
      return "program change";
    case 0xD0:
      return "channel pressure";
    default:
      return "pitch bend";
  }
}

// One MTrk chunk's events, from the cursor to its end (or its end-of-track event).
void readTrack(Cursor& in, Tracks& tracks) {
  uint64_t tick = 0;
  uint8_t running = 0;  // the last channel status, reused by data bytes that come without one
  while (in.left() > 0) {
    if (++tracks.events > kSmfMaxEvents)
      in.fail(in.at(),
              fmt::format("the file holds over {} events, more than Vitrine reads from one file.", kSmfMaxEvents));
    tick += in.vlq("an event's delta time");
    tracks.lastTick = std::max(tracks.lastTick, tick);
    const size_t start = in.at();
    uint8_t status = in.byte("an event");
    if (status < 0x80) {
      if (running == 0)
        in.fail(start, fmt::format("a data byte ({}) where a status byte is needed, with no earlier channel "
                                   "message whose status it could reuse (running status).",
                                   hexByte(status)));
      status = running;
      in.seek(start);  // the byte read is the message's first data byte
    }
    if (status < 0xF0) {
      running = status;
      const int count = midiDataBytes(status);
      // Checked up front rather than by byte(): its description would be formatted for every data byte.
      if (in.left() < size_t(count))
        in.fail(in.at() + in.left(), fmt::format("the track ends inside a {} message.", messageName(status)));
      uint8_t data[2] = {0, 0};
      for (int i = 0; i < count; ++i) {
        const size_t at = in.at();
        data[i] = in.byte("a channel message");
        if (data[i] >= 0x80)
          in.fail(at, fmt::format("a status byte ({}) where a data byte of a {} message is needed.", hexByte(data[i]),
                                  messageName(status)));
      }
      tracks.messages.push_back({tick, MidiMessage{0.0, status, data[0], data[1]}});
      continue;
    }
    if (status == 0xF0 || status == 0xF7) {  // sysex, or its continuation / an escape: skipped whole
      const uint32_t length = in.vlq("a sysex event's length");
      if (length > in.left())
        in.fail(start, fmt::format("a sysex event claims {} bytes, only {} remain in the track.", length, in.left()));
      in.skip(length);
      continue;
    }
    if (status != 0xFF)
      in.fail(start, fmt::format("status byte {} is a system message, which a MIDI file cannot hold (only channel "
                                 "messages, sysex 0xF0/0xF7 and meta 0xFF).",
                                 hexByte(status)));
    const uint8_t type = in.byte("a meta event");
    const uint32_t length = in.vlq("a meta event's length");
    if (length > in.left())
      in.fail(start, fmt::format("a meta event (type {}) claims {} bytes, only {} remain in the track.", hexByte(type),
                                 length, in.left()));
    if (type == 0x2F) return;  // end of track: whatever the chunk holds after it is not part of the track
    if (type == 0x51) {
      if (length != 3)
        in.fail(start, fmt::format("a tempo event of {} bytes; a tempo is 3 bytes (µs per quarter note).", length));
      tracks.tempos.push_back({tick, in.bigEndian(3, "a tempo event")});
      continue;
    }
    in.skip(length);
  }
}

// Ticks to seconds through the tempo map, for ticks asked in non-decreasing order.
class Clock {
 public:
  Clock(std::vector<TempoChange> tempos, uint16_t division) : tempos_(std::move(tempos)) {
    if (division & 0x8000) {
      // SMPTE: the high byte is minus the frames per second, the low byte ticks per frame; tempo does not apply.
      const int fps = -int(int8_t(division >> 8));
      const double framesPerSecond = fps == 29 ? 30000.0 / 1001.0 : fps;  // 29 stands for 29.97 drop-frame
      smpteSecondsPerTick_ = 1.0 / (framesPerSecond * (division & 0xFF));
    } else {
      ticksPerQuarter_ = division;
      std::stable_sort(tempos_.begin(), tempos_.end(),
                       [](const TempoChange& a, const TempoChange& b) { return a.tick < b.tick; });
    }
  }

  double seconds(uint64_t tick) {
    if (smpteSecondsPerTick_ > 0.0) return double(tick) * smpteSecondsPerTick_;
    // A change at a tick applies from that tick on; several at one tick: the last in file order wins.
    while (next_ < tempos_.size() && tempos_[next_].tick <= tick) {
      segmentSeconds_ += secondsFor(tempos_[next_].tick - segmentTick_);
      segmentTick_ = tempos_[next_].tick;
      tempo_ = tempos_[next_++].microsPerQuarter;
    }
    return segmentSeconds_ + secondsFor(tick - segmentTick_);
  }

 private:
  double secondsFor(uint64_t ticks) const { return double(ticks) * tempo_ / (1e6 * ticksPerQuarter_); }

  std::vector<TempoChange> tempos_;
  double smpteSecondsPerTick_ = 0.0;
  uint32_t ticksPerQuarter_ = 1;
  size_t next_ = 0;
  uint64_t segmentTick_ = 0;
  double segmentSeconds_ = 0.0;
  uint32_t tempo_ = kDefaultTempo;
};

bool startsWith(std::span<const uint8_t> bytes, std::string_view tag) {
  return bytes.size() >= tag.size() &&
         std::equal(tag.begin(), tag.end(), bytes.begin(), [](char a, uint8_t b) { return uint8_t(a) == b; });
}

void appendVlq(std::vector<uint8_t>& out, uint32_t value) {
  uint8_t groups[4];
  int count = 0;
  do {
    groups[count++] = value & 0x7F;
    value >>= 7;
  } while (value != 0);
  while (count > 1) out.push_back(groups[--count] | 0x80);
  out.push_back(groups[0]);
}

void appendBigEndian(std::vector<uint8_t>& out, uint32_t value, int count) {
  for (int i = count - 1; i >= 0; --i) out.push_back(uint8_t(value >> (8 * i)));
}

}  // namespace

MidiSequence parseSmf(std::span<const uint8_t> bytes, const std::string& name) {
  Cursor in(bytes, name);
  if (bytes.size() > kSmfMaxBytes)
    in.fail(kSmfMaxBytes,
            fmt::format("the file is {} bytes, over the 16 MiB Vitrine reads from a MIDI file.", bytes.size()));
  if (bytes.empty()) in.fail(0, "the file is empty, not a Standard MIDI File.");
  if (!startsWith(bytes, "MThd")) in.fail(0, "the file does not start with \"MThd\": it is not a Standard MIDI File.");

  // The header chunk: format, track count and division, each 16 bits; a longer header is allowed (the
  // standard reserves the room) and its extra bytes skipped.
  in.skip(4);
  const uint32_t headerLength = in.bigEndian(4, "the header chunk");
  if (headerLength < 6)
    in.fail(4, fmt::format("the header chunk is {} bytes long; it needs 6 (format, tracks, division).", headerLength));
  if (headerLength > in.left())
    in.fail(4, fmt::format("the header chunk claims {} bytes, only {} remain in the file.", headerLength, in.left()));
  const size_t headerEnd = in.at() + headerLength;
  const uint32_t format = in.bigEndian(2, "the header chunk");
  const uint32_t trackCount = in.bigEndian(2, "the header chunk");
  const auto division = uint16_t(in.bigEndian(2, "the header chunk"));
  if (format == 2)
    in.fail(8, "format 2 (independent sequences, one per track) is not supported; Vitrine plays formats 0 and 1.");
  if (format > 2) in.fail(8, fmt::format("format {} is not a MIDI file format (0, 1 or 2).", format));
  if (trackCount == 0) in.fail(10, "the header announces no tracks.");
  if (format == 0 && trackCount != 1)
    in.fail(10, fmt::format("a format-0 file holds one track, but the header announces {}.", trackCount));
  if (division & 0x8000) {
    const int fps = -int(int8_t(division >> 8));
    if (fps != 24 && fps != 25 && fps != 29 && fps != 30)
      in.fail(12,
              fmt::format("an SMPTE division of {} frames per second; the standard has -24, -25, -29 and -30.", -fps));
    if ((division & 0xFF) == 0) in.fail(13, "an SMPTE division of 0 ticks per frame.");
  } else if (division == 0) {
    in.fail(12, "a division of 0 ticks per quarter note.");
  }
  in.seek(headerEnd);

  // The chunks: tracks read in file order, any other kind skipped, until the announced count is in.
  Tracks tracks;
  for (uint32_t found = 0; found < trackCount;) {
    if (in.left() == 0)
      in.fail(in.at(), fmt::format("the file ends after {} of the {} tracks its header announces.", found, trackCount));
    const size_t chunkStart = in.at();
    const bool isTrack = startsWith(bytes.subspan(chunkStart), "MTrk");
    const std::string_view type(reinterpret_cast<const char*>(bytes.data() + chunkStart),
                                std::min<size_t>(4, in.left()));
    in.skip(std::min<size_t>(4, in.left()));
    const uint32_t length = in.bigEndian(4, "a chunk header");
    if (length > in.left())
      in.fail(chunkStart + 4, fmt::format("the \"{}\" chunk claims {} bytes, only {} remain in the file.",
                                          printable(type), length, in.left()));
    const size_t end = in.at() + length;
    if (isTrack) {
      in.enterChunk(end);
      readTrack(in, tracks);
      in.leaveChunk();
      ++found;
    }
    in.seek(end);
  }

  // Merged by tick, keeping file order within a tick; ticks become seconds in that order.
  std::stable_sort(tracks.messages.begin(), tracks.messages.end(),
                   [](const TickMessage& a, const TickMessage& b) { return a.tick < b.tick; });
  Clock clock(std::move(tracks.tempos), division);
  MidiSequence sequence;
  sequence.messages.reserve(tracks.messages.size());
  for (TickMessage& m : tracks.messages) {
    m.message.time = clock.seconds(m.tick);
    sequence.messages.push_back(m.message);
  }
  sequence.seconds = clock.seconds(tracks.lastTick);
  return sequence;
}

MidiSequence readSmf(const std::filesystem::path& path) {
  const std::string name = printable(path.string());
  std::string text;
  try {
    text = readBoundedFile(path, kSmfMaxBytes);
  } catch (const FileRefused& refused) {
    throw Error(fmt::format("Cannot read MIDI file {}: {}.", name, refused.why));
  }
  const std::vector<uint8_t> bytes(text.begin(), text.end());
  return parseSmf(bytes, path.string());
}

std::vector<uint8_t> writeSmf(std::span<const MidiMessage> messages, int ppq, double bpm) {
  if (ppq < 1 || ppq > 0x7FFF)
    throw Error(fmt::format("writeSmf: {} ticks per quarter note; a MIDI file holds 1 to 32767.", ppq));
  const double micros = std::isfinite(bpm) && bpm > 0.0 ? std::round(60e6 / bpm) : 0.0;
  if (!(micros >= 1.0 && micros <= 0xFF'FFFF))
    throw Error(
        fmt::format("writeSmf: a tempo of {} BPM; a MIDI file's tempo event holds about 3.6 to 60 million.", bpm));
  const auto microsPerQuarter = uint32_t(micros);

  std::vector<MidiMessage> sorted(messages.begin(), messages.end());
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](const MidiMessage& a, const MidiMessage& b) { return a.time < b.time; });

  std::vector<uint8_t> track;
  appendVlq(track, 0);
  track.insert(track.end(), {0xFF, 0x51, 0x03});
  appendBigEndian(track, microsPerQuarter, 3);
  int64_t lastTick = 0;
  uint8_t running = 0;
  for (const MidiMessage& m : sorted) {
    if (m.status < 0x80 || m.status >= 0xF0)
      throw Error(fmt::format("writeSmf: status 0x{:02X} is not a channel voice message (0x80..0xEF).", m.status));
    if (m.data1 > 0x7F || (midiDataBytes(m.status) == 2 && m.data2 > 0x7F))
      throw Error(fmt::format("writeSmf: a message with status 0x{:02X} has a data byte over 0x7F ({}, {}).", m.status,
                              m.data1, m.data2));
    if (!(std::isfinite(m.time) && m.time >= 0.0))
      throw Error(fmt::format("writeSmf: a message at {} s; times are finite and not negative.", m.time));
    // Seconds to ticks through the tempo as written (rounded to whole µs), so reading back lands within half a tick.
    const double tick = std::round(m.time * 1e6 * ppq / microsPerQuarter);
    if (tick - double(lastTick) > kMaxVlq)
      throw Error(
          fmt::format("writeSmf: the gap before the message at {} s is over {} ticks, the most one delta "
                      "time holds.",
                      m.time, kMaxVlq));
    appendVlq(track, uint32_t(int64_t(tick) - lastTick));
    lastTick = int64_t(tick);
    if (m.status != running) track.push_back(m.status);
    running = m.status;
    track.push_back(m.data1);
    if (midiDataBytes(m.status) == 2) track.push_back(m.data2);
  }
  appendVlq(track, 0);
  track.insert(track.end(), {0xFF, 0x2F, 0x00});

  std::vector<uint8_t> file = {'M', 'T', 'h', 'd'};
  appendBigEndian(file, 6, 4);
  appendBigEndian(file, 0, 2);  // format 0
  appendBigEndian(file, 1, 2);  // one track
  appendBigEndian(file, uint32_t(ppq), 2);
  file.insert(file.end(), {'M', 'T', 'r', 'k'});
  appendBigEndian(file, uint32_t(track.size()), 4);
  file.insert(file.end(), track.begin(), track.end());
  return file;
}

SmfPlayer::SmfPlayer(MidiSequence sequence) : sequence_(std::move(sequence)) {}

std::vector<MidiMessage> SmfPlayer::until(double seconds) {
  std::vector<MidiMessage> due;
  if (!(seconds >= reached_)) return due;  // earlier than already asked, or NaN
  reached_ = seconds;
  const std::vector<MidiMessage>& messages = sequence_.messages;
  while (next_ < messages.size() && messages[next_].time < seconds) due.push_back(messages[next_++]);
  return due;
}

bool SmfPlayer::finished() const { return next_ == sequence_.messages.size() && reached_ >= sequence_.seconds; }

}  // namespace vitrine::live
