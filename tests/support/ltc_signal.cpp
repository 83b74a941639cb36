#include "support/ltc_signal.h"

#include <ltc.h>

#include <cstring>
#include <stdexcept>

namespace vitrine::test {

std::vector<float> ltcSignal(double sampleRate, rig::FrameRate rate, const rig::Timecode& start, int frames,
                             double leadIn, bool backwards) {
  const LTC_TV_STANDARD standard = rate == rig::FrameRate::Fps24   ? LTC_TV_FILM_24
                                   : rate == rig::FrameRate::Fps25 ? LTC_TV_625_50
                                                                   : LTC_TV_525_60;
  LTCEncoder* encoder = ltc_encoder_create(sampleRate, rig::realFps(rate), standard, 0);
  if (!encoder) throw std::runtime_error("libltc could not make an encoder");
  SMPTETimecode label{};
  std::strcpy(label.timezone, "+0000");
  label.hours = static_cast<unsigned char>(start.hours);
  label.mins = static_cast<unsigned char>(start.minutes);
  label.secs = static_cast<unsigned char>(start.seconds);
  label.frame = static_cast<unsigned char>(start.frames);
  ltc_encoder_set_timecode(encoder, &label);
  std::vector<float> out(size_t(leadIn * sampleRate), 0.0f);
  for (int i = 0; i < frames; ++i) {
    if (backwards)
      for (int byte = 9; byte >= 0; --byte) ltc_encoder_encode_byte(encoder, byte, -1.0);
    else
      ltc_encoder_encode_frame(encoder);
    ltcsnd_sample_t* samples = nullptr;
    const int n = ltc_encoder_get_bufferptr(encoder, &samples, 1);
    for (int j = 0; j < n; ++j) out.push_back((float(samples[j]) - 128.0f) / 127.0f);
    if (backwards) ltc_encoder_dec_timecode(encoder);
    else ltc_encoder_inc_timecode(encoder);
  }
  ltc_encoder_free(encoder);
  return out;
}

}  // namespace vitrine::test
