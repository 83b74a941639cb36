#include "film/stream_sender.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <climits>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "core/error.h"
#include "film/hardware_encoder.h"
#include "film/libav.h"
#include "film/sound_track.h"

namespace vitrine::film {
namespace {

using Clock = std::chrono::steady_clock;
constexpr int kSoundRate = 48000;
constexpr double kFirstPause = 0.5, kLongestPause = 5.0;  // seconds between tries, doubling

std::string_view schemeOf(std::string_view url) {
  const size_t colon = url.find("://");
  return colon == std::string_view::npos ? std::string_view() : url.substr(0, colon);
}

// Thrown out of a connection when the sender is stopping: no error, no retry.
struct Stopping {};

}  // namespace

std::string streamMuxer(std::string_view url) {
  const std::string_view scheme = schemeOf(url);
  if (scheme.empty())
    throw Error(fmt::format("Cannot stream to {}: a stream's URL is scheme://host:port (srt://, rtmp://, rtp://, "
                            "udp://).",
                            url));
  std::string muxer;
  if (scheme == "srt" || scheme == "udp") muxer = "mpegts";
  else if (scheme == "rtp") muxer = "rtp_mpegts";
  else if (scheme == "rtmp" || scheme == "rtmps") muxer = "flv";
  else
    throw Error(fmt::format("Cannot stream to {}: {}:// is not a stream's scheme; use srt://, rtmp://, rtmps://, "
                            "rtp:// or udp://.",
                            url, scheme));
  const std::string_view rest = url.substr(scheme.size() + 3);
  if (rest.empty() || rest.front() == ':' || rest.front() == '/' || rest.front() == '?')
    throw Error(fmt::format("Cannot stream to {}: the URL names no host.", url));
  return muxer;
}

struct StreamSender::Worker {
  struct Frame {
    std::vector<uint8_t> rgba;
    double seconds = 0;
  };

  // One connection: the muxer writing to the network, the encoders feeding it. Made afresh for each,
  // so every connection starts with its headers and a keyframe, its times from zero.
  struct Connection {
    OutputPtr output;
    std::unique_ptr<HardwareEncoder> video;
    AVStream* stream = nullptr;
    std::optional<SoundTrack> sound;
    PacketPtr packet = makePacket();
    std::optional<int64_t> firstPts;  // the stream's frame number of this connection's first frame
    int64_t lastPts = -1;
    int64_t soundBase = 0;  // the sound's sample at this connection's first frame
  };

  StreamSettings settings;
  std::string muxer;  // empty: the URL cannot be streamed to
  size_t capacity;

  mutable std::mutex mutex;
  std::condition_variable wake;
  bool stopping = false;
  std::deque<Frame> queue;
  std::vector<std::vector<uint8_t>> spare;  // frame buffers to reuse
  std::vector<float> sound;                 // interleaved stereo, waiting for the worker
  int64_t soundStart = 0;                   // the sample of sound's first frame on the stream's clock
  StreamHealth health;
  bool everConnected = false;
  bool announced = false;  // the encoder's choice said: once, not at every try

  std::atomic<bool> stopFlag{false};
  std::atomic<int64_t> stopAt{INT64_MAX};  // Clock's ticks: closing, the stream is cut then
  std::atomic<int64_t> deadline{0};  // Clock's ticks: a network call still waiting then is given up
  std::thread thread;

  explicit Worker(const StreamSettings& s) : settings(s) {
    capacity = size_t(std::clamp(std::lround(settings.latencyMs / 1000.0 * settings.fps / 2.0), 2L, 8L));
    try {
      muxer = streamMuxer(settings.url);
      health.line = fmt::format("connecting to {}", settings.url);
    } catch (const Error& e) {
      health.line = e.what();
      health.stopped = true;
      std::fprintf(stderr, "vitrine: %s The run goes on without it.\n", e.what());
      return;
    }
    thread = std::thread([this] { run(); });
  }

