#include "scenes/neon/particle_engine.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace vitrine::neon {
namespace {

uint32_t checkedMaxChains(uint32_t maxChains) {
  if (maxChains == 0 || maxChains > kMaxChainsLimit)
    throw std::invalid_argument("neon: max chains must be 1.." + std::to_string(kMaxChainsLimit));
  return maxChains;
}

float checkedRate(float value, const char* what) {
  if (!std::isfinite(value) || value < 0.0f)
    throw std::invalid_argument(std::string("neon: ") + what + " must be finite and >= 0");
  return value;
}

std::vector<uint32_t> allSlots(uint32_t count) {
  std::vector<uint32_t> slots(count);
  std::iota(slots.begin(), slots.end(), 0u);  // ascending: already a valid min-heap
  return slots;
}

}  // namespace

ParticleEngine::ParticleEngine(const EngineSettings& settings, EngineMode mode)
    : maxChains_(checkedMaxChains(settings.maxChains)),
      mode_(mode),
      decayPerSecond_(checkedRate(settings.decayPerSecond, "decay per second")),
      heads_(maxChains_),
      free_(std::greater<>(), allSlots(maxChains_)),
      slots_(maxChains_),
      snapshots_(Snapshot{0, 0, std::vector<HeadState>(maxChains_)}) {
  if (mode_ == EngineMode::Worker) worker_ = std::thread([this] { run(); });
}

ParticleEngine::~ParticleEngine() {
  {
    std::lock_guard lock(inboxMutex_);
    stopping_ = true;
  }
  wake_.notify_one();
  if (worker_.joinable()) worker_.join();
}

void ParticleEngine::post(const Command& command) {
  std::lock_guard lock(inboxMutex_);
  inbox_.push_back(command);  // no wake-up: it waits for the next step
}

void ParticleEngine::release(glm::vec3 position, bool steered) {
  post({position, 0.0f, 0.0f, steered ? Kind::ReleaseSteered : Kind::Release});
}

void ParticleEngine::steer(glm::vec3 position) { post({position, 0.0f, 0.0f, Kind::Steer}); }

void ParticleEngine::endSteer() { post({{}, 0.0f, 0.0f, Kind::EndSteer}); }

void ParticleEngine::setDecayPerSecond(float decayPerSecond) {
  decayPerSecond_ = checkedRate(decayPerSecond, "decay per second");
}

void ParticleEngine::setSlots(uint32_t slots) {
  if (slots == 0 || slots > maxChains_)
    throw std::invalid_argument("neon: slots must be 1.." + std::to_string(maxChains_));
  post({{}, 0.0f, 0.0f, Kind::Slots, slots});
}

void ParticleEngine::step(float dt) {
  const Command command{{}, checkedRate(dt, "dt"), decayPerSecond_, Kind::Step};
  if (mode_ == EngineMode::LockStep) {
    // This thread is the simulation thread: take what was released so far, then step, here and now.
    {
      std::lock_guard lock(inboxMutex_);
      batch_.swap(inbox_);
    }
    batch_.push_back(command);
    apply(batch_);
    batch_.clear();
    return;
  }
  {
    std::lock_guard lock(inboxMutex_);
    inbox_.push_back(command);
    stepPosted_ = true;
    ++stepsPosted_;
  }
  wake_.notify_one();
}

void ParticleEngine::flush() {
  if (mode_ == EngineMode::LockStep) return;
  std::unique_lock lock(inboxMutex_);
  idle_.wait(lock, [this] { return stepsPublished_ == stepsPosted_; });
}

void ParticleEngine::run() {
  for (;;) {
    {
      std::unique_lock lock(inboxMutex_);
      wake_.wait(lock, [this] { return stepPosted_ || stopping_; });
      if (stopping_) return;
      // The whole inbox in one swap: the posters get back the (cleared) vector of the last batch, so
      // neither side allocates in the steady state, and the lock is held for O(1).
      batch_.swap(inbox_);
      stepPosted_ = false;
    }
    apply(batch_);  // without the lock: posters keep queueing into the other vector meanwhile
    uint64_t steps = 0;
    for (const Command& command : batch_) steps += command.isStep();
    batch_.clear();
    {
      std::lock_guard lock(inboxMutex_);
      stepsPublished_ += steps;
    }
    idle_.notify_all();
  }
}

// Releases queued after the last step of a batch are applied now rather than at the start of the
// next step: nothing else touches the heads in between, so the result is the same.
void ParticleEngine::apply(const std::vector<Command>& commands) {
  for (const Command& command : commands) {
    switch (command.kind) {
      case Kind::Release: spawn(command.position, false); break;
      case Kind::ReleaseSteered: spawn(command.position, true); break;
      case Kind::Steer:
        if (HeadState* head = pen()) head->origin = command.position;
        break;
      case Kind::EndSteer: letPenGo(); break;
      case Kind::Slots: slots_ = command.slots; break;
      case Kind::Step:
        advance(command.dt, command.decayPerSecond);
        publish();
        break;
    }
  }
}

void ParticleEngine::letPenGo() {
  if (HeadState* head = pen()) {  // from now on it stays as drawn and fades, from full brightness
    head->flags &= ~kHeadSteered;
    head->life = std::min(head->life, kFadeLife);
  }
  pen_ = {0, 0};
}

