#include "film/video_encoder.h"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <future>
#include <optional>
#include <vector>

#include "core/atomic_file.h"
#include "core/error.h"
#include "film/hardware_encoder.h"
#include "film/libav.h"
#include "film/parallel_scaler.h"
#include "film/sound_track.h"

namespace vitrine::film {
namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point from, Clock::time_point to) { return std::chrono::duration<double>(to - from).count(); }

// Whether a hardware encoder may take the film: h264 or hevc as yuv420p in limited range, what NVENC and
// VAAPI give (HardwareEncoder); a film it cannot take, or none opens, is encoded in software as always.
bool hardwareMayEncode(const FilmFormat& format) {
  return (format.codec == Codec::H264 || format.codec == Codec::Hevc) && format.pixelFormat == "yuv420p" &&
         !format.fullRange;
}

// The encoder's own settings, set on its private options (AVCodecContext has a "profile" of its own that
// would take ProRes's otherwise) and checked: quality for h264 and hevc, the profile for ProRes.
void setEncoderOptions(AVCodecContext& codec, const FilmFormat& format, const std::string& target) {
  auto set = [&](const char* key, const std::string& value) {
    checkAv(av_opt_set(codec.priv_data, key, value.c_str(), 0), target,
            fmt::format("setting {}'s {} to {}", format.encoder, key, value));
  };
  if (format.crf) set("crf", std::to_string(*format.crf));
  if (!format.preset.empty()) set("preset", format.preset);
  if (format.bitrate) codec.bit_rate = *format.bitrate;
  if (format.codec == Codec::Hevc) set("x265-params", "log-level=error");  // x265 prints a page otherwise
  if (!format.proresProfile.empty()) set("profile", format.proresProfile);
  if (format.codec == Codec::Ffv1) codec.level = 3;  // FFV1 version 3: slices with checksums, an archive's format
}

}  // namespace

struct VideoEncoder::State {
  std::string target;
  FilmFormat format;
  uint32_t width, height;
  double fps;
  PendingFile pending;
  OutputPtr output;
  CodecPtr codec;
  std::optional<HardwareEncoder> hardware;  // NVENC or VAAPI, where one opened: it owns the codec then
  AVCodecContext* context = nullptr;        // the encoder's: codec's or hardware's
  std::string choice;                       // which encoder, and why not the hardware ones
  std::string hardwareRefusals;             // "; h264_nvenc: REASON; h264_vaapi: REASON", when none opened
  AVStream* stream = nullptr;
  std::optional<ParallelScaler> scaler;  // sRGB RGB to Y'CbCr; none for an RGB film
  FramePtr frame = makeFrame();  // the frame being converted into
  FramePtr spare = makeFrame();  // the frame before, being encoded meanwhile
  PacketPtr packet = makePacket();
  std::vector<uint8_t> packed;    // a PNG's RGBA in layout's bytes: packed RGB, or B, G, R, 0
  std::vector<uint16_t> rgb48;    // the same at 16 bits a channel, for a 10-bit film
  DisplayLayout layout;           // what addDisplay takes
  std::vector<uint16_t> widened;  // a PNG's RGBA at 16 bits, for a 10-bit film
  std::optional<SoundTrack> sound;
  uint32_t frames = 0;
  bool started = false;  // the header written: no stream can be added
  bool finished = false;
  StageTimes times;
  // The last converted frame's encoding, on a thread of its own while the next frame is converted: the
  // two take about as long at 4K (swscale's bands and x264's threads), so overlapping them nearly halves
  // a film's time where the encoder thread is the bottleneck. Last, so it ends before what it uses.
  std::future<void> sending;

  State(const std::filesystem::path& path, const FilmFormat& filmFormat, uint32_t w, uint32_t h, double rate,
        const AVCodec& encoder)
      : target(path.string()), format(filmFormat), width(w), height(h), fps(rate), pending(path),
        output(openOutput(format.muxer, pending.path().string(), target)) {
    layout = displayLayout(format);
    choice = format.encoder;
    if (hardwareMayEncode(format)) openHardware();
    if (hardware) {
      context = &hardware->codec();
      layout = DisplayLayout::Rgb0;
      choice = hardware->choice();
    } else {
      openSoftware(encoder);
    }

    stream = avformat_new_stream(output.get(), nullptr);
    if (!stream) throw std::bad_alloc();
    checkAv(avcodec_parameters_from_context(stream->codecpar, context), target, "describing the video stream");
    // Apple's players play HEVC in MP4 and QuickTime only under the 'hvc1' tag (FFmpeg's default is 'hev1').
    if (format.codec == Codec::Hevc && format.container != Container::Mkv)
      stream->codecpar->codec_tag = MKTAG('h', 'v', 'c', '1');
    stream->time_base = context->time_base;
    stream->avg_frame_rate = context->framerate;
  }

