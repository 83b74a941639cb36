#pragma once
// The neon scene's CPU particle engine: it owns the life of every tube head - where it was released,
// whether it is initialising, alive or free, and how much life it has left - while the GPU owns the
// positions (chains.h). `release()` may be called from any thread; the steps run either on the
// caller's thread (lock-step: headless runs and tests, deterministic) or on the engine's own worker
// thread (the gallery), which publishes a snapshot after every step through a triple buffer that the
// render thread reads without ever waiting.
#include "frame/state_archive.h"
#include "scenes/neon/head_state.h"

#include <glm/vec3.hpp>

#include <array>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <queue>
#include <span>
#include <thread>
#include <vector>

namespace vitrine::neon {

// A single-writer single-reader triple buffer: the writer fills back() and publishes it, the reader
// takes the latest published value. Neither side locks or waits, and a reader that falls behind sees
// only the newest value (the ones in between are overwritten, never queued).
//
// Why it is race-free: three slots, and at every moment back_ (the writer's), front_ (the reader's)
// and the index in middle_ (the one in between) are a permutation of {0, 1, 2}, because each side
// only ever swaps its own index with middle_ in one atomic exchange. So the two threads never touch
// the same slot. The writer's exchange releases its writes to the slot it hands over and the
// reader's exchange acquires them; the reader's exchange in turn releases its reads of the slot it
// gives back, and the writer's next exchange acquires them before it overwrites that slot.
template <class T>
class TripleBuffer {
 public:
  explicit TripleBuffer(const T& initial) : slots_{initial, initial, initial} {}

  // Writer only: the slot to fill next; the reader cannot see it until publish().
  T& back() { return slots_[back_]; }
  // Writer only: hands back() to the reader and takes the spare slot in its place.
  void publish() { back_ = middle_.exchange(back_ | kFresh, std::memory_order_acq_rel) & kIndex; }

  // Reader only: the latest published value (the initial one before any publish). It stays valid and
  // unchanged until this reader's next call.
  const T& latest() {
    if (middle_.load(std::memory_order_relaxed) & kFresh)
      front_ = middle_.exchange(front_, std::memory_order_acq_rel) & kIndex;
    return slots_[front_];
  }

 private:
  static constexpr uint32_t kIndex = 3, kFresh = 4;  // middle_ = slot index | kFresh when not yet read
  std::array<T, 3> slots_;
  alignas(64) std::atomic<uint32_t> middle_{1};
  alignas(64) uint32_t back_ = 0;   // the writer's
  alignas(64) uint32_t front_ = 2;  // the reader's
};

inline constexpr uint32_t kMaxChainsLimit = 65536;

struct EngineSettings {
  uint32_t maxChains = 4096;     // 1 .. kMaxChainsLimit slots
  float decayPerSecond = 0.25f;  // life lost per second once alive: a head lives 2 steps + 1 / decay s
};

// What the render thread reads: every slot's head after `steps` steps.
struct Snapshot {
  uint64_t steps = 0;            // steps completed; a jump of more than one means snapshots were skipped
  uint64_t releases = 0;         // releases applied by then (the serial of the latest one)
  std::vector<HeadState> heads;  // maxChains entries, in slot (= chain) order
};

enum class EngineMode {
  LockStep,  // step() runs the step on the calling thread before it returns
  Worker,    // step() posts the step to the engine's worker thread and returns at once
};

class ParticleEngine {
 public:
  ParticleEngine(const EngineSettings& settings, EngineMode mode);
  ~ParticleEngine();  // stops the worker; steps still queued are dropped
  ParticleEngine(const ParticleEngine&) = delete;
  ParticleEngine& operator=(const ParticleEngine&) = delete;

  // Any thread. Spawns a head at `position` at the start of the next step, in the order the
  // releases were queued. Its slot is the first (lowest) free one; when every slot is taken, the
  // oldest release (among undrawn heads, the lowest life: they all lose life at the same rate) is replaced.
  // With one thread releasing and stepping, both modes compute the same snapshots; releases from
  // several threads are applied in the order they took the inbox lock, which is up to the scheduler.
  // `steered`: the head is a pen (a drag): it stays where steer() last put it, with its life held at
  // 1, until endSteer() or the next steered release lets it go: its chain keeps the path it drew and
  // fades over kDrawnFadeSeconds. The pen's slot is never the one a full engine replaces.
  void release(glm::vec3 position, bool steered = false);
  // Any thread: moves the pen (the last steered release) to `position` at the start of the next step.
  void steer(glm::vec3 position);
  // Any thread: lets the pen go.
  void endSteer();

