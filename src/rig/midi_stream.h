#pragma once
// A raw MIDI byte stream, each byte with its arrival time, cut into the messages the show's clocks
// read: real-time bytes (0xF8..0xFF, which may fall anywhere, even inside another message), system
// common messages (0xF1 quarter frame, 0xF2 song position, ...) and system exclusive (0xF0 .. 0xF7).
// Channel messages are followed (running status included) only so their data bytes are not taken
// for anything else. Whatever the bytes, it never throws and holds at most kMaxSysex bytes: a data
// byte with no status, a message cut short by another status, an unfinished or oversized SysEx are
// dropped and counted, the last such trouble kept as one line.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace vitrine::rig {

class MidiStreamHandler {
 public:
  virtual ~MidiStreamHandler() = default;
  virtual void realtime(double time, uint8_t status) = 0;
  // A complete system common message: `data` holds its 0..2 data bytes.
  virtual void common(double time, uint8_t status, std::span<const uint8_t> data) = 0;
  // A complete SysEx: the bytes between 0xF0 and 0xF7, both left out; `time` that of its 0xF7.
  virtual void sysex(double time, std::span<const uint8_t> body) = 0;
};

class MidiStream {
 public:
  // Far more than the SysEx a clock sends (a full frame is 8 bytes between F0 and F7).
  static constexpr size_t kMaxSysex = 256;

  void feed(double time, uint8_t byte, MidiStreamHandler& handler);
  void feed(double time, std::span<const uint8_t> bytes, MidiStreamHandler& handler) {
    for (const uint8_t byte : bytes) feed(time, byte, handler);
  }

  uint64_t dropped() const { return dropped_; }         // messages and stray bytes thrown away
  const std::string& trouble() const { return trouble_; }  // the last, as one line; empty if none

 private:
  void drop(std::string why);
  uint8_t status_ = 0;  // the message being read (channel or system common), kept for running status; 0: none
  int wanted_ = 0;       // data bytes the message needs
  uint8_t data_[2] = {};
  int have_ = 0;
  bool inSysex_ = false, sysexTooLong_ = false;
  std::vector<uint8_t> sysex_;
  uint64_t dropped_ = 0;
  std::string trouble_;
};

}  // namespace vitrine::rig