  // NVENC, then VAAPI, each opened for real; none is no error: the film is encoded in software.
  void openHardware() {
    EncoderRequest request;
    request.codec = format.codec;
    request.width = width;
    request.height = height;
    request.fps = fps;
    request.bitrate = format.bitrate;
    request.crf = format.crf;
    request.globalHeader = (output->oformat->flags & AVFMT_GLOBALHEADER) != 0;
    request.order = {EncoderKind::Nvenc, EncoderKind::Vaapi};
    request.announce = false;
    try {
      hardware.emplace(request, target);
    } catch (const Error& none) {
      std::string why = none.what();
      if (why.ends_with('.')) why.pop_back();
      const size_t reasons = why.find("; ");
      hardwareRefusals = reasons == std::string::npos ? why : why.substr(reasons);
    }
  }

  void openSoftware(const AVCodec& encoder) {
    codec.reset(avcodec_alloc_context3(&encoder));
    if (!codec) throw std::bad_alloc();
    context = codec.get();
    if (!hardwareRefusals.empty()) choice = fmt::format("{}{}", format.encoder, hardwareRefusals);
    codec->width = int(width);
    codec->height = int(height);
    codec->pix_fmt = av_get_pix_fmt(format.pixelFormat.c_str());
    codec->framerate = av_d2q(fps, 1'000'000);
    codec->time_base = av_inv_q(codec->framerate);
    codec->thread_count = 0;  // as many as the encoder finds useful
    // ProRes's frame header has no code for the sRGB curve (prores_ks writes "unknown" there): a ProRes
    // film says it in its 'colr' box only.
    tagColour(*codec, format.rgb, format.fullRange);
    if (output->oformat->flags & AVFMT_GLOBALHEADER) codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    setEncoderOptions(*codec, format, target);
    const int opened = avcodec_open2(codec.get(), &encoder, nullptr);
    if (opened < 0)
      throw Error(fmt::format("Cannot write {}: {} would not start for {} {}x{} at {:g} fps: {}.", target, format.encoder,
                              format.pixelFormat, width, height, fps, avErrorText(opened)));
    for (AVFrame* each : {frame.get(), spare.get()}) {
      each->format = codec->pix_fmt;
      each->width = codec->width;
      each->height = codec->height;
      checkAv(av_frame_get_buffer(each, 0), target, "allocating a frame");
    }
    if (!format.rgb)
      scaler.emplace(format.deep ? AV_PIX_FMT_RGB48 : AV_PIX_FMT_RGB24, codec->pix_fmt, width, height, format.fullRange,
                     target);
  }

  // The header, once every stream is there: before the first packet of either.
  void start() {
    if (started) return;
    started = true;
    AVDictionary* options = muxerOptions(format);
    const int header = avformat_write_header(output.get(), &options);
    av_dict_free(&options);
    checkAv(header, target, "writing the header");
  }

  void encode(const AVFrame* next) { encodeInto(*context, next, *output, *stream, *packet, target, "the video"); }

  // The frame buffer may still be referenced by the encoder (frame threads, lookahead): a fresh one then.
  void writable() { checkAv(av_frame_make_writable(frame.get()), target, "allocating a frame"); }

  // Waits for the last frame's encoding, throwing its error: before anything else touches the muxer.
  void settle() {
    if (sending.valid()) sending.get();
  }

  // The converted frame into the encoder while the next one is converted (settle waits for it).
  void sendBehind() {
    settle();
    frame->pts = frames;
    start();
    ++frames;
    std::swap(frame, spare);
    sending = std::async(std::launch::async, [this] {
      const auto begun = Clock::now();
      encode(spare.get());
      avio_flush(output->pb);  // as send() does
      times.encode += seconds(begun, Clock::now());
    });
  }

  // `next`, its pts set to the next frame's, into the encoder.
  void send(const AVFrame& next) {
    settle();
    const auto converted = Clock::now();
    start();
    ++frames;
    encode(&next);
    // Onto the disk frame by frame: FFmpeg's file writer otherwise holds 256 KiB, which a small or
    // still film takes minutes to fill.
    avio_flush(output->pb);
    times.encode += seconds(converted, Clock::now());
  }

  // Display values in `layout` into the frame, and on to the encoder.
  void addDisplay(const uint8_t* bytes) {
    const auto begun = Clock::now();
    if (hardware) {  // RGB0: the hardware encoder's own input
      const AVFrame& next = hardware->frame(bytes, frames);
      times.convert += seconds(begun, Clock::now());
      return send(next);
    }
    writable();
    const size_t stride = size_t(width) * bytesPerPixel(layout);
    if (layout == DisplayLayout::Bgr0) {  // copied, not converted, so the bytes come back as they went in
      for (uint32_t y = 0; y < height; ++y)
        std::memcpy(frame->data[0] + size_t(y) * size_t(frame->linesize[0]), bytes + y * stride, stride);
    } else {
      scaler->scale(bytes, stride, *frame);
    }
    times.convert += seconds(begun, Clock::now());
    sendBehind();
  }