  // The stepping thread (one thread: the frame loop, or the test). Applies the pending releases, then
  // one step of `dt` seconds (finite, >= 0), then publishes a snapshot. Never waits for the worker.
  void step(float dt);
  // The stepping thread. Takes effect from the next step().
  void setDecayPerSecond(float decayPerSecond);
  // The stepping thread: releases from now on take slots below `slots` only (1 .. maxChains; a lower
  // quality tier's), replacing the oldest there when those are full. Heads already above it swim on
  // and die as they would: a lowered limit thins the tubes out over their lives, never cuts one.
  void setSlots(uint32_t slots);
  // The stepping thread. Worker mode: returns once every step posted so far has been published
  // (tests, shutdown, a headless run that wants the worker's result); lock-step: returns at once.
  void flush();

  // The reader thread (one thread: the render thread; in lock-step mode, usually the stepping thread).
  // The newest published snapshot, valid until this thread's next call. Never waits.
  const Snapshot& latest() { return snapshots_.latest(); }

  // Checkpoints: the whole simulation saved or restored, between steps of a lock-step engine (a
  // worker's would race it: std::logic_error). A restored engine publishes the restored heads.
  void simulationState(StateArchive& state);

  uint64_t releasesApplied() const { return releasesApplied_.load(std::memory_order_relaxed); }  // any thread
  uint32_t maxChains() const { return maxChains_; }
  EngineMode mode() const { return mode_; }

 private:
  enum class Kind : uint8_t { Release, ReleaseSteered, Steer, EndSteer, Step, Slots };
  struct Command {
    glm::vec3 position;  // a release's or a steer's
    float dt;            // a step's
    float decayPerSecond;
    Kind kind;
    uint32_t slots = 0;  // a Slots command's
    bool isStep() const { return kind == Kind::Step; }
  };
  struct Occupant {  // a slot taken by the release with this serial
    uint32_t slot;
    uint32_t serial;
  };

  void run();                                        // the worker thread
  void apply(const std::vector<Command>& commands);  // the simulation thread, from here on
  void spawn(glm::vec3 position, bool steered);
  void post(const Command& command);  // a release, steer or end of steering, into the inbox
  HeadState* pen();                   // the steered head, if it still holds its slot
  void letPenGo();
  void advance(float dt, float decayPerSecond);
  void dropStaleOccupants();
  void publish();

  const uint32_t maxChains_;
  const EngineMode mode_;
  float decayPerSecond_;  // the stepping thread's; copied into each step command

  // The simulation: touched only by the thread that runs the steps (the worker, or in lock-step mode
  // the stepping thread), so it needs no lock.
  std::vector<HeadState> heads_;
  std::priority_queue<uint32_t, std::vector<uint32_t>, std::greater<>> free_;  // free slots, lowest first
  std::deque<Occupant> occupants_;  // taken slots in release order, plus stale entries for freed ones
  uint64_t serial_ = 0;
  uint32_t slots_;      // releases take slots below this (setSlots)
  Occupant pen_{0, 0};  // the steered release (serial 0: none)
  uint64_t steps_ = 0;
  std::vector<Command> batch_;  // the commands being applied, swapped out of the inbox

  TripleBuffer<Snapshot> snapshots_;  // simulation thread -> reader thread
  std::atomic<uint64_t> releasesApplied_{0};

  // The inbox: the only state shared between the posting threads and the simulation, all of it under
  // inboxMutex_. Every critical section is a push_back, a vector swap or a counter update - never a
  // step - so no thread holds the lock long enough to stall the frame loop.
  std::mutex inboxMutex_;
  std::condition_variable wake_;  // the worker: a step was posted, or stop
  std::condition_variable idle_;  // flush(): the worker finished a batch
  std::vector<Command> inbox_;
  bool stepPosted_ = false;
  uint64_t stepsPosted_ = 0, stepsPublished_ = 0;
  bool stopping_ = false;

  std::thread worker_;  // last: it starts once everything above is constructed
};

// The render thread's side of the hand-off, for worker mode. A reader only sees the newest snapshot,
// so if the worker ran three or more steps between two reads (a stalled frame), a head can go from
// free to alive without the GPU ever seeing it initialising: its chain would never be placed at its
// origin and the new tube would streak in from wherever the slot's last one died. The guard remembers
// which release each chain was placed for and uploads such a head as initialising for one frame. When
// every snapshot is read (lock-step, or a worker that keeps up) it changes nothing.
class PlacementGuard {
 public:
  explicit PlacementGuard(uint32_t maxChains) : placed_(maxChains, 0u) {}
  // Copies `heads` into `out` (the upload, same size), fixing up unplaced chains; returns how many.
  uint32_t copy(std::span<const HeadState> heads, std::span<HeadState> out);
  void simulationState(StateArchive& state) { state(placed_); }  // checkpoints

 private:
  std::vector<uint32_t> placed_;  // per chain: the serial of the release it was last placed for, 0 for none
};

}  // namespace vitrine::neon