HeadState* ParticleEngine::pen() {
  if (pen_.serial == 0) return nullptr;
  HeadState& head = heads_[pen_.slot];
  return chainState(head) != ChainState::Inactive && head.serial == pen_.serial ? &head : nullptr;
}

void ParticleEngine::spawn(glm::vec3 position, bool steered) {
  if (steered) letPenGo();  // one pen at a time
  uint32_t slot;
  if (!free_.empty() && free_.top() < slots_) {
    slot = free_.top();
    free_.pop();
  } else {
    // Every slot below the limit is taken, so each has a live entry in occupants_, and the first live
    // one below the limit is the oldest release there: the one replaced. Undrawn heads all lose the
    // same life each step, so it is also the lowest life among them; a drawn tube fades at its own
    // rate and may die before older ones, leaving a stale entry that the search skips. The pen, whose
    // life is held, is passed over (a single slot aside).
    dropStaleOccupants();
    const bool spareThePen = slots_ > 1;
    const auto oldest = std::find_if(occupants_.begin(), occupants_.end(), [&](const Occupant& o) {
      return o.slot < slots_ && chainState(heads_[o.slot]) != ChainState::Inactive && heads_[o.slot].serial == o.serial &&
             !(spareThePen && o.serial == pen_.serial);
    });
    slot = oldest->slot;
    if (slot == pen_.slot) pen_ = {0, 0};
    occupants_.erase(oldest);
  }
  ++serial_;
  heads_[slot] = {.origin = position,
                  .life = 1.0f,
                  .state = uint32_t(ChainState::Initialising),
                  .serial = uint32_t(serial_),
                  .steps = 0u,
                  .flags = steered ? kHeadSteered | kHeadDrawn : 0u,
                  .launch = launchVelocity(uint32_t(serial_), position),
                  .padding = 0u};
  occupants_.push_back({slot, uint32_t(serial_)});
  if (steered) pen_ = {slot, uint32_t(serial_)};
  releasesApplied_.store(serial_, std::memory_order_relaxed);
}

// The write-up's behaviour: count the steps since release; after two, the head is alive and its life
// falls; at zero the slot is freed for the next release.
void ParticleEngine::advance(float dt, float decayPerSecond) {
  for (uint32_t slot = 0; slot < maxChains_; ++slot) {
    HeadState& head = heads_[slot];
    if (chainState(head) == ChainState::Inactive) continue;
    if (++head.steps <= kInitialisingSteps) continue;
    head.state = uint32_t(ChainState::Alive);
    if (steered(head)) continue;  // the pen keeps its full life while it draws
    // A drawn tube fades in its own time once let go: the autopilot's tubes live long to sweep far.
    head.life -= (drawn(head) ? kFadeLife / kDrawnFadeSeconds : decayPerSecond) * dt;
    if (head.life <= 0.0f) {
      head = HeadState{};  // inactive, life 0: the GPU leaves the tube where it is, and it draws nothing
      free_.push(slot);
    }
  }
  ++steps_;
  // Heads die in release order (see spawn), so the entries of freed slots gather at the front.
  dropStaleOccupants();
}

void ParticleEngine::dropStaleOccupants() {
  while (!occupants_.empty()) {
    const Occupant& o = occupants_.front();
    const HeadState& head = heads_[o.slot];
    if (chainState(head) != ChainState::Inactive && head.serial == o.serial) return;
    occupants_.pop_front();
  }
}

void ParticleEngine::simulationState(StateArchive& state) {
  if (mode_ != EngineMode::LockStep) throw std::logic_error("neon: only a lock-step engine can be checkpointed");
  {
    std::lock_guard lock(inboxMutex_);
    if (!inbox_.empty()) throw std::logic_error("neon: a checkpoint between a release and its step");
  }
  std::vector<uint32_t> freeSlots;  // the heap's pop order is the slots' order, whatever its layout
  for (auto heap = free_; !heap.empty(); heap.pop()) freeSlots.push_back(heap.top());
  uint64_t applied = releasesApplied_.load(std::memory_order_relaxed);
  state(decayPerSecond_, heads_, freeSlots, occupants_, serial_, slots_, pen_, steps_, applied);
  if (!state.isRestoring()) return;
  if (heads_.size() != maxChains_) throw std::invalid_argument("neon: the saved engine has another number of chains");
  free_ = decltype(free_)(std::greater<>(), std::move(freeSlots));
  releasesApplied_.store(applied, std::memory_order_relaxed);
  publish();
}

void ParticleEngine::publish() {
  Snapshot& back = snapshots_.back();
  back.steps = steps_;
  back.releases = serial_;
  std::copy(heads_.begin(), heads_.end(), back.heads.begin());  // same size: no allocation
  snapshots_.publish();
}

uint32_t PlacementGuard::copy(std::span<const HeadState> heads, std::span<HeadState> out) {
  if (heads.size() != placed_.size() || out.size() != heads.size())
    throw std::invalid_argument("neon: the placement guard, the snapshot and the upload disagree on max chains");
  uint32_t fixed = 0;
  for (size_t i = 0; i < heads.size(); ++i) {
    out[i] = heads[i];
    const ChainState state = chainState(heads[i]);
    if (state == ChainState::Inactive || placed_[i] == heads[i].serial) continue;
    if (state == ChainState::Alive) {
      out[i].state = uint32_t(ChainState::Initialising);  // skipped: place it now, move it from next frame
      ++fixed;
    }
    placed_[i] = heads[i].serial;
  }
  return fixed;
}

}  // namespace vitrine::neon