  ~Worker() { close(); }

  // No more frames; what waits is sent and the stream ended within a second, or at once when there
  // is no connection (connecting, or pausing before the next try).
  void close() {
    {
      std::lock_guard lock(mutex);
      if (stopping) return;
      stopping = true;
      if (!health.connected) stopFlag = true;
    }
    stopAt = (Clock::now() + std::chrono::seconds(1)).time_since_epoch().count();
    wake.notify_all();
    if (thread.joinable()) thread.join();
  }

  void setLine(std::string line, bool connected) {
    std::lock_guard lock(mutex);
    health.line = std::move(line);
    health.connected = connected;
    if (!connected) {  // what waited is the lost connection's
      for (Frame& f : queue) spare.push_back(std::move(f.rgba));
      queue.clear();
      soundStart += int64_t(sound.size() / 2);
      sound.clear();
    }
  }

  static int interrupted(void* opaque) {
    const auto* w = static_cast<const Worker*>(opaque);
    const int64_t now = Clock::now().time_since_epoch().count();
    return w->stopFlag.load() || now > w->deadline.load() || now > w->stopAt.load();
  }
  void armDeadline(double seconds) {
    deadline = (Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds)))
                   .time_since_epoch()
                   .count();
  }
  bool timedOut() const { return Clock::now().time_since_epoch().count() > deadline.load(); }

  void run() {
    double pause = kFirstPause;
    while (!stopFlag) {
      std::string reason;
      try {
        Connection c = connect();
        pause = kFirstPause;
        pump(c);  // until stopping
        end(c);
        return;
      } catch (const Stopping&) {
        return;
      } catch (const Error& e) {
        reason = e.what();
      } catch (const std::exception& e) {
        reason = fmt::format("Cannot write {}: {}.", settings.url, e.what());
      }
      if (stopFlag || Clock::now().time_since_epoch().count() > stopAt.load()) return;
      std::fprintf(stderr, "vitrine: %s Trying again in %.1f s.\n", reason.c_str(), pause);
      setLine(fmt::format("{} Trying again in {:.1f} s.", reason, pause), false);
      std::unique_lock lock(mutex);
      wake.wait_for(lock, std::chrono::duration<double>(pause), [&] { return stopping; });
      pause = std::min(pause * 2, kLongestPause);
    }
  }

  // Opens the network and the encoders, writes the headers. Throws vitrine::Error saying why not
  // (timed out, refused), or Stopping.
  Connection connect() {
    const std::string& url = settings.url;
    Connection c;
    AVFormatContext* raw = nullptr;
    checkAv(avformat_alloc_output_context2(&raw, nullptr, muxer.c_str(), url.c_str()), url, "choosing the muxer");
    c.output.reset(raw);
    AVFormatContext& out = *c.output;
    out.interrupt_callback = {&Worker::interrupted, this};
    // The muxer holds a stream's packets at most this long waiting for the other's, so the picture
    // is not held back by a sound that comes late. MPEG-TS takes a sound packet older than the picture
    // already written; FLV and RTP refuse it (and the connection with it), so they wait up to a second.
    const bool strict = muxer != "mpegts";
    out.max_interleave_delta = (strict ? 1000 : std::max(100, settings.latencyMs)) * int64_t(1000);

    EncoderRequest request;
    request.width = settings.width;
    request.height = settings.height;
    request.fps = settings.fps;
    request.bitrate = settings.bitrate;
    request.lowLatency = true;
    // FLV carries the parameter sets once, in its header; MPEG-TS (and RTP's) in the stream, before every
    // keyframe, so a receiver that joins late (or an RTP muxer that would keep them apart) can decode.
    request.globalHeader = muxer == "flv";
    request.announce = !announced;
    announced = true;
    c.video = std::make_unique<HardwareEncoder>(request, url);
    c.stream = avformat_new_stream(&out, nullptr);
    if (!c.stream) throw std::bad_alloc();
    checkAv(avcodec_parameters_from_context(c.stream->codecpar, &c.video->codec()), url, "describing the video");
    c.stream->time_base = c.video->codec().time_base;
    c.stream->avg_frame_rate = c.video->codec().framerate;
    if (settings.sound) c.sound.emplace(out, settings.url, "aac");

    AVDictionary* options = nullptr;
    const std::string_view scheme = schemeOf(url);
    if (scheme == "srt") {
      av_dict_set_int(&options, "latency", int64_t(settings.latencyMs) * 1000, 0);  // microseconds
      av_dict_set_int(&options, "connect_timeout", std::lround(settings.timeoutSeconds * 1000), 0);  // ms
      av_dict_set_int(&options, "linger", 1, 0);  // closing waits a second at most for the packets still unsent
    }
    if (scheme == "udp") av_dict_set(&options, "pkt_size", "1316", 0);  // seven TS packets a datagram
    armDeadline(settings.timeoutSeconds);
    LibavMessages messages;
    const int opened = avio_open2(&out.pb, url.c_str(), AVIO_FLAG_WRITE, &out.interrupt_callback, &options);
    av_dict_free(&options);
    if (stopFlag) throw Stopping{};
    if (opened < 0) {
      if (opened == AVERROR_EXIT || timedOut())
        throw Error(fmt::format("Cannot connect to {}: no answer within {:g} s.", url, settings.timeoutSeconds));
      throw Error(fmt::format("Cannot connect to {}: {}.", url,
                              messages.text().empty() ? avErrorText(opened) : messages.text()));
    }
    AVDictionary* header = nullptr;
    if (muxer == "flv") av_dict_set(&header, "flvflags", "no_duration_filesize", 0);
    const int written = avformat_write_header(&out, &header);
    av_dict_free(&header);
    checkAv(written, url, "writing the stream's header");

    const std::string line =
        fmt::format("streaming to {}: {} {}x{} at {:g} fps, {:.1f} Mbit/s{}", url, c.video->name(), settings.width,
                    settings.height, settings.fps, double(settings.bitrate) / 1e6, settings.sound ? ", AAC sound" : "");
    {
      std::lock_guard lock(mutex);
      if (everConnected) ++health.reconnects;
      everConnected = true;
    }
    std::fprintf(stderr, "vitrine: %s\n", line.c_str());
    setLine(line, true);
    return c;
  }

  void pump(Connection& c) {
    for (;;) {
      Frame frame;
      std::vector<float> stretch;
      int64_t stretchStart = 0;
      {
        std::unique_lock lock(mutex);
        wake.wait(lock, [&] { return stopping || !queue.empty(); });
        if (queue.empty()) return;  // closing, and all sent
        frame = std::move(queue.front());
        queue.pop_front();
        stretch.swap(sound);
        stretchStart = soundStart;
        soundStart += int64_t(stretch.size() / 2);
      }
      sendFrame(c, frame);
      if (c.sound) sendSound(c, stretch, stretchStart);
      std::lock_guard lock(mutex);
      spare.push_back(std::move(frame.rgba));
    }
  }

  // Fails (throws) with the reason when a write is refused or takes longer than the timeout.
  template <typename Write>
  void guarded(Write&& write) {
    armDeadline(settings.timeoutSeconds);
    try {
      write();
    } catch (const Error& e) {
      if (stopFlag || Clock::now().time_since_epoch().count() > stopAt.load()) throw Stopping{};
      if (timedOut())
        throw Error(fmt::format("The stream to {} was lost: nothing went through for {:g} s.", settings.url,
                                settings.timeoutSeconds));
      std::string_view why = e.what();  // checkAv's "Cannot write URL: WHAT failed: REASON."
      if (const std::string prefix = fmt::format("Cannot write {}: ", settings.url); why.starts_with(prefix))
        why.remove_prefix(prefix.size());
      throw Error(fmt::format("The stream to {} was lost: {}", settings.url, why));
    }
  }

  void sendFrame(Connection& c, const Frame& frame) {
    const int64_t number = std::llround(frame.seconds * settings.fps);
    if (!c.firstPts) {
      c.firstPts = number;
      c.soundBase = std::llround(double(number) / settings.fps * kSoundRate);
    }
    const int64_t pts = number - *c.firstPts;
    if (pts <= c.lastPts) return;  // given faster than the stream's rate: the next one is the same frame
    c.lastPts = pts;
    guarded([&] {
      encodeInto(c.video->codec(), &c.video->frame(frame.rgba.data(), pts), *c.output, *c.stream, *c.packet,
                 settings.url, "the video");
    });
    std::lock_guard lock(mutex);
    ++health.sent;
  }

  // The stretch starting at sample `start` on the stream's clock, into the connection's sound from
  // its first frame's sample: what came before dropped, a gap (sound dropped) filled with silence.
  void sendSound(Connection& c, std::vector<float>& stretch, int64_t start) {
    if (!c.firstPts) return;
    const int64_t next = c.soundBase + c.sound->given();
    if (start > next) stretch.insert(stretch.begin(), size_t(start - next) * 2, 0.0f);
    else if (start < next) stretch.erase(stretch.begin(), stretch.begin() + std::min<ptrdiff_t>(ptrdiff_t(next - start) * 2, ptrdiff_t(stretch.size())));
    if (!stretch.empty()) guarded([&] { c.sound->add(stretch); });
  }

  // Drains the encoder and ends the stream cleanly, given a second at most.
  void end(Connection& c) {
    armDeadline(1.0);
    try {
      encodeInto(c.video->codec(), nullptr, *c.output, *c.stream, *c.packet, settings.url, "the video");
      av_write_trailer(c.output.get());
    } catch (const Error&) {
      // a stream that ends as it is cut loses its last frames, which nobody waits for
    }
  }
};

