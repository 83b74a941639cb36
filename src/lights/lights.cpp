#include "lights/lights.h"

#include "lights/ola_link.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <utility>

namespace vitrine::lights {
namespace {

double seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

Lights::Lights(Patch patch) : patch_(std::move(patch)), master_(patch_.master) {
  thread_ = std::thread([this] { run(); });
}

Lights::~Lights() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void Lights::publish(SmallFrame frame, Signals sceneSignals) {
  {
    std::lock_guard lock(mutex_);
    published_.emplace(std::move(frame), std::move(sceneSignals));
    raw_.reset();
    ++publishedSerial_;
  }
  wake_.notify_all();
}

void Lights::publishSrgb8(std::vector<uint8_t> rgba, uint32_t width, uint32_t height, Signals sceneSignals) {
  {
    std::lock_guard lock(mutex_);
    raw_.emplace(RawFrame{std::move(rgba), width, height}, std::move(sceneSignals));
    published_.reset();
    ++publishedSerial_;
  }
  wake_.notify_all();
}

void Lights::setMaster(float master) {
  master_ = std::clamp(std::isfinite(master) ? master : 0.0f, 0.0f, 1.0f);
  wake_.notify_all();
}

void Lights::setBlackout(bool on) {
  blackout_ = on;
  wake_.notify_all();
}

void Lights::listen(std::vector<uint32_t> universes) {
  std::lock_guard lock(mutex_);
  if (universes == extraListen_) return;
  extraListen_ = std::move(universes);
  listenChanged_ = true;
}

double Lights::clockSeconds() { return seconds(); }

std::vector<Lights::Input> Lights::takeInput() {
  std::vector<Input> changed;
  std::lock_guard lock(mutex_);
  for (auto& [universe, arrived] : inputChanged_)
    if (arrived > 0.0) changed.push_back({universe, input_[universe], std::exchange(arrived, 0.0)});
  return changed;
}

bool Lights::flush(double wait) {
  std::unique_lock lock(mutex_);
  const uint64_t serial = publishedSerial_;
  wake_.wait_for(lock, std::chrono::duration<double>(wait),
                 [&] { return sentSerial_ >= serial || (!counts_.connected && tries_ > 0); });
  return sentSerial_ >= serial;
}

Lights::Counts Lights::counts() const {
  std::lock_guard lock(mutex_);
  return counts_;
}

std::string Lights::status() const {
  const Counts c = counts();
  return fmt::format("lights: {} fixtures, olad on port {} {}; {} frames sent, {} in{}{}", patch_.fixtures.size(), patch_.oladPort,
                     c.connected ? "connected" : "not connected", c.framesSent, c.framesIn, blackout() ? "; BLACKOUT" : "",
                     c.held > 0 ? fmt::format("; {} changes held by the flash limit", c.held) : "");
}

void Lights::say(const std::string& line) {
  if (line == said_) return;  // once a state change, never a flood
  said_ = line;
  std::fprintf(stderr, "vitrine: lights: %s\n", line.c_str());
}

Signals Lights::signalsOf(const SmallFrame& frame, const Signals& scene) const {
  Signals signals = scene;
  if (frame.width > 0) {
    signals.set("regions", regionMeans(frame, patch_.gridWidth, patch_.gridHeight));
    std::vector<glm::vec3> dominant;
    for (const ColourCluster& cluster : dominantColours(shrink(frame, kSmallWidth, kSmallHeight), kDominantColours))
      dominant.push_back(cluster.colour);
    signals.set("dominant", std::move(dominant));
  }
  return signals;
}

void Lights::sendFrame(OlaLink& link, double now, bool all) {
  const float dt = lastFrame_ > 0.0 ? float(now - lastFrame_) : 0.0f;
  lastFrame_ = now;
  const std::vector<glm::vec3> shown = guard_.limit(lightColours(patch_, signals_, master_.load()), dt, blackout_.load());
  uint64_t sent = 0;
  for (const auto& [universe, channels] : pack(patch_, shown)) {
    const auto last = lastSent_.find(universe);
    const bool changed = last == lastSent_.end() || last->second != channels;
    if (!all && !changed && now - sentAt_[universe] < kKeepAliveSeconds) continue;
    link.send(universe, channels);
    lastSent_[universe] = channels;
    sentAt_[universe] = now;
    ++sent;
  }
  std::lock_guard lock(mutex_);
  counts_.framesSent += sent;
  counts_.held = guard_.held();
}

void Lights::run() {
  OlaLink link(patch_.oladPort, [this](uint32_t universe, const uint8_t* channels, size_t count) {
    Universe values{};
    std::copy(channels, channels + count, values.begin());
    std::lock_guard lock(mutex_);
    ++counts_.framesIn;
    Universe& held = input_[universe];
    if (held != values) held = values, inputChanged_[universe] = seconds();
  });
  double nextTry = 0.0, nextFrame = 0.0;
  bool fresh = false;  // a new connection: every universe is sent at once
  bool lit = false;    // a frame has been published
  std::optional<std::pair<uint64_t, uint64_t>> answered;  // a publication sent, and the frames olad must answer for
  for (;;) {
    double now = seconds();
    if (!link.connected()) {
      if (now >= nextTry) {
        const std::string why = link.connect();
        nextTry = now + kRetrySeconds;
        std::lock_guard lock(mutex_);
        ++tries_;
        counts_.connected = why.empty();
        if (why.empty()) {
          ++counts_.connections;
          fresh = listenChanged_ = true;
        }
        wake_.notify_all();
      }
      if (link.connected()) {
        say(fmt::format("olad connected on port {}", patch_.oladPort));
      } else {
        say(fmt::format("no olad on port {}: the lights are off; trying again every {:g} s", patch_.oladPort, kRetrySeconds));
        std::unique_lock lock(mutex_);
        wake_.wait_for(lock, std::chrono::duration<double>(std::max(0.0, nextTry - seconds())), [&] { return stop_; });
        if (stop_) break;
        continue;
      }
    }
    std::vector<uint32_t> universes;
    bool relisten = false;
    std::optional<std::pair<SmallFrame, Signals>> taken;
    std::optional<std::pair<RawFrame, Signals>> takenRaw;
    uint64_t serial = 0;
    {
      std::lock_guard lock(mutex_);
      if (stop_) break;
      relisten = std::exchange(listenChanged_, false);
      universes = patch_.input;
      for (uint32_t u : extraListen_)
        if (std::find(universes.begin(), universes.end(), u) == universes.end()) universes.push_back(u);
      if (published_) taken = std::move(published_), published_.reset();
      if (raw_) takenRaw = std::move(raw_), raw_.reset();
      serial = publishedSerial_;
    }
    if (relisten) link.listen(universes);
    if (takenRaw)  // decoded here rather than on the frame thread
      taken.emplace(reduceSrgb8(takenRaw->first.rgba.data(), takenRaw->first.width, takenRaw->first.height, takenRaw->first.width * 4),
                    std::move(takenRaw->second));
    if (taken) signals_ = signalsOf(taken->first, taken->second), lit = true;
    now = seconds();
    if (lit && now >= nextFrame) {  // nothing before the first frame: a fixture keeps what it had
      sendFrame(link, now, std::exchange(fresh, false));
      nextFrame = std::max(nextFrame + 1.0 / kFramesPerSecond, now);
      answered = {serial, link.sent()};
    }
    // Until the next frame is due; before the first publication there is none (a desk's frames still come).
    const bool up = link.pump(lit ? std::clamp(nextFrame - seconds(), 0.0, 0.05) : 0.05);
    if (up && answered && link.acknowledged() >= answered->second) {  // olad has this publication's frames
      std::lock_guard lock(mutex_);
      sentSerial_ = std::max(sentSerial_, answered->first);
      answered.reset();
      wake_.notify_all();
    }
    if (!up) {
      answered.reset();
      say("olad went away: the lights are off until it is back");
      nextTry = seconds() + 0.5;  // a restart: olad is usually back within a second
      std::lock_guard lock(mutex_);
      counts_.connected = false;
      lastSent_.clear();
    }
  }
}

}  // namespace vitrine::lights
