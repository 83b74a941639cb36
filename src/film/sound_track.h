#pragma once
// A film's sound, encoded as it is given, a stretch at a time, beside the video in the same file: the
// muxer interleaves the two streams by time as their packets come, so the film is written as it is
// made and nothing waits for its end. 48 kHz stereo, as format.audioEncoder (AAC beside h264 and
// hevc, 24-bit PCM beside ProRes and FFV1), starting at the film's first instant.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "film/libav.h"

namespace vitrine::film {

class SoundTrack {
 public:
  // Adds the sound's stream to `output`, whose header is not written yet. Throws vitrine::Error naming
  // `target`: an encoder this FFmpeg lacks.
  SoundTrack(AVFormatContext& output, const std::string& target, const std::string& encoderName);

  // The next interleaved stereo frames, encoded a block (the encoder's frame) at a time and handed to
  // the muxer; a part block waits for the rest.
  void add(std::span<const float> stereo);
  int64_t given() const { return given_; }  // frames given so far

  // Ends the sound at exactly `frames` frames, so it ends with the video: silence after what was given,
  // and what was given past them dropped. Throws vitrine::Error when more than that is encoded already.
  void finish(int64_t frames);

 private:
  void encodeBlock(int count, const float* stereo);
  void send(const AVFrame* frame);

  AVFormatContext& output_;
  const std::string& target_;
  CodecPtr codec_;
  ResamplerPtr converter_;
  AVStream* stream_ = nullptr;
  int block_ = 1024;
  int64_t encoded_ = 0, given_ = 0;  // frames sent to the encoder; frames given
  std::vector<float> waiting_;       // given, not yet a whole block: interleaved stereo
  FramePtr frame_ = makeFrame();
  PacketPtr packet_ = makePacket();
};

}  // namespace vitrine::film
