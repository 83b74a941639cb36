#include "rig/midi_stream.h"

#include <fmt/format.h>

namespace vitrine::rig {
namespace {

// Data bytes after a status: channel messages by type, system common by status; -1: undefined status.
int dataBytes(uint8_t status) {
  if (status < 0xF0) return (status & 0xF0) == 0xC0 || (status & 0xF0) == 0xD0 ? 1 : 2;
  switch (status) {
    case 0xF1: case 0xF3: return 1;  // quarter frame, song select
    case 0xF2: return 2;             // song position
    case 0xF6: return 0;             // tune request
    default: return -1;              // 0xF4, 0xF5: undefined
  }
}

}  // namespace

void MidiStream::drop(std::string why) {
  ++dropped_;
  trouble_ = std::move(why);
}

void MidiStream::feed(double time, uint8_t byte, MidiStreamHandler& handler) {
  if (byte >= 0xF8) {  // real time: between any two bytes, changing nothing around it
    if (byte == 0xF9 || byte == 0xFD) return drop(fmt::format("undefined real-time byte 0x{:02X}", byte));
    return handler.realtime(time, byte);
  }
  if (byte == 0xF7) {
    if (!inSysex_) return drop("0xF7 (end of SysEx) with no SysEx begun");
    inSysex_ = false;
    if (sysexTooLong_) return drop(fmt::format("a SysEx over {} bytes", kMaxSysex));
    return handler.sysex(time, sysex_);
  }
  if (byte >= 0x80) {  // a status: it ends whatever came before it
    if (inSysex_) inSysex_ = false, drop(fmt::format("a SysEx cut short by status 0x{:02X}", byte));
    else if (status_ && have_ > 0) drop(fmt::format("status 0x{:02X} cut short by 0x{:02X}", status_, byte));
    status_ = 0, have_ = 0;
    if (byte == 0xF0) {
      inSysex_ = true, sysexTooLong_ = false;
      sysex_.clear();
      return;
    }
    const int wanted = dataBytes(byte);
    if (wanted < 0) return drop(fmt::format("undefined status 0x{:02X}", byte));
    if (wanted == 0) return handler.common(time, byte, {});
    status_ = byte, wanted_ = wanted;
    return;
  }
  // A data byte.
  if (inSysex_) {
    if (sysex_.size() < kMaxSysex) sysex_.push_back(byte);
    else sysexTooLong_ = true;
    return;
  }
  if (!status_) return drop(fmt::format("data byte 0x{:02X} with no status before it", byte));
  data_[have_++] = byte;
  if (have_ < wanted_) return;
  have_ = 0;
  if (status_ >= 0xF0) {
    handler.common(time, status_, std::span<const uint8_t>(data_, size_t(wanted_)));
    status_ = 0;  // system common ends running status
  }
  // A channel message is complete: nothing here reads it; its status stays for running status.
}

}  // namespace vitrine::rig
