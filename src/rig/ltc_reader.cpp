#include "rig/ltc_reader.h"

#include <fmt/format.h>
#include <ltc.h>

#include <algorithm>
#include <cmath>

namespace vitrine::rig {
namespace {

// The frames a second a frame's length in samples stands for, and whether it is 29.97 drop-frame.
FrameRate rateOf(double samplesPerFrame, double sampleRate, bool dropFlag) {
  const double fps = sampleRate / samplesPerFrame;
  if (fps < 24.5) return FrameRate::Fps24;
  if (fps < 27.5) return FrameRate::Fps25;
  return dropFlag ? FrameRate::Fps2997Drop : FrameRate::Fps30;
}

}  // namespace

struct LtcReader::Decoder {
  LTCDecoder* handle;
  explicit Decoder(double sampleRate) : handle(ltc_decoder_create(int(sampleRate / 25.0), 32)) {}
  ~Decoder() {
    if (handle) ltc_decoder_free(handle);
  }
};

LtcReader::LtcReader(double sampleRate)
    : decoder_(std::make_unique<Decoder>(sampleRate)), sampleRate_(sampleRate > 0.0 ? sampleRate : 48000.0) {}

LtcReader::~LtcReader() = default;

void LtcReader::push(std::span<const float> samples) {
  if (!decoder_->handle) return;
  constexpr size_t kChunk = 4096;
  for (size_t at = 0; at < samples.size(); at += kChunk) {
    const size_t n = std::min(kChunk, samples.size() - at);
    scratch_.resize(n);
    for (size_t i = 0; i < n; ++i) {
      const float s = samples[at + i];
      scratch_[i] = std::isfinite(s) ? std::clamp(s, -1.0f, 1.0f) : 0.0f;
    }
    ltc_decoder_write_float(decoder_->handle, scratch_.data(), n, ltc_off_t(stream_));
    stream_ += n;
    LTCFrameExt frame;
    while (ltc_decoder_read(decoder_->handle, &frame)) take(frame);
  }
}

void LtcReader::take(const LTCFrameExt& decoded) {
  LTCFrameExt frame = decoded;
  SMPTETimecode label{};
  ltc_frame_to_time(&label, &frame.ltc, 0);
  const double span = double(frame.off_end - frame.off_start + 1);
  if (!(span > 0.0)) return;
  samplesPerFrame_ = samplesPerFrame_ > 0.0 && std::abs(span - samplesPerFrame_) < 0.1 * samplesPerFrame_
                         ? samplesPerFrame_ + (span - samplesPerFrame_) * 0.1
                         : span;
  const FrameRate rate = rateOf(samplesPerFrame_, sampleRate_, frame.ltc.dfbit);
  const Timecode tc{label.hours, label.mins, label.secs, label.frame};
  const auto count = frameCount(tc, rate);
  if (!count) {
    ++refused_;
    trouble_ = fmt::format("impossible timecode {} at {} fps", formatTimecode(tc), rateName(rate));
    return;
  }
  const int direction = frame.reverse ? -1 : 1;
  if (frame_ && rate == rate_) {
    const int64_t day = framesPerDay(rate);
    const int64_t expected = ((*frame_ + direction) % day + day) % day;
    if (*count != expected) ++jumps_, fit_.clear();
  }
  if (rate != rate_ || direction != direction_) fit_.clear();
  // Either way round, the frame shows from where its sound begins in the stream.
  frameStart_ = int64_t(frame.off_start);
  fit_.add(double(frameStart_) / sampleRate_);
  frame_ = *count, rate_ = rate, direction_ = direction, volumeDb_ = frame.volume;
  ++decoded_;
}

std::optional<TimecodePosition> LtcReader::position() const {
  if (!frame_) return std::nullopt;
  // Frames begun since the last decoded one began; lost, it holds where it had counted to.
  const double since = std::clamp((double(stream_) - double(frameStart_)) / samplesPerFrame_, 0.0, kLostFrames - 1.0);
  const auto whole = int64_t(std::floor(since));
  const int64_t day = framesPerDay(rate_);
  const int64_t frames = ((*frame_ + direction_ * whole) % day + day) % day;
  return TimecodePosition{frames, rate_, locked() ? since - double(whole) : 0.0, locked() ? direction_ : 0};
}

bool LtcReader::locked() const {
  return frame_ && double(stream_) - double(frameStart_) < kLostFrames * samplesPerFrame_;
}

ClockStatus LtcReader::status() const {
  ClockStatus status{.name = "ltc", .locked = locked(), .jitterMs = jitterMs()};
  const auto at = position();
  if (at) {
    status.seconds = at->seconds();
    status.timecode = formatTimecode(at->label());
  }
  if (!at) status.note = "no LTC heard in the audio input";
  else if (status.locked)
    status.note = fmt::format("{} fps, {}, {:.0f} dBFS", rateName(rate_), direction_ < 0 ? "backwards" : "forwards", volumeDb_);
  else status.note = fmt::format("{} fps, lost {:.1f} s ago: holding", rateName(rate_),
                                 (double(stream_) - double(frameStart_)) / sampleRate_);
  if (!trouble_.empty()) status.note += "; last refused: " + trouble_;
  return status;
}

}  // namespace vitrine::rig
