#include "film/hardware_encoder.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <new>

#include "core/error.h"

namespace vitrine::film {
namespace {

std::string_view kindWords(EncoderKind kind) {
  switch (kind) {
    case EncoderKind::Nvenc: return "NVIDIA's NVENC";
    case EncoderKind::Vaapi: return "VAAPI";
    case EncoderKind::Software: return "software";
  }
  return "";
}

// The first render node, in name order (renderD128 first): the machine's first GPU.
std::string firstRenderNode() {
  std::vector<std::string> nodes;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator("/dev/dri", error))
    if (entry.path().filename().string().starts_with("renderD")) nodes.push_back(entry.path().string());
  std::sort(nodes.begin(), nodes.end());
  return nodes.empty() ? std::string() : nodes.front();
}

// Thrown for an encoder that cannot be tried or will not open: the reason, for the choice's sentence.
struct NotOpened {
  std::string reason;
};

void setOption(AVCodecContext& codec, const char* key, const std::string& value) {
  const int set = av_opt_set(codec.priv_data, key, value.c_str(), 0);
  if (set < 0) throw NotOpened{fmt::format("cannot set {} to {}: {}", key, value, avErrorText(set))};
}

}  // namespace

std::string encoderName(Codec codec, EncoderKind kind) {
  const bool hevc = codec == Codec::Hevc;
  switch (kind) {
    case EncoderKind::Nvenc: return hevc ? "hevc_nvenc" : "h264_nvenc";
    case EncoderKind::Vaapi: return hevc ? "hevc_vaapi" : "h264_vaapi";
    case EncoderKind::Software: return hevc ? "libx265" : "libx264";
  }
  return "";
}

HardwareEncoder::HardwareEncoder(const EncoderRequest& request, const std::string& target)
    : request_(request), target_(target) {
  if (request.codec != Codec::H264 && request.codec != Codec::Hevc)
    throw Error(fmt::format("Cannot write {}: only h264 and hevc are encoded live, not {}.", target,
                            codecName(request.codec)));
  std::string refusals;
  for (EncoderKind kind : request.order) {
    const std::string name = encoderName(request.codec, kind);
    std::string reason;
    if (const AVCodec* encoder = avcodec_find_encoder_by_name(name.c_str())) {
      try {
        open(kind, *encoder);
        kind_ = kind;
        name_ = name;
        choice_ = fmt::format("encoding {} with {} ({}{}){}", codecName(request.codec), name, kindWords(kind),
                              request.lowLatency ? ", tuned for latency" : "", refusals);
        if (request.announce) std::fprintf(stderr, "vitrine: %s: %s\n", target.c_str(), choice_.c_str());
        return;
      } catch (const NotOpened& failed) {
        reason = failed.reason;
      }
    } else {
      reason = "this FFmpeg has none";
    }
    codec_.reset();
    device_.reset();
    surfaces_.reset();
    scaler_.reset();
    upload_.reset();
    refusals += fmt::format("; {}: {}", name, reason);
  }
  throw Error(fmt::format("Cannot write {}: no {} encoder would start{}.", target, codecName(request.codec), refusals));
}

HardwareEncoder::~HardwareEncoder() = default;

