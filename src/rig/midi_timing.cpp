#include "rig/midi_timing.h"

namespace vitrine::rig {

void MidiTiming::feed(double time, std::span<const uint8_t> bytes) {
  for (const uint8_t byte : bytes) {
    const uint64_t before = stream_.dropped();
    stream_.feed(time, byte, *this);
    if (stream_.dropped() != before) mtcLast_ = false;
  }
}

void MidiTiming::realtime(double time, uint8_t status) {
  if (status < 0xF8 || status > 0xFC) return;  // active sensing, reset: nothing to do with time
  heard_ = true;
  clock_.realtime(time, status);
}

void MidiTiming::common(double time, uint8_t status, std::span<const uint8_t> data) {
  if (status == 0xF1 && data.size() == 1) {
    heard_ = true;
    const uint64_t before = mtc_.refused();
    mtc_.quarterFrame(time, data[0]);
    if (mtc_.refused() != before) mtcLast_ = true;
  } else if (status == 0xF2 && data.size() == 2) {
    heard_ = true;
    clock_.songPosition(data[0] | data[1] << 7);
  }
}

void MidiTiming::sysex(double, std::span<const uint8_t> body) {
  const uint64_t before = mtc_.refused();
  mtc_.sysex(body);
  if (mtc_.refused() != before) mtcLast_ = true;
  if (body.size() >= 4 && body[0] == 0x7F && body[2] == 0x01) heard_ = true;
}

std::string MidiTiming::trouble() const {
  if (mtcLast_ && !mtc_.trouble().empty()) return mtc_.trouble();
  return stream_.trouble().empty() ? mtc_.trouble() : stream_.trouble();
}

}  // namespace vitrine::rig
