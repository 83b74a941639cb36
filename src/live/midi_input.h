#pragma once
// Live MIDI input: every MIDI input port through RtMidi (the ALSA sequencer), hot-plugged, so a
// controller plugged in mid-run is picked up within a second and one pulled out closes cleanly.
//
// Without a MIDI system (no /dev/snd/seq, as in containers and CI) or when RtMidi fails to start, it
// prints one warning, "vitrine: no MIDI input (REASON): MIDI off", and every call is a no-op; it never
// throws for want of MIDI. Use from one thread (the frame loop); RtMidi's own threads only push
// received messages into a guarded queue that drain() empties.
#include <memory>
#include <string>
#include <vector>

#include "live/midi_message.h"

namespace vitrine::live {

class MidiInput {
 public:
  struct Options {
    bool useDevices = true;      // false: behave as though there were no MIDI system (tests)
    double rescanSeconds = 1.0;  // poll() looks for new and gone ports at most this often
  };

  // Messages held for drain() at most; beyond that, new ones are dropped (nobody is draining).
  static constexpr size_t kQueueLimit = 1 << 16;

  // Two constructors rather than `Options options = {}`: a nested struct's member initializers are not
  // usable in a default argument inside its enclosing class (clang refuses; AudioOutput does the same).
  MidiInput();
  explicit MidiInput(Options options);
  ~MidiInput();
  MidiInput(const MidiInput&) = delete;
  MidiInput& operator=(const MidiInput&) = delete;

  // Rescans the ports at most every rescanSeconds (cheap when called every frame): opens new ports,
  // closes gone ones, printing one line per change ("vitrine: MIDI in: NAME connected" / "...
  // disconnected"). A port that fails to open is reported once and tried again only after it has gone.
  void poll();

  // Channel messages received since the last drain, in arrival order, timed in steady clock seconds
  // at arrival. System messages go to drainSystem(); active sensing is ignored.
  std::vector<MidiMessage> drain();
  // The bytes of the system messages received since the last drain (clock, start/stop, song
  // position, MIDI timecode, SysEx of at most kMaxSystemMessage bytes), each with its message's arrival
  // time, in arrival order: what rig::MidiTiming reads.
  struct TimedByte {
    double time = 0.0;
    uint8_t byte = 0;
  };
  static constexpr size_t kMaxSystemMessage = 1024;
  std::vector<TimedByte> drainSystem();

  std::vector<std::string> ports() const;  // names of the open ports, as ALSA gives them ("CLIENT:PORT C:P")
  bool active() const;                     // a MIDI system is there (even with no port yet)
  std::string status() const;              // "MIDI in: 2 ports (NAME, NAME)" or "no MIDI (REASON)"

  // The clock of drain()'s times: steady clock seconds, to compare a message's arrival with now.
  static double clockSeconds();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace vitrine::live