StreamSender::StreamSender(const StreamSettings& settings) : worker_(std::make_unique<Worker>(settings)) {}
StreamSender::~StreamSender() = default;

bool StreamSender::pushFrame(std::span<const uint8_t> rgba, double seconds) {
  Worker& w = *worker_;
  std::vector<uint8_t> buffer;
  {
    std::lock_guard lock(w.mutex);
    if (w.health.stopped || w.stopping) return false;
    if (!w.health.connected) return ++w.health.disconnected, false;
    if (w.queue.size() >= w.capacity) return ++w.health.dropped, false;
    if (!w.spare.empty()) buffer = std::move(w.spare.back()), w.spare.pop_back();
  }
  buffer.assign(rgba.begin(), rgba.end());  // outside the lock: the worker pops meanwhile
  {
    std::lock_guard lock(w.mutex);
    w.queue.push_back({std::move(buffer), seconds});
  }
  w.wake.notify_one();
  return true;
}

void StreamSender::pushSound(std::span<const float> stereo48k) {
  Worker& w = *worker_;
  std::lock_guard lock(w.mutex);
  if (!w.health.connected) {  // nobody to send it to: the clock moves on
    w.soundStart += int64_t(stereo48k.size() / 2);
    return;
  }
  w.sound.insert(w.sound.end(), stereo48k.begin(), stereo48k.end());
  const size_t most = size_t(kSoundRate) * 2;  // a second: the worker is far behind, the oldest goes
  if (w.sound.size() > most) {
    const size_t over = (w.sound.size() - most) & ~size_t(1);
    w.sound.erase(w.sound.begin(), w.sound.begin() + std::ptrdiff_t(over));
    w.soundStart += int64_t(over / 2);
  }
}

void StreamSender::close() { worker_->close(); }

StreamHealth StreamSender::health() const {
  std::lock_guard lock(worker_->mutex);
  return worker_->health;
}

const StreamSettings& StreamSender::settings() const { return worker_->settings; }

}  // namespace vitrine::film