void HardwareEncoder::open(EncoderKind kind, const AVCodec& encoder) {
  const EncoderRequest& r = request_;
  codec_.reset(avcodec_alloc_context3(&encoder));
  if (!codec_) throw std::bad_alloc();
  AVCodecContext& c = *codec_;
  c.width = int(r.width);
  c.height = int(r.height);
  c.framerate = av_d2q(r.fps, 1'000'000);
  c.time_base = av_inv_q(c.framerate);
  c.thread_count = 0;  // as many as the encoder finds useful
  tagColour(c, false, false);
  if (r.globalHeader) c.flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  if (r.bitrate) c.bit_rate = *r.bitrate;
  if (r.lowLatency) {
    c.gop_size = std::max(1, int(std::lround(r.fps * r.keyframeSeconds)));
    c.max_b_frames = 0;
    if (r.bitrate) c.rc_max_rate = *r.bitrate, c.rc_buffer_size = int(std::min<int64_t>(*r.bitrate, INT32_MAX));
  }

  const AVPixelFormat rgba = AV_PIX_FMT_RGBA;
  switch (kind) {
    case EncoderKind::Nvenc:
      c.pix_fmt = AV_PIX_FMT_RGB0;  // the RGBA bytes as they are; the alpha byte ignored
      // NVENC turns RGB into Y'CbCr with BT.601's matrix, and FFmpeg's VUI says so: the stream agrees.
      c.colorspace = AVCOL_SPC_BT470BG;
      if (r.lowLatency) {
        setOption(c, "preset", "p4");
        setOption(c, "tune", "ull");
        setOption(c, "rc", "cbr");
        setOption(c, "zerolatency", "1");
        setOption(c, "delay", "0");
      } else {
        setOption(c, "preset", "p5");
        setOption(c, "tune", "hq");
        setOption(c, "rc", "vbr");
        if (r.crf && !r.bitrate) setOption(c, "cq", std::to_string(*r.crf));
      }
      break;
    case EncoderKind::Vaapi: {
      const std::string node = r.renderNode.empty() ? firstRenderNode() : r.renderNode;
      if (node.empty()) throw NotOpened{"no render node in /dev/dri"};
      LibavMessages messages;
      AVBufferRef* device = nullptr;
      const int made = av_hwdevice_ctx_create(&device, AV_HWDEVICE_TYPE_VAAPI, node.c_str(), nullptr, 0);
      if (made < 0)
        throw NotOpened{fmt::format("{} would not open: {}", node,
                                    messages.text().empty() ? avErrorText(made) : messages.text())};
      device_.reset(device);
      surfaces_.reset(av_hwframe_ctx_alloc(device_.get()));
      if (!surfaces_) throw std::bad_alloc();
      auto* frames = reinterpret_cast<AVHWFramesContext*>(surfaces_->data);
      frames->format = AV_PIX_FMT_VAAPI;
      frames->sw_format = AV_PIX_FMT_NV12;
      frames->width = c.width;
      frames->height = c.height;
      frames->initial_pool_size = 16;
      if (const int init = av_hwframe_ctx_init(surfaces_.get()); init < 0)
        throw NotOpened{fmt::format("{} has no NV12 surfaces of {}x{}: {}", node, r.width, r.height, avErrorText(init))};
      c.pix_fmt = AV_PIX_FMT_VAAPI;
      c.hw_frames_ctx = av_buffer_ref(surfaces_.get());
      if (r.lowLatency) setOption(c, "rc_mode", r.bitrate ? "CBR" : "CQP");
      else if (r.crf && !r.bitrate) setOption(c, "rc_mode", "CQP"), setOption(c, "qp", std::to_string(*r.crf));
      scaler_ = rgbToYuv(r.width, r.height, rgba, AV_PIX_FMT_NV12, false, target_);
      upload_ = makeFrame();
      upload_->format = AV_PIX_FMT_NV12;
      upload_->width = c.width;
      upload_->height = c.height;
      if (av_frame_get_buffer(upload_.get(), 0) < 0) throw std::bad_alloc();
      break;
    }
    case EncoderKind::Software:
      c.pix_fmt = AV_PIX_FMT_YUV420P;
      if (request_.codec == Codec::Hevc) setOption(c, "x265-params", "log-level=error");  // x265 prints a page otherwise
      if (r.lowLatency) {
        setOption(c, "preset", "veryfast");
        setOption(c, "tune", "zerolatency");
      } else if (r.crf && !r.bitrate) {
        setOption(c, "crf", std::to_string(*r.crf));
      }
      scaler_ = rgbToYuv(r.width, r.height, rgba, c.pix_fmt, false, target_);
      break;
  }

  LibavMessages messages;
  const int opened = avcodec_open2(&c, &encoder, nullptr);
  if (opened < 0) throw NotOpened{messages.text().empty() ? avErrorText(opened) : messages.text()};

  if (kind != EncoderKind::Vaapi) {
    frame_->format = c.pix_fmt;
    frame_->width = c.width;
    frame_->height = c.height;
    if (av_frame_get_buffer(frame_.get(), 0) < 0) throw std::bad_alloc();
  }
}

const AVFrame& HardwareEncoder::frame(const uint8_t* rgba, int64_t pts) {
  const int stride = int(request_.width) * 4;
  const uint8_t* planes[1] = {rgba};
  const int strides[1] = {stride};
  if (kind_ == EncoderKind::Vaapi) {
    sws_scale(scaler_.get(), planes, strides, 0, int(request_.height), upload_->data, upload_->linesize);
    frame_ = makeFrame();  // the encoder holds the last surface until it is done with it
    checkAv(av_hwframe_get_buffer(surfaces_.get(), frame_.get(), 0), target_, "taking a VAAPI surface");
    checkAv(av_hwframe_transfer_data(frame_.get(), upload_.get(), 0), target_, "uploading a frame to VAAPI");
  } else {
    // The encoder may still hold the buffer (frame threads, lookahead): a fresh one then.
    checkAv(av_frame_make_writable(frame_.get()), target_, "allocating a frame");
    if (kind_ == EncoderKind::Nvenc) {
      for (uint32_t y = 0; y < request_.height; ++y)
        std::memcpy(frame_->data[0] + size_t(y) * size_t(frame_->linesize[0]), rgba + size_t(y) * size_t(stride),
                    size_t(stride));
    } else {
      sws_scale(scaler_.get(), planes, strides, 0, int(request_.height), frame_->data, frame_->linesize);
    }
  }
  frame_->pts = pts;
  return *frame_;
}

}  // namespace vitrine::film