  // Display values, RGBA at 8 bits a channel, into the frame.
  void addRgba8(const uint8_t* rgba) {
    if (format.deep) {  // a PNG's bytes into a 10-bit film: 8 bits widened exactly (255 -> 65535)
      widened.resize(size_t(width) * height * 4);
      for (size_t i = 0; i < widened.size(); ++i) widened[i] = uint16_t(rgba[i] * 257);
      return addRgba16(widened.data());
    }
    if (hardware) return addDisplay(rgba);  // RGBA is RGB0, the alpha byte ignored
    const size_t pixels = size_t(width) * height;
    if (format.rgb) {  // bgr0
      packed.resize(pixels * 4);
      for (size_t p = 0; p < pixels; ++p)
        packed[p * 4] = rgba[p * 4 + 2], packed[p * 4 + 1] = rgba[p * 4 + 1], packed[p * 4 + 2] = rgba[p * 4], packed[p * 4 + 3] = 0;
    } else {
      packed.resize(pixels * 3);
      for (size_t p = 0; p < pixels; ++p) std::memcpy(&packed[p * 3], rgba + p * 4, 3);
    }
    addDisplay(packed.data());
  }

  void addRgba16(const uint16_t* rgba) {
    rgb48.resize(size_t(width) * height * 3);
    for (size_t p = 0; p < size_t(width) * height; ++p) std::memcpy(&rgb48[p * 3], rgba + p * 4, 3 * sizeof(uint16_t));
    addDisplay(reinterpret_cast<const uint8_t*>(rgb48.data()));
  }

  void checkSize(uint32_t w, uint32_t h) const {
    if (finished) throw Error(fmt::format("Cannot add a frame to {}: the film is finished.", target));
    if (w != width || h != height)
      throw Error(fmt::format("Cannot add a {}x{} frame to {}: the film is {}x{}.", w, h, target, width, height));
  }

  // Drains the encoders, ends the sound with the video, writes the trailer and closes the file,
  // checking the close: a full disk shows up in the last flush.
  void end() {
    settle();
    start();
    encode(nullptr);
    if (sound) sound->finish(std::llround(double(frames) / fps * 48000.0));
    checkAv(av_write_trailer(output.get()), target, "writing the trailer");
    checkAv(avio_closep(&output->pb), target, "closing the file");
    output.reset();
  }
};

VideoEncoder::VideoEncoder(const std::filesystem::path& target, const FilmFormat& format, uint32_t width,
                           uint32_t height, double fps) {
  quietLibav();
  const AVCodec* encoder = avcodec_find_encoder_by_name(format.encoder.c_str());
  if (!encoder)
    throw Error(fmt::format("This FFmpeg has no {} encoder, so it cannot write {}; choose another --codec.",
                            format.encoder, codecName(format.codec)));
  state_ = std::make_unique<State>(target, format, width, height, fps, *encoder);
}

VideoEncoder::~VideoEncoder() = default;  // unfinished: the temporary goes with the state

void VideoEncoder::addFrame(const ImageRgba& linear) {
  state_->checkSize(linear.width, linear.height);
  if (state_->format.deep) state_->addRgba16(srgb16(linear).data());
  else state_->addRgba8(srgb8(linear).data());
}

void VideoEncoder::addFrame(const Picture& srgb) {
  state_->checkSize(srgb.width, srgb.height);
  state_->addRgba8(srgb.rgba.data());
}

void VideoEncoder::addDisplay(std::span<const std::byte> bytes) {
  State& s = *state_;
  s.checkSize(s.width, s.height);
  const size_t expected = size_t(s.width) * s.height * bytesPerPixel(s.layout);
  if (bytes.size() < expected)
    throw Error(fmt::format("Cannot add a frame of {} bytes to {}: a {}x{} frame is {}.", bytes.size(), s.target,
                            s.width, s.height, expected));
  s.addDisplay(reinterpret_cast<const uint8_t*>(bytes.data()));
}

DisplayLayout VideoEncoder::layout() const { return state_->layout; }

const std::string& VideoEncoder::encoderChoice() const { return state_->choice; }

VideoEncoder::StageTimes VideoEncoder::times() const { return state_->times; }

uint32_t VideoEncoder::frames() const { return state_->frames; }

void VideoEncoder::addSoundTrack() {
  State& s = *state_;
  if (s.started || s.sound)
    throw Error(fmt::format("Cannot give {} a sound track {}.", s.target, s.sound ? "twice" : "after its first frame"));
  s.sound.emplace(*s.output, s.target, s.format.audioEncoder);
}

bool VideoEncoder::hasSoundTrack() const { return state_->sound.has_value(); }

void VideoEncoder::addSound(std::span<const float> stereo48k) {
  State& s = *state_;
  if (!s.sound) throw Error(fmt::format("Cannot add sound to {}: it has no sound track.", s.target));
  if (s.finished) throw Error(fmt::format("Cannot add sound to {}: the film is finished.", s.target));
  s.settle();
  const auto begun = Clock::now();
  s.start();
  s.sound->add(stereo48k);
  s.times.sound += seconds(begun, Clock::now());
}

void VideoEncoder::finish() {
  State& s = *state_;
  if (s.finished) throw Error(fmt::format("{} is already finished.", s.target));
  if (s.frames == 0) throw Error(fmt::format("Cannot write {}: it has no frames.", s.target));
  s.finished = true;
  s.end();
  s.pending.commit();
}

}  // namespace vitrine::film
