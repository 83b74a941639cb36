#pragma once
// The video encoder for h264 or hevc chosen from what the machine has: NVIDIA's NVENC where it opens,
// VAAPI where a render node exists and its driver opens, the software encoder (libx264, libx265)
// otherwise. Each is tried for real (avcodec_open2), so a driver that is installed but cannot start
// falls through to the next; one console line says which was picked and why the others were not.
// Frames go in as 8-bit RGBA display values in system memory, whatever the encoder takes: NVENC takes
// them as they are (RGB0, converted on the GPU), VAAPI as NV12 uploaded to its surfaces, software as
// yuv420p; all carry BT.709 primaries and the sRGB curve in their tags.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "film/film_format.h"
#include "film/libav.h"

namespace vitrine::film {

enum class EncoderKind { Nvenc, Vaapi, Software };

struct EncoderRequest {
  Codec codec = Codec::H264;  // h264 or hevc
  uint32_t width = 0, height = 0;
  double fps = 60;
  std::optional<int64_t> bitrate;  // bits a second; a stream's is always set
  std::optional<int> crf;          // constant quality (a film's), when no bit rate is given
  // A live stream: no B-frames, no lookahead, a keyframe every `keyframeSeconds`, the rate capped at
  // the bit rate with a buffer (VBV) of one second of it, so a viewer is never far behind.
  bool lowLatency = false;
  double keyframeSeconds = 1.0;
  bool globalHeader = false;  // the muxer wants the parameter sets apart (MP4, FLV), not in the stream
  std::vector<EncoderKind> order = {EncoderKind::Nvenc, EncoderKind::Vaapi, EncoderKind::Software};
  std::string renderNode;  // VAAPI's device; empty: the first /dev/dri/renderD*
  bool announce = true;    // print the choice on stderr (a stream's reconnection does not again)
};

// "h264_nvenc", "h264_vaapi", "libx264" (and hevc's).
std::string encoderName(Codec codec, EncoderKind kind);

class HardwareEncoder {
 public:
  // Opens the first encoder of request.order that starts, and prints the choice on stderr (when
  // request.announce), prefixed with "vitrine: <target>: ". Throws vitrine::Error naming `target` and each encoder's reason when
  // none starts, or for a codec other than h264 and hevc.
  HardwareEncoder(const EncoderRequest& request, const std::string& target);
  ~HardwareEncoder();
  HardwareEncoder(const HardwareEncoder&) = delete;
  HardwareEncoder& operator=(const HardwareEncoder&) = delete;

  EncoderKind kind() const { return kind_; }
  const std::string& name() const { return name_; }
  // The sentence printed: "encoding h264 with libx264 (software, tuned for latency); h264_nvenc did
  // not open: Cannot load libcuda.so.1; h264_vaapi: no render node in /dev/dri".
  const std::string& choice() const { return choice_; }
  AVCodecContext& codec() { return *codec_; }

  // The encoder's next frame from `rgba` (width x height pixels of 4 bytes, rows packed), with `pts`
  // in the encoder's time base (1/fps): valid until the next call. Send it with encodeInto.
  const AVFrame& frame(const uint8_t* rgba, int64_t pts);

 private:
  void open(EncoderKind kind, const AVCodec& encoder);

  EncoderRequest request_;
  std::string target_;
  EncoderKind kind_ = EncoderKind::Software;
  std::string name_, choice_;
  CodecPtr codec_;
  BufferPtr device_, surfaces_;  // VAAPI's device and its frames (surfaces)
  ScalerPtr scaler_;             // RGBA to yuv420p or NV12; none for NVENC
  FramePtr frame_ = makeFrame(), upload_;
};

}  // namespace vitrine::film
