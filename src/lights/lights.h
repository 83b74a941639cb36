#pragma once
// The room's lights (docs/LIGHTS.md): a thread of their own that speaks to olad (lights/ola_link.h),
// sends the patch's fixtures their signals at DMX's own rate (up to kFramesPerSecond, a universe only
// when its values change, and once a second besides so a node that restarted hears them), through the
// master dimmer, the blackout and the flash guard's limits, and keeps the frames of the universes a
// lighting desk plays in on, for the dmx.* live sources. olad absent or restarting: one line when that
// changes, a new try every kRetrySeconds, everything else runs.
//
// The frame thread only publishes (a copy under a lock, never a wait on olad) and takes what came in.
#include "lights/fixtures.h"
#include "lights/frame_colours.h"
#include "lights/light_guard.h"
#include "lights/patch.h"
#include "lights/signals.h"

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace vitrine::lights {

inline constexpr double kFramesPerSecond = 44.0;
inline constexpr double kKeepAliveSeconds = 1.0;
inline constexpr double kRetrySeconds = 3.0;

class Lights {
 public:
  explicit Lights(Patch patch);
  ~Lights();
  Lights(const Lights&) = delete;
  Lights& operator=(const Lights&) = delete;

  const Patch& patch() const { return patch_; }

  // The frame thread: the frame reduced to a small image, and the scene's own signals. The newest wins.
  void publish(SmallFrame frame, Signals sceneSignals);
  // The same from a read-back of the shown frame, 8-bit sRGB RGBA rows tightly packed: reduced on the
  // lights thread.
  void publishSrgb8(std::vector<uint8_t> rgba, uint32_t width, uint32_t height, Signals sceneSignals);
  void setMaster(float master);
  float master() const { return master_.load(); }
  void setBlackout(bool on);
  bool blackout() const { return blackout_.load(); }
  // The universes whose frames come in, besides the patch's "input" (those the mappings read).
  void listen(std::vector<uint32_t> universes);
  // The listened universes whose values changed since the last call, each with when its newest frame
  // arrived (steady clock seconds).
  struct Input {
    uint32_t universe = 0;
    Universe channels{};
    double arrived = 0.0;
  };
  std::vector<Input> takeInput();
  static double clockSeconds();  // the steady clock those times are in (CLOCK_MONOTONIC)

  // Waits, at most `seconds`, until the newest publication has been sent, or olad has been tried and
  // found absent: a headless run's last frame. True when it was sent.
  bool flush(double seconds);

  struct Counts {
    uint64_t framesSent = 0;    // universes' frames sent to olad
    uint64_t framesIn = 0;      // frames received from olad
    uint64_t held = 0;          // light changes the flash limit held back
    uint64_t connections = 0;   // times it connected to olad
    bool connected = false;
  };
  Counts counts() const;
  std::string status() const;  // one line, for the panel and the console

 private:
  void run();
  void sendFrame(class OlaLink& link, double now, bool all);
  Signals signalsOf(const SmallFrame& frame, const Signals& scene) const;
  void say(const std::string& line);

  const Patch patch_;
  std::atomic<float> master_;
  std::atomic<bool> blackout_{false};

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  std::optional<std::pair<SmallFrame, Signals>> published_;
  struct RawFrame {
    std::vector<uint8_t> rgba;
    uint32_t width = 0, height = 0;
  };
  std::optional<std::pair<RawFrame, Signals>> raw_;
  uint64_t publishedSerial_ = 0, sentSerial_ = 0, tries_ = 0;
  std::vector<uint32_t> extraListen_;
  bool listenChanged_ = true;
  std::map<uint32_t, Universe> input_;
  std::map<uint32_t, double> inputChanged_;  // when a changed frame arrived; 0: unchanged since taken
  Counts counts_;
  std::string said_;

  // The lights thread's own.
  Signals signals_;
  LightGuard guard_;
  Universes lastSent_;
  std::map<uint32_t, double> sentAt_;
  double lastFrame_ = 0.0;

  std::thread thread_;
};

}  // namespace vitrine::lights
