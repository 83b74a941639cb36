#include "film/sound_mux.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.h"
#include "film/libav.h"

namespace vitrine::film {
namespace {

constexpr int kRate = 48000;
constexpr int64_t kAacBitrate = 256'000;  // stereo AAC well above transparency
// How far the sound is encoded ahead of the video packet being copied: the muxer interleaves what it
// is given by time, holding back only this much.
constexpr int64_t kLead = kRate / 2;

// The sound's encoder and stream, fed from the film's samples a block at a time.
class SoundTrack {
 public:
  SoundTrack(AVFormatContext& output, const std::string& target, const std::string& encoderName,
             std::span<const float> stereo, int64_t frames)
      : output_(output), target_(target), stereo_(stereo), total_(frames) {
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
    resampler_.reset(raw);
    checkAv(swr_init(resampler_.get()), target, "setting up the sound's conversion");
  }

  // Encodes and hands to the muxer the sound up to sample frame `until` (or the end).
  void encodeUpTo(int64_t until) {
    until = std::min(until, total_);
    while (next_ < until) {
      const int count = int(std::min<int64_t>(block_, total_ - next_));  // a short block only last
      FramePtr frame = makeFrame();
      frame->nb_samples = count;
      frame->format = codec_->sample_fmt;
      frame->sample_rate = kRate;
      checkAv(av_channel_layout_copy(&frame->ch_layout, &codec_->ch_layout), target_, "describing the sound");
      checkAv(av_frame_get_buffer(frame.get(), 0), target_, "allocating the sound");
      // The film's length exactly: past the samples given, silence.
      blockSamples_.assign(size_t(count) * 2, 0.0f);
      const size_t have = stereo_.size() / 2;
      for (int64_t i = next_; i < next_ + count && size_t(i) < have; ++i) {
        blockSamples_[size_t(i - next_) * 2] = stereo_[size_t(i) * 2];
        blockSamples_[size_t(i - next_) * 2 + 1] = stereo_[size_t(i) * 2 + 1];
      }
      const uint8_t* in[1] = {reinterpret_cast<const uint8_t*>(blockSamples_.data())};
      checkAv(swr_convert(resampler_.get(), frame->data, count, in, count), target_, "converting the sound");
      frame->pts = next_;
      next_ += count;
      send(frame.get());
    }
  }

  void finish() {
    encodeUpTo(total_);
    send(nullptr);
  }

 private:
  void send(const AVFrame* frame) {
    checkAv(avcodec_send_frame(codec_.get(), frame), target_, "encoding the sound");
    PacketPtr packet = makePacket();
    for (;;) {
      const int received = avcodec_receive_packet(codec_.get(), packet.get());
      if (received == AVERROR(EAGAIN) || received == AVERROR_EOF) return;
      checkAv(received, target_, "encoding the sound");
      av_packet_rescale_ts(packet.get(), codec_->time_base, stream_->time_base);
      packet->stream_index = stream_->index;
      checkAv(av_interleaved_write_frame(&output_, packet.get()), target_, "writing the sound");
    }
  }

  AVFormatContext& output_;
  const std::string& target_;
  std::span<const float> stereo_;
  int64_t total_;
  CodecPtr codec_;
  ResamplerPtr resampler_;
  AVStream* stream_ = nullptr;
  int block_ = 1024;
  int64_t next_ = 0;
  std::vector<float> blockSamples_;
};

InputPtr openVideo(const std::filesystem::path& path, const std::string& target) {
  AVFormatContext* raw = nullptr;
  checkAv(avformat_open_input(&raw, path.c_str(), nullptr, nullptr), target, "reading back the video");
  InputPtr input(raw);
  checkAv(avformat_find_stream_info(input.get(), nullptr), target, "reading back the video");
  if (input->nb_streams != 1 || input->streams[0]->codecpar->codec_type != AVMEDIA_TYPE_VIDEO)
    throw Error(fmt::format("Cannot write {}: its video-only pass holds {} streams, not one video.", target,
                            input->nb_streams));
  return input;
}

}  // namespace

void muxWithSound(const std::filesystem::path& videoOnly, const std::filesystem::path& out, const std::string& target,
                  const FilmFormat& format, std::span<const float> stereo48k, double seconds) {
  const InputPtr input = openVideo(videoOnly, target);
  const AVStream& source = *input->streams[0];
  const OutputPtr output = openOutput(format.muxer, out.string(), target);

  AVStream* video = avformat_new_stream(output.get(), nullptr);
  if (!video) throw std::bad_alloc();
  // Tag and all: the same muxer wrote it, and the tag says more than the codec (ProRes 4444 is 'ap4h',
  // HEVC for Apple 'hvc1').
  checkAv(avcodec_parameters_copy(video->codecpar, source.codecpar), target, "copying the video stream");
  video->time_base = source.time_base;
  video->avg_frame_rate = source.avg_frame_rate;
  video->r_frame_rate = source.r_frame_rate;

  const int64_t frames = std::llround(seconds * kRate);
  SoundTrack sound(*output, target, format.audioEncoder, stereo48k, frames);

  AVDictionary* options = muxerOptions(format);  // as the video-only pass
  const int header = avformat_write_header(output.get(), &options);
  av_dict_free(&options);
  checkAv(header, target, "writing the header");

  PacketPtr packet = makePacket();
  for (;;) {
    const int read = av_read_frame(input.get(), packet.get());
    if (read == AVERROR_EOF) break;
    checkAv(read, target, "reading back the video");
    const int64_t at = packet->dts != AV_NOPTS_VALUE ? packet->dts : packet->pts;
    if (at != AV_NOPTS_VALUE) sound.encodeUpTo(av_rescale_q(at, source.time_base, {1, kRate}) + kLead);
    av_packet_rescale_ts(packet.get(), source.time_base, video->time_base);
    packet->stream_index = video->index;
    packet->pos = -1;
    checkAv(av_interleaved_write_frame(output.get(), packet.get()), target, "writing the video");
  }
  sound.finish();
  checkAv(av_write_trailer(output.get()), target, "writing the trailer");
  checkAv(avio_closep(&output->pb), target, "closing the file");
}

}  // namespace vitrine::film
