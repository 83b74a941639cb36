// vitrine_ltc_wav OUT.wav RATE HH:MM:SS:FF SECONDS [LEAD-IN]: a WAV of LTC from libltc's encoder (48 kHz
// mono, 16-bit), for the command-line tests of timecode; RATE is 24, 25, 29.97df or 30.
#include <sndfile.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "rig/timecode.h"
#include "support/ltc_signal.h"

int main(int argc, char** argv) {
  using namespace vitrine;
  if (argc < 5) {
    std::fprintf(stderr, "usage: vitrine_ltc_wav OUT.wav 24|25|29.97df|30 HH:MM:SS:FF SECONDS [LEAD-IN]\n");
    return 2;
  }
  const std::string rateText = argv[2];
  const rig::FrameRate rate = rateText == "24"        ? rig::FrameRate::Fps24
                              : rateText == "25"      ? rig::FrameRate::Fps25
                              : rateText == "29.97df" ? rig::FrameRate::Fps2997Drop
                                                      : rig::FrameRate::Fps30;
  std::string why;
  const auto start = rig::parseTimecode(argv[3], &why);
  if (!start) {
    std::fprintf(stderr, "vitrine_ltc_wav: %s: %s\n", argv[3], why.c_str());
    return 2;
  }
  const double seconds = std::atof(argv[4]), leadIn = argc > 5 ? std::atof(argv[5]) : 0.0;
  constexpr double kRate = 48000.0;
  const auto samples = test::ltcSignal(kRate, rate, *start, int(seconds * rig::realFps(rate)), leadIn);
  SF_INFO info{};
  info.samplerate = int(kRate);
  info.channels = 1;
  info.format = SF_FORMAT_WAV | SF_FORMAT_PCM_16;
  SNDFILE* file = sf_open(argv[1], SFM_WRITE, &info);
  if (!file) {
    std::fprintf(stderr, "vitrine_ltc_wav: %s: %s\n", argv[1], sf_strerror(nullptr));
    return 1;
  }
  sf_writef_float(file, samples.data(), sf_count_t(samples.size()));
  sf_close(file);
  return 0;
}
