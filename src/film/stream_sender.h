#pragma once
// A live stream of the picture and its sound to a URL: SRT, UDP and RTP carry MPEG-TS, RTMP carries
// FLV; the video h264 from the encoder the machine has (film/hardware_encoder.h), the sound AAC at
// 48 kHz stereo. A worker thread owns the encoder and the network: the frame thread only copies a
// frame into a bounded queue, and a frame the queue has no room for is dropped and counted, never
// waited for. A connection that fails or drops is reported and tried again with a growing pause; a
// URL that never answers times out; stopping is prompt even while connecting.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace vitrine::film {

// What the command line set: --stream, --stream-bitrate, --stream-latency.
struct StreamSettings {
  std::string url;
  uint32_t width = 0, height = 0;
  double fps = 60;
  int64_t bitrate = 6'000'000;  // bits a second, video; the sound's AAC adds 160 kbit/s
  int latencyMs = 200;          // SRT's latency (the receiver's buffer) and the queue's depth
  bool sound = true;
  // Seconds a connection may take to open, or a write to go through, before it counts as lost.
  double timeoutSeconds = 3.0;
};

// The container for a URL: "mpegts" for srt://, udp://; "rtp_mpegts" for rtp://; "flv" for rtmp://
// and rtmps://. Throws vitrine::Error for a URL that is not one (no scheme, another scheme, no host).
std::string streamMuxer(std::string_view url);

// How the stream fares, for the console, the menu and the remote page.
struct StreamHealth {
  std::string line;          // "streaming to srt://...: h264 (libx264) 1280x720 at 60 fps, 4.1 Mbit/s"
  uint64_t sent = 0;         // frames encoded and written
  uint64_t dropped = 0;      // frames dropped: the queue was full (the encoder or the network behind)
  uint64_t disconnected = 0; // frames given while there was no connection
  uint64_t reconnects = 0;   // connections made after the first
  bool connected = false;
  bool stopped = false;      // gave up for good (a URL that cannot be streamed to): see line
};

class StreamSender {
 public:
  // Starts the worker, which connects. Never throws for the URL or the network: a URL that cannot
  // be streamed to is said once on stderr and in health(), and every push is then a no-op.
  explicit StreamSender(const StreamSettings& settings);
  ~StreamSender();  // stops the worker promptly, ending the stream cleanly when it is connected
  StreamSender(const StreamSender&) = delete;
  StreamSender& operator=(const StreamSender&) = delete;

  // The frame at `seconds` on the stream's clock (from its first frame), width x height RGBA display
  // values, rows packed. Copies it and returns at once: false when it was dropped.
  bool pushFrame(std::span<const uint8_t> rgba, double seconds);
  // The sound's next stretch, interleaved stereo at 48 kHz, following the last, on the same clock
  // (its first sample at 0 s). Dropped when the worker is over a second behind.
  void pushSound(std::span<const float> stereo48k);

  // Ends the stream: no more frames are taken, those waiting are sent and the stream closed cleanly
  // within a second (at once when not connected). The destructor does it too.
  void close();

  StreamHealth health() const;
  const StreamSettings& settings() const;

 private:
  struct Worker;
  std::unique_ptr<Worker> worker_;
};

}  // namespace vitrine::film
