#pragma once
// FFmpeg's objects owned like any other resource: each freed by the call FFmpeg pairs with its making,
// whatever path a run leaves by (an error, an interrupt). Only src/film/*.cpp include this, and so
// FFmpeg's headers.
extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/hwcontext.h>
#include <libavutil/opt.h>
#include <libavutil/pixdesc.h>
#include <libswresample/swresample.h>
#include <libswscale/swscale.h>
}

#include <memory>
#include <string>
#include <string_view>

namespace vitrine::film {

struct FreeCodec {
  void operator()(AVCodecContext* c) const { avcodec_free_context(&c); }
};
struct FreeFrame {
  void operator()(AVFrame* f) const { av_frame_free(&f); }
};
struct FreePacket {
  void operator()(AVPacket* p) const { av_packet_free(&p); }
};
struct FreeBuffer {
  void operator()(AVBufferRef* b) const { av_buffer_unref(&b); }
};
struct FreeScaler {
  void operator()(SwsContext* s) const { sws_freeContext(s); }
};
struct FreeResampler {
  void operator()(SwrContext* s) const { swr_free(&s); }
};
// An input file opened by avformat_open_input.
struct CloseInput {
  void operator()(AVFormatContext* f) const { avformat_close_input(&f); }
};
// An output file: its I/O closed (when opened), then the muxer freed. A muxer whose trailer was never
// written leaves a file that is not a film; its owner removes it.
struct CloseOutput {
  void operator()(AVFormatContext* f) const {
    if (f->pb && !(f->oformat->flags & AVFMT_NOFILE)) avio_closep(&f->pb);
    avformat_free_context(f);
  }
};

using CodecPtr = std::unique_ptr<AVCodecContext, FreeCodec>;
using FramePtr = std::unique_ptr<AVFrame, FreeFrame>;
using PacketPtr = std::unique_ptr<AVPacket, FreePacket>;
using BufferPtr = std::unique_ptr<AVBufferRef, FreeBuffer>;
using ScalerPtr = std::unique_ptr<SwsContext, FreeScaler>;
using ResamplerPtr = std::unique_ptr<SwrContext, FreeResampler>;
using InputPtr = std::unique_ptr<AVFormatContext, CloseInput>;
using OutputPtr = std::unique_ptr<AVFormatContext, CloseOutput>;

// FFmpeg's words for an error code ("No space left on device", "Invalid argument").
std::string avErrorText(int code);
// Throws vitrine::Error "Cannot write TARGET: WHAT failed: REASON" for a negative code; returns it otherwise.
int checkAv(int code, const std::string& target, std::string_view what);

FramePtr makeFrame();
PacketPtr makePacket();
// A muxer writing `path` as `muxer` ("mp4", "mov", "matroska"), its file opened. Throws vitrine::Error.
OutputPtr openOutput(const std::string& muxer, const std::string& path, const std::string& target);
// Sends `frame` to `codec` (null: the end, draining it) and hands every packet it gives back to
// `output`'s muxer as `stream`'s, which interleaves the streams by time. Throws vitrine::Error naming
// `target` and `what` ("the video", "the sound").
void encodeInto(AVCodecContext& codec, const AVFrame* frame, AVFormatContext& output, AVStream& stream,
                AVPacket& packet, const std::string& target, std::string_view what);
struct FilmFormat;
// The muxer's options for a film in `format`'s container (both passes write the same), for
// avformat_write_header; the caller frees what it leaves.
AVDictionary* muxerOptions(const FilmFormat& format);
// FFmpeg logs only what is wrong, on stderr: errors, not its banner of warnings for every stream.
void quietLibav();

// What FFmpeg logs on this thread while one is alive, kept rather than printed: why an encoder would
// not open ("Cannot load libcuda.so.1") is then part of the sentence that says so. Other threads log
// as before.
class LibavMessages {
 public:
  LibavMessages();
  ~LibavMessages();
  LibavMessages(const LibavMessages&) = delete;
  LibavMessages& operator=(const LibavMessages&) = delete;
  // The messages so far, trimmed, joined by "; "; empty when there were none.
  std::string text() const { return text_; }
  void keep(std::string_view line);

 private:
  std::string text_;
  LibavMessages* outer_;
};

// The film's and the stream's colour tags, on the encoder (into H.264's and HEVC's VUI) and through it
// on the stream: BT.709 primaries with the sRGB transfer curve (iec61966-2-1), since what is encoded
// are exactly the sRGB-encoded display values; the matrix BT.709's, or none for RGB.
void tagColour(AVCodecContext& codec, bool rgb, bool fullRange);
// The scaler from packed RGB (`source`: RGB24, RGBA, RGB48) to Y'CbCr as `yuv`, with BT.709's matrix,
// into limited (tv) or full (pc) range, chroma subsampled from every input pixel, rounded accurately.
// Throws vitrine::Error naming `target`.
ScalerPtr rgbToYuv(uint32_t width, uint32_t height, AVPixelFormat source, AVPixelFormat yuv, bool fullRange,
                   const std::string& target);

}  // namespace vitrine::film
