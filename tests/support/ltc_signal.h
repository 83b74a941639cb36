#pragma once
// LTC as a show's timecode generator sends it, written by libltc's own encoder: the test side of
// src/rig/ltc_reader.h (and of the small tool vitrine_ltc_wav, for command-line tests).
#include <vector>

#include "rig/timecode.h"

namespace vitrine::test {

// `frames` frames of LTC from `start` at `rate` (forwards, or `backwards` from `start` down), mono,
// -1..1 at -3 dBFS, after `leadIn` seconds of silence.
std::vector<float> ltcSignal(double sampleRate, rig::FrameRate rate, const rig::Timecode& start, int frames,
                             double leadIn = 0.0, bool backwards = false);

}  // namespace vitrine::test
