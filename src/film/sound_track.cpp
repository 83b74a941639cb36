#include "film/sound_track.h"

#include <fmt/format.h>

#include <algorithm>
#include <new>

#include "core/error.h"

namespace vitrine::film {
namespace {

constexpr int kRate = 48000;
constexpr int64_t kAacBitrate = 256'000;  // stereo AAC well above transparency

}  // namespace

SoundTrack::SoundTrack(AVFormatContext& output, const std::string& target, const std::string& encoderName)
    : output_(output), target_(target) {
  const AVCodec* encoder = avcodec_find_encoder_by_name(encoderName.c_str());
  if (!encoder)
    throw Error(fmt::format("Cannot write {}: this FFmpeg has no {} encoder for the sound.", target, encoderName));
  codec_.reset(avcodec_alloc_context3(encoder));
  if (!codec_) throw std::bad_alloc();
  codec_->sample_rate = kRate;
  av_channel_layout_default(&codec_->ch_layout, 2);
  codec_->sample_fmt = encoder->sample_fmts ? encoder->sample_fmts[0] : AV_SAMPLE_FMT_FLTP;  // aac: fltp; pcm_s24le: s32
  codec_->time_base = {1, kRate};
  if (encoderName == "aac") codec_->bit_rate = kAacBitrate;
  if (output.oformat->flags & AVFMT_GLOBALHEADER) codec_->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  checkAv(avcodec_open2(codec_.get(), encoder, nullptr), target, fmt::format("starting the {} encoder", encoderName));
  block_ = codec_->frame_size > 0 ? codec_->frame_size : 1024;

  stream_ = avformat_new_stream(&output, nullptr);
  if (!stream_) throw std::bad_alloc();
  checkAv(avcodec_parameters_from_context(stream_->codecpar, codec_.get()), target, "describing the sound stream");
  stream_->time_base = codec_->time_base;

  // Interleaved floats into the encoder's sample format (planar floats, 32-bit integers), with no
  // change of rate: FFmpeg's conversion, clipped and rounded as its own tools do.
  SwrContext* raw = nullptr;
  checkAv(swr_alloc_set_opts2(&raw, &codec_->ch_layout, codec_->sample_fmt, kRate, &codec_->ch_layout,
                              AV_SAMPLE_FMT_FLT, kRate, 0, nullptr),
          target, "setting up the sound's conversion");
  converter_.reset(raw);
  checkAv(swr_init(converter_.get()), target, "setting up the sound's conversion");
}

void SoundTrack::add(std::span<const float> stereo) {
  given_ += int64_t(stereo.size() / 2);
  waiting_.insert(waiting_.end(), stereo.begin(), stereo.end());
  size_t taken = 0;
  while (waiting_.size() - taken >= size_t(block_) * 2) {
    encodeBlock(block_, waiting_.data() + taken);
    taken += size_t(block_) * 2;
  }
  waiting_.erase(waiting_.begin(), waiting_.begin() + std::ptrdiff_t(taken));
}

void SoundTrack::finish(int64_t frames) {
  if (encoded_ > frames)
    throw Error(fmt::format("Cannot write {}: {} frames of sound are encoded already, past the film's {}.", target_,
                            encoded_, frames));
  // What waits is cut to the film's length, or padded with silence to it; a short block only last.
  waiting_.resize(size_t(frames - encoded_) * 2, 0.0f);
  size_t taken = 0;
  while (taken < waiting_.size()) {
    const int count = int(std::min<size_t>(size_t(block_), (waiting_.size() - taken) / 2));
    encodeBlock(count, waiting_.data() + taken);
    taken += size_t(count) * 2;
  }
  waiting_.clear();
  send(nullptr);
}

void SoundTrack::encodeBlock(int count, const float* stereo) {
  // A fresh frame each block: the encoder may still hold the last one.
  frame_ = makeFrame();
  frame_->nb_samples = count;
  frame_->format = codec_->sample_fmt;
  frame_->sample_rate = kRate;
  checkAv(av_channel_layout_copy(&frame_->ch_layout, &codec_->ch_layout), target_, "describing the sound");
  checkAv(av_frame_get_buffer(frame_.get(), 0), target_, "allocating the sound");
  const uint8_t* in[1] = {reinterpret_cast<const uint8_t*>(stereo)};
  checkAv(swr_convert(converter_.get(), frame_->data, count, in, count), target_, "converting the sound");
  frame_->pts = encoded_;
  encoded_ += count;
  send(frame_.get());
}

void SoundTrack::send(const AVFrame* frame) {
  encodeInto(*codec_, frame, output_, *stream_, *packet_, target_, "the sound");
}

}  // namespace vitrine::film
