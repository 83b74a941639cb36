// The neon scene's CPU side: the particle engine's life cycle, slot choice, determinism and threading
// (src/scenes/neon/particle_engine.h), and the chain update's CPU reference (src/scenes/neon/chains.h).
#include "gpu/program.h"
#include "maths/hash.h"
#include "scenes/neon/chains.h"
#include "scenes/neon/particle_engine.h"
#include "scenes/neon/settings.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <set>
#include <span>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace vitrine::neon {
namespace {

using namespace std::chrono_literals;

glm::vec3 scatter(uint32_t i, uint32_t seed) {
  return {maths::hash01({i, 1u, seed}) * 8.0f - 4.0f, maths::hash01({i, 2u, seed}) * 8.0f - 4.0f,
          maths::hash01({i, 3u, seed}) * 8.0f - 4.0f};
}

bool sameHeads(const std::vector<HeadState>& a, const std::vector<HeadState>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(HeadState)) == 0;
}

// A head's bookkeeping as one comparable value: (state, serial, steps since release, flags).
glm::uvec4 bookkeeping(const HeadState& h) { return {h.state, h.serial, h.steps, h.flags}; }
glm::vec4 originAndLife(const HeadState& h) { return {h.origin, h.life}; }

// ---------------------------------------------------------------------------------------- record

// Its layout is the shader's, checked by the build (shaders/neon/head_state.h); a zeroed one is free.
TEST(NeonHeadState, ZeroIsAFreeSlot) {
  const HeadState zero{};
  EXPECT_EQ(chainState(zero), ChainState::Inactive);
  EXPECT_EQ(zero.life, 0.0f);
  EXPECT_EQ(zero.launch, glm::vec3(0.0f));
}

// The launch direction is a sine and a cosine: the CPU computes it once, at release, so that no GPU's
// own transcendentals enter the integration (see the pass's arithmetic test below).
TEST(NeonEngine, AReleaseCarriesItsLaunchVelocity) {
  ParticleEngine engine({4, 1.0f}, EngineMode::LockStep);
  engine.release({1.0f, 2.0f, 3.0f});
  engine.release({0.0f, 0.0f, 0.0f}, true);  // a pen too, though its tube stays as drawn
  engine.step(0.25f);
  std::set<std::pair<float, float>> directions;
  for (const HeadState& h : engine.latest().heads) {
    if (chainState(h) == ChainState::Inactive) {
      EXPECT_EQ(h.launch, glm::vec3(0.0f));
      continue;
    }
    EXPECT_EQ(h.launch, launchVelocity(h.serial, h.origin)) << "serial " << h.serial;
    EXPECT_NEAR(glm::length(h.launch), kLaunchSpeed, 1e-5f);
    EXPECT_EQ(h.launch.z, 0.0f) << "in the facade's plane";
    // Across the facade: toward a point of it, within the aims' box round its middle.
    const glm::vec2 at = glm::vec2(h.origin), direction = glm::vec2(h.launch) / kLaunchSpeed;
    const float along = glm::dot(glm::vec2(kLaunchTowardX, kLaunchTowardY) - at, direction);
    const glm::vec2 closest = at + direction * along;  // the point of its line nearest the middle
    EXPECT_LE(std::abs(closest.x - kLaunchTowardX), kLaunchHalfWidth + 1e-3f) << "serial " << h.serial;
    EXPECT_LE(std::abs(closest.y - kLaunchTowardY), std::hypot(kLaunchHalfWidth, kLaunchHalfHeight)) << h.serial;
    directions.insert({h.launch.x, h.launch.y});
  }
  EXPECT_EQ(directions.size(), 2u) << "each tube its own direction";
}

// ------------------------------------------------------------------------------ the pass's arithmetic

// The instructions of a SPIR-V module whose results are ids, by opcode (SPIR-V spec, 2.3).
struct SpirvScan {
  std::set<uint32_t> noContraction;                    // ids decorated NoContraction
  std::vector<std::pair<uint16_t, uint32_t>> results;  // (opcode, result id) of the ops below
  std::vector<uint32_t> std450;                        // GLSL.std.450 instruction numbers used
};

SpirvScan scanSpirv(std::span<const uint32_t> code) {
  constexpr uint16_t kOpExtInstImport = 11, kOpExtInst = 12, kOpDecorate = 71, kNoContraction = 42;
  // Floating-point arithmetic a driver could fuse or compute to less than correct rounding.
  const std::set<uint16_t> kArithmetic{127 /*FNegate*/, 129 /*FAdd*/,  131 /*FSub*/,
                                       133 /*FMul*/,    136 /*FDiv*/,  141 /*FMod*/,
                                       142 /*VectorTimesScalar*/,      148 /*Dot*/};
  SpirvScan scan;
  uint32_t std450 = 0;  // the id of the GLSL.std.450 import (the debug information is another set)
  for (size_t at = 5; at < code.size();) {
    const uint16_t opcode = uint16_t(code[at] & 0xffffu), words = uint16_t(code[at] >> 16);
    if (words == 0 || at + words > code.size()) throw std::runtime_error("malformed SPIR-V");
    if (opcode == kOpDecorate && code[at + 2] == kNoContraction) scan.noContraction.insert(code[at + 1]);
    if (kArithmetic.contains(opcode)) scan.results.push_back({opcode, code[at + 2]});
    if (opcode == kOpExtInstImport &&
        std::string(reinterpret_cast<const char*>(&code[at + 2])).starts_with("GLSL.std.450"))
      std450 = code[at + 1];
    if (opcode == kOpExtInst && code[at + 3] == std450) scan.std450.push_back(code[at + 4]);
    at += words;
  }
  return scan;
}

// The chains are integrated on the GPU frame after frame, so they can only stay where the CPU
// reference puts them, on every driver, if each operation rounds the same everywhere: additions,
// subtractions and multiplications (correctly rounded in Vulkan) that no driver may fuse, floor, and
// nothing else - no dot products, divisions or transcendentals, whose precision Vulkan leaves open.
TEST(NeonChains, ThePassComputesOnlyCorrectlyRoundedUnfusedArithmetic) {
  std::span<const uint32_t> code;
  for (const auto& [name, spirv] : gpu::embeddedShaders())
    if (name == "neon/chains.comp") code = spirv;
  ASSERT_FALSE(code.empty());
  const SpirvScan scan = scanSpirv(code);
  EXPECT_GT(scan.results.size(), 40u) << "the curl noise is in the pass";
  for (const auto& [opcode, id] : scan.results) {
    EXPECT_NE(opcode, 136) << "a division";
    EXPECT_NE(opcode, 148) << "a dot product";
    EXPECT_TRUE(scan.noContraction.contains(id)) << "opcode " << opcode << ", id %" << id << " may be fused";
  }
  constexpr uint32_t kFloor = 8;
  for (uint32_t instruction : scan.std450) EXPECT_EQ(instruction, kFloor) << "GLSL.std.450 instruction";
}

// ------------------------------------------------------------------------------------- life cycle

TEST(NeonEngine, StartsEmpty) {
  ParticleEngine engine({8, 1.0f}, EngineMode::LockStep);
  const Snapshot& s = engine.latest();
  EXPECT_EQ(s.steps, 0u);
  EXPECT_EQ(s.heads.size(), 8u);
  for (const HeadState& h : s.heads) EXPECT_EQ(chainState(h), ChainState::Inactive);
}

TEST(NeonEngine, WaitsTwoStepsThenDecaysThenRecycles) {
  // 0.5 per second x 0.25 s = 0.125 per step: every life below is exact in float.
  ParticleEngine engine({4, 0.5f}, EngineMode::LockStep);
  engine.release({1.0f, 2.0f, 3.0f});
  for (uint32_t step = 1; step <= 2; ++step) {
    engine.step(0.25f);
    const HeadState h = engine.latest().heads[0];
    EXPECT_EQ(chainState(h), ChainState::Initialising) << "step " << step;
    EXPECT_EQ(originAndLife(h), glm::vec4(1.0f, 2.0f, 3.0f, 1.0f)) << "step " << step;
    EXPECT_EQ(bookkeeping(h), glm::uvec4(1u, 1u, step, 0u)) << "step " << step;
  }
  for (uint32_t step = 3; step <= 9; ++step) {
    engine.step(0.25f);
    const HeadState h = engine.latest().heads[0];
    EXPECT_EQ(chainState(h), ChainState::Alive) << "step " << step;
    EXPECT_EQ(h.life, 1.0f - 0.125f * float(step - 2)) << "step " << step;
    EXPECT_EQ(h.steps, step);
    EXPECT_EQ(h.origin, glm::vec3(1.0f, 2.0f, 3.0f));  // the origin never moves
  }
  engine.step(0.25f);  // life reaches 0: the slot is free again
  EXPECT_EQ(chainState(engine.latest().heads[0]), ChainState::Inactive);
  EXPECT_EQ(engine.latest().heads[0].life, 0.0f);
  for (const HeadState& h : engine.latest().heads) EXPECT_EQ(chainState(h), ChainState::Inactive);

  engine.release({-1.0f, 0.0f, 0.0f});
  engine.step(0.25f);
  const Snapshot& s = engine.latest();
  EXPECT_EQ(s.steps, 11u);
  EXPECT_EQ(s.releases, 2u);
  EXPECT_EQ(bookkeeping(s.heads[0]), glm::uvec4(1u, 2u, 1u, 0u));  // slot 0 again, second serial
  EXPECT_EQ(originAndLife(s.heads[0]), glm::vec4(-1.0f, 0.0f, 0.0f, 1.0f));
}

TEST(NeonEngine, DecayIsRatePerSecondTimesDt) {
  ParticleEngine engine({1, 2.0f}, EngineMode::LockStep);
  engine.release({});
  for (int i = 0; i < 3; ++i) engine.step(0.0625f);  // the third step is the first alive one
  EXPECT_EQ(engine.latest().heads[0].life, 1.0f - 2.0f * 0.0625f);
  engine.setDecayPerSecond(4.0f);
  engine.step(0.0625f);
  EXPECT_EQ(engine.latest().heads[0].life, 1.0f - 2.0f * 0.0625f - 4.0f * 0.0625f);
}

TEST(NeonEngine, ARecycledSlotIsTheFirstFreeOne) {
  // Slot 0 dies while slot 1 still lives: the next release takes slot 0, not slot 2.
  ParticleEngine engine({4, 1.0f}, EngineMode::LockStep);  // 0.25 per alive step at dt 0.25
  engine.release({0.0f, 0.0f, 0.0f});
  for (int i = 0; i < 4; ++i) engine.step(0.25f);
  engine.release({1.0f, 0.0f, 0.0f});
  for (int i = 0; i < 2; ++i) engine.step(0.25f);  // the first head's sixth step: life 0
  ASSERT_EQ(chainState(engine.latest().heads[0]), ChainState::Inactive);
  ASSERT_EQ(chainState(engine.latest().heads[1]), ChainState::Initialising);
  engine.release({2.0f, 0.0f, 0.0f});
  engine.step(0.25f);
  const Snapshot& s = engine.latest();
  EXPECT_EQ(s.heads[0].serial, 3u);
  EXPECT_EQ(s.heads[0].origin.x, 2.0f);
  EXPECT_EQ(s.heads[1].serial, 2u);
  EXPECT_EQ(chainState(s.heads[1]), ChainState::Alive);
  EXPECT_EQ(chainState(s.heads[2]), ChainState::Inactive);
}

uint32_t lowestLife(const std::vector<HeadState>& heads) {
  uint32_t lowest = 0;
  for (uint32_t i = 1; i < heads.size(); ++i)
    if (heads[i].life < heads[lowest].life) lowest = i;
  return lowest;
}

TEST(NeonEngine, WhenFullTheLowestLifeIsReplaced) {
  // 0.25 per alive step. A recycled slot 0 is refilled first, so the oldest head ends up in slot 1:
  // a rule of "lowest index" or "last slot" would pick differently from "lowest life".
  ParticleEngine engine({3, 1.0f}, EngineMode::LockStep);
  engine.release({0.0f, 0.0f, 0.0f});  // serial 1 -> slot 0, dies in step 6
  for (int i = 0; i < 3; ++i) engine.step(0.25f);
  engine.release({1.0f, 0.0f, 0.0f});  // serial 2 -> slot 1
  engine.step(0.25f);
  engine.release({2.0f, 0.0f, 0.0f});  // serial 3 -> slot 2
  for (int i = 0; i < 2; ++i) engine.step(0.25f);
  ASSERT_EQ(chainState(engine.latest().heads[0]), ChainState::Inactive);
  engine.release({3.0f, 0.0f, 0.0f});  // serial 4 -> slot 0, the first free one
  engine.step(0.25f);

  // Full: lives 1 (slot 0, initialising), 0.5 (slot 1), 0.75 (slot 2).
  for (uint32_t serial = 5; uint32_t expectedSlot : {1u, 2u, 0u}) {
    const std::vector<HeadState> before = engine.latest().heads;
    for (const HeadState& h : before) ASSERT_NE(chainState(h), ChainState::Inactive);
    ASSERT_EQ(lowestLife(before), expectedSlot);
    engine.release({float(serial), 0.0f, 0.0f});
    engine.step(0.25f);
    const std::vector<HeadState>& after = engine.latest().heads;
    EXPECT_EQ(bookkeeping(after[expectedSlot]), glm::uvec4(1u, serial, 1u, 0u)) << "serial " << serial;
    EXPECT_EQ(originAndLife(after[expectedSlot]), glm::vec4(float(serial), 0.0f, 0.0f, 1.0f));
    for (uint32_t slot = 0; slot < 3; ++slot) {
      if (slot == expectedSlot) continue;
      EXPECT_EQ(after[slot].serial, before[slot].serial) << "slot " << slot << " kept";
    }
    ++serial;
  }
}

TEST(NeonEngine, MoreReleasesInOneStepThanSlotsKeepTheNewest) {
  ParticleEngine engine({2, 0.5f}, EngineMode::LockStep);
  for (int i = 1; i <= 5; ++i) engine.release({float(i), 0.0f, 0.0f});
  engine.step(0.1f);
  const Snapshot& s = engine.latest();
  EXPECT_EQ(s.releases, 5u);
  EXPECT_EQ(engine.releasesApplied(), 5u);
  // 1 -> slot 0, 2 -> slot 1, 3 replaces 1, 4 replaces 2, 5 replaces 3.
  EXPECT_EQ(s.heads[0].serial, 5u);
  EXPECT_EQ(s.heads[1].serial, 4u);
}

// A lower tier's slots (setSlots): releases go below the limit, replacing the oldest there once it is
// full, while heads above it swim on and die as they would (a tier change thins tubes out, never cuts
// one); raised again, the slots above take releases.
TEST(NeonEngine, ReleasesStayBelowTheSlotsAndHeadsAboveDieOnTheirOwn) {
  ParticleEngine engine({8, 1.0f}, EngineMode::LockStep);
  for (int i = 1; i <= 8; ++i) engine.release({float(i), 0.0f, 0.0f});  // serials 1..8 -> slots 0..7
  engine.step(0.1f);
  engine.setSlots(4);
  engine.release({9.0f, 0.0f, 0.0f});
  engine.release({10.0f, 0.0f, 0.0f});
  engine.step(0.1f);
  {
    const std::vector<HeadState>& heads = engine.latest().heads;
    EXPECT_EQ(heads[0].serial, 9u) << "the oldest below the limit is replaced";
    EXPECT_EQ(heads[1].serial, 10u);
    for (uint32_t slot = 2; slot < 8; ++slot) EXPECT_EQ(heads[slot].serial, slot + 1) << "slot " << slot << " swims on";
  }
  for (int i = 0; i < 14; ++i) engine.step(0.1f);  // two steps initialising, then 1 / s of life at 0.1 s
  for (const HeadState& head : engine.latest().heads) ASSERT_EQ(chainState(head), ChainState::Inactive);
  for (int i = 11; i <= 16; ++i) engine.release({float(i), 0.0f, 0.0f});
  engine.step(0.1f);
  {
    const std::vector<HeadState>& heads = engine.latest().heads;
    // 11..14 -> slots 0..3 (free, below the limit); 15 and 16 replace 11 and 12, not free slot 4.
    constexpr std::array<uint32_t, 4> kSerials{15u, 16u, 13u, 14u};
    for (uint32_t slot = 0; slot < 4; ++slot) EXPECT_EQ(heads[slot].serial, kSerials[slot]) << "slot " << slot;
    for (uint32_t slot = 4; slot < 8; ++slot) EXPECT_EQ(chainState(heads[slot]), ChainState::Inactive);
  }
  engine.setSlots(8);
  engine.release({17.0f, 0.0f, 0.0f});
  engine.step(0.1f);
  EXPECT_EQ(engine.latest().heads[4].serial, 17u) << "raised: the first free slot again";
  EXPECT_THROW(engine.setSlots(0), std::invalid_argument);
  EXPECT_THROW(engine.setSlots(9), std::invalid_argument);
}

TEST(NeonSettings, LowerTiersReleaseIntoFewerChains) {
  EXPECT_EQ(tierChains(1024, Tier::High), 1024);
  EXPECT_EQ(tierChains(1024, Tier::Medium), 768);
  EXPECT_EQ(tierChains(1024, Tier::Low), 512);
  EXPECT_EQ(tierChains(16384, Tier::Low), 8192);
  EXPECT_EQ(tierChains(20, Tier::Low), 16) << "never under the parameter's 16";
  EXPECT_EQ(tierChains(16, Tier::Low), 16);
}

TEST(NeonEngine, RejectsBadSettings) {
  EXPECT_THROW(ParticleEngine({0, 1.0f}, EngineMode::LockStep), std::invalid_argument);
  EXPECT_THROW(ParticleEngine({kMaxChainsLimit + 1, 1.0f}, EngineMode::LockStep), std::invalid_argument);
  EXPECT_THROW(ParticleEngine({4, -1.0f}, EngineMode::Worker), std::invalid_argument);
  ParticleEngine engine({kMaxChainsLimit, 1.0f}, EngineMode::LockStep);
  EXPECT_THROW(engine.step(-0.1f), std::invalid_argument);
  EXPECT_THROW(engine.step(std::nanf("")), std::invalid_argument);
  EXPECT_THROW(engine.setDecayPerSecond(INFINITY), std::invalid_argument);
  engine.step(0.0f);
  EXPECT_EQ(engine.latest().steps, 1u);
}

// A checkpoint mid-run (slots recycled, a pen held): an engine restored from it goes on exactly as the
// one that saved it.
TEST(NeonEngine, ARestoredEngineGoesOnAsTheSavedOne) {
  auto play = [](ParticleEngine& engine, int from, int to) {
    for (int step = from; step < to; ++step) {
      if (step % 3 == 0) engine.release({float(step), 1.0f, 0.0f});
      if (step == 5) engine.release({0.0f, 2.0f, 0.0f}, true);
      if (step > 5 && step < 20) engine.steer({float(step) * 0.1f, 2.0f, 0.0f});
      if (step == 20) engine.endSteer();
      engine.step(0.05f + 0.001f * float(step));
    }
  };
  ParticleEngine original({5, 0.7f}, EngineMode::LockStep);
  play(original, 0, 12);
  StateArchive saved = StateArchive::saving();
  original.simulationState(saved);
  ParticleEngine restored({5, 0.1f}, EngineMode::LockStep);
  StateArchive in = StateArchive::restoring(saved.bytes());
  restored.simulationState(in);
  EXPECT_TRUE(in.finished());
  EXPECT_EQ(restored.latest().steps, 12u);
  play(original, 12, 40);
  play(restored, 12, 40);
  const Snapshot& a = original.latest();
  const Snapshot& b = restored.latest();
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.releases, b.releases);
  ASSERT_EQ(a.heads.size(), b.heads.size());
  EXPECT_EQ(std::memcmp(a.heads.data(), b.heads.data(), a.heads.size() * sizeof(HeadState)), 0);
  ParticleEngine smaller({4, 0.7f}, EngineMode::LockStep);  // another size is refused
  StateArchive again = StateArchive::restoring(saved.bytes());
  EXPECT_THROW(smaller.simulationState(again), std::invalid_argument);
}

// ---------------------------------------------------------------------------------- determinism

// A script of releases: a few per step at hashed positions, enough to fill 64 slots and replace.
void feed(ParticleEngine& engine, uint32_t step) {
  const uint32_t count = maths::pcg3d({step, 7u, 7u}).x % 4u;
  for (uint32_t i = 0; i < count; ++i) engine.release(scatter(step * 4u + i, 11u));
}

TEST(NeonEngine, LockStepIsDeterministic) {
  ParticleEngine a({64, 0.7f}, EngineMode::LockStep), b({64, 0.7f}, EngineMode::LockStep);
  bool sawFull = false;
  for (uint32_t step = 0; step < 400; ++step) {
    feed(a, step);
    feed(b, step);
    const float dt = 1.0f / 60.0f + 0.001f * float(step % 5);
    a.step(dt);
    b.step(dt);
    const Snapshot &sa = a.latest(), &sb = b.latest();
    ASSERT_EQ(sa.steps, sb.steps);
    ASSERT_EQ(sa.releases, sb.releases);
    ASSERT_TRUE(sameHeads(sa.heads, sb.heads)) << "step " << step;
    sawFull |= sa.releases > 64 && std::all_of(sa.heads.begin(), sa.heads.end(), [](const HeadState& h) {
                 return chainState(h) != ChainState::Inactive;
               });
  }
  EXPECT_TRUE(sawFull) << "the script should also exercise replacement";
}

TEST(NeonEngine, WorkerWithOnePosterMatchesLockStep) {
  // The worker applies commands in the order they were posted, so with one posting thread it computes
  // exactly what lock-step does.
  ParticleEngine lockStep({64, 0.7f}, EngineMode::LockStep), worker({64, 0.7f}, EngineMode::Worker);
  for (uint32_t step = 0; step < 300; ++step) {
    feed(lockStep, step);
    feed(worker, step);
    lockStep.step(1.0f / 60.0f);
    worker.step(1.0f / 60.0f);
    if (step % 7 == 0 || step == 299) {  // let the worker run ahead over several steps in between
      worker.flush();
      const Snapshot &l = lockStep.latest(), &w = worker.latest();
      ASSERT_EQ(w.steps, l.steps);
      ASSERT_TRUE(sameHeads(l.heads, w.heads)) << "step " << step;
    }
  }
}

// ------------------------------------------------------------------------------------ threading

TEST(NeonTripleBuffer, ReaderGetsTheNewestAndKeepsItUntilItsNextCall) {
  TripleBuffer<int> buffer(0);
  EXPECT_EQ(buffer.latest(), 0);
  buffer.back() = 1;
  buffer.publish();
  buffer.back() = 2;
  buffer.publish();  // 1 is overwritten, never seen
  const int& held = buffer.latest();
  EXPECT_EQ(held, 2);
  buffer.back() = 3;  // writing the next value must not touch the one the reader holds
  EXPECT_EQ(held, 2);
  buffer.publish();
  buffer.back() = 4;
  EXPECT_EQ(held, 2);
  EXPECT_EQ(buffer.latest(), 3);
  EXPECT_EQ(buffer.latest(), 3);  // nothing new: the same value again
}

TEST(NeonTripleBuffer, ConcurrentReaderNeverSeesATornOrOlderValue) {
  constexpr size_t kWords = 256;
  constexpr uint64_t kValues = 200000;
  using Block = std::array<uint64_t, kWords>;
  TripleBuffer<Block> buffer(Block{});
  std::atomic<bool> done{false};
  std::atomic<uint64_t> seen{0}, written{0};
  std::thread writer([&] {
    // Past kValues it goes on until the reader has seen two values: on a loaded machine the reader
    // may not run at all while the first 200,000 are written, and the test would prove nothing.
    for (uint64_t value = 1; value <= kValues || seen.load() < 2; ++value) {
      buffer.back().fill(value);
      buffer.publish();
      written = value;
    }
    done = true;
  });
  uint64_t last = 0, distinct = 0, torn = 0, backwards = 0;
  for (bool stop = false; !stop;) {
    stop = done.load();  // one more read after the writer finished, to see its last value
    const Block& block = buffer.latest();
    const uint64_t value = block[0];
    torn += std::any_of(block.begin(), block.end(), [&](uint64_t word) { return word != value; });
    backwards += value < last;
    distinct += value != last;
    seen = distinct;
    last = value;
  }
  writer.join();
  EXPECT_EQ(torn, 0u);
  EXPECT_EQ(backwards, 0u);
  EXPECT_EQ(last, written.load());
  EXPECT_GE(last, kValues);
  EXPECT_GT(distinct, 1u);
}

TEST(NeonEngine, ReleasesFromEightThreadsAreAllApplied) {
  constexpr uint32_t kThreads = 8, kPerThread = 10000, kTotal = kThreads * kPerThread;
  ParticleEngine engine({4096, 0.01f}, EngineMode::Worker);  // 6000 steps of life: nothing dies here
  std::atomic<uint32_t> finished{0};
  std::vector<std::thread> threads;
  for (uint32_t t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      for (uint32_t i = 0; i < kPerThread; ++i) engine.release(scatter(i, t));
      ++finished;
    });
  // Meanwhile this thread is the frame loop: it posts steps and reads snapshots, as the gallery does.
  uint64_t frames = 0, lastSteps = 0, backwards = 0;
  while (finished.load() < kThreads) {
    engine.step(1.0f / 60.0f);
    const Snapshot& s = engine.latest();
    backwards += s.steps < lastSteps;
    lastSteps = s.steps;
    ++frames;
    std::this_thread::sleep_for(100us);  // a frame; keeps the worker's inbox from growing without bound
  }
  for (std::thread& thread : threads) thread.join();
  engine.step(1.0f / 60.0f);  // releases wait for a step
  engine.flush();
  const Snapshot& s = engine.latest();
  EXPECT_EQ(backwards, 0u);
  EXPECT_EQ(s.steps, frames + 1);
  EXPECT_EQ(s.releases, kTotal);
  EXPECT_EQ(engine.releasesApplied(), kTotal);
  // Every slot is taken (80,000 releases, none dead), each by its own serial, the last one included.
  std::set<uint32_t> serials;
  for (const HeadState& h : s.heads) {
    EXPECT_NE(chainState(h), ChainState::Inactive);
    EXPECT_LE(h.serial, kTotal);
    serials.insert(h.serial);
  }
  EXPECT_EQ(serials.size(), 4096u);
  EXPECT_TRUE(serials.count(kTotal));
  RecordProperty("frames", std::to_string(frames));
}

TEST(NeonEngine, ReaderNeverWaitsAndNeverSeesAHalfWrittenStep) {
  // One release per step, at x = the number of the step that applies it, so every snapshot can be
  // checked against its own step count: a head released in step r has been stepped (steps - r + 1)
  // times. A snapshot mixing two steps would break that for some head.
  ParticleEngine engine({512, 1.0f}, EngineMode::Worker);
  std::atomic<bool> readerDone{false};
  uint64_t distinctSteps = 0, backwards = 0, wrongReleases = 0, torn = 0;
  std::thread reader([&] {
    uint64_t last = 0;
    for (int read = 0; read < 100000; ++read) {
      const Snapshot& s = engine.latest();  // lock-free: one atomic exchange when there is news
      backwards += s.steps < last;
      distinctSteps += s.steps != last;
      last = s.steps;
      wrongReleases += s.releases != s.steps;
      for (const HeadState& h : s.heads) {
        if (chainState(h) == ChainState::Inactive) continue;
        const auto releasedIn = uint64_t(h.origin.x);
        const auto expectedState = h.steps <= kInitialisingSteps ? ChainState::Initialising : ChainState::Alive;
        torn += h.serial != releasedIn || h.steps != s.steps - releasedIn + 1 || chainState(h) != expectedState;
      }
    }
    readerDone = true;
  });
  uint32_t step = 0;
  while (!readerDone.load()) {
    engine.release({float(++step), 0.0f, 0.0f});
    engine.step(1.0f / 60.0f);
    std::this_thread::sleep_for(20us);
  }
  reader.join();
  engine.flush();
  EXPECT_EQ(engine.latest().steps, step);
  EXPECT_EQ(backwards, 0u);
  EXPECT_EQ(wrongReleases, 0u);
  EXPECT_EQ(torn, 0u);
  EXPECT_GT(distinctSteps, 1u) << "the reader should have read while the worker published";
  RecordProperty("steps", std::to_string(step));
  RecordProperty("distinct_steps_seen", std::to_string(distinctSteps));
}

TEST(NeonEngine, DestroyedWithStepsStillQueued) {
  ParticleEngine engine({1024, 1.0f}, EngineMode::Worker);
  for (int i = 0; i < 1000; ++i) {
    engine.release(scatter(uint32_t(i), 5u));
    engine.step(0.01f);
  }
  // No flush: the destructor must stop and join the worker without deadlocking.
}

TEST(NeonPlacementGuard, ChangesNothingWhenEverySnapshotIsRead) {
  ParticleEngine engine({64, 0.7f}, EngineMode::LockStep);
  PlacementGuard guard(64);
  std::vector<HeadState> upload(64);
  for (uint32_t step = 0; step < 400; ++step) {
    feed(engine, step);  // replaces heads too: a new serial in a slot is seen initialising first
    engine.step(1.0f / 60.0f);
    ASSERT_EQ(guard.copy(engine.latest().heads, upload), 0u) << "step " << step;
    ASSERT_TRUE(sameHeads(upload, engine.latest().heads)) << "step " << step;
  }
}

TEST(NeonPlacementGuard, PlacesAChainWhoseInitialisationWasSkipped) {
  ParticleEngine engine({2, 0.5f}, EngineMode::LockStep);
  PlacementGuard guard(2);
  std::vector<HeadState> upload(2);
  engine.release({1.0f, 2.0f, 3.0f});
  for (int i = 0; i < 3; ++i) engine.step(0.1f);  // three steps unread: the reader meets it alive
  std::vector<HeadState> heads = engine.latest().heads;
  ASSERT_EQ(chainState(heads[0]), ChainState::Alive);
  EXPECT_EQ(guard.copy(heads, upload), 1u);
  EXPECT_EQ(chainState(upload[0]), ChainState::Initialising);
  EXPECT_EQ(originAndLife(upload[0]), originAndLife(heads[0]));
  EXPECT_EQ(glm::uvec3(upload[0].serial, upload[0].steps, upload[0].flags),
            glm::uvec3(heads[0].serial, heads[0].steps, heads[0].flags));
  engine.step(0.1f);
  EXPECT_EQ(guard.copy(engine.latest().heads, upload), 0u);  // placed once; from now on it moves
  EXPECT_EQ(chainState(upload[0]), ChainState::Alive);

  // Slot 0 taken over by a new release that the reader again meets only once it is alive.
  engine.release({5.0f, 0.0f, 0.0f});  // slot 1
  engine.release({6.0f, 0.0f, 0.0f});  // full: replaces slot 0
  for (int i = 0; i < 3; ++i) engine.step(0.1f);
  heads = engine.latest().heads;
  ASSERT_EQ(heads[0].serial, 3u);
  EXPECT_EQ(guard.copy(heads, upload), 2u);
  EXPECT_EQ(chainState(upload[0]), ChainState::Initialising);
  EXPECT_EQ(chainState(upload[1]), ChainState::Initialising);
  EXPECT_THROW(guard.copy(heads, std::span<HeadState>(upload).first(1)), std::invalid_argument);
}

// -------------------------------------------------------------------------------- chain reference

ChainParams stillField(float lerp) { return {1.0f / 60.0f, lerp, 0.0f, 0.5f, 0.0}; }

HeadState headIn(ChainState state, glm::vec3 origin, float life, uint32_t flags = 0u) {
  return {.origin = origin,
          .life = life,
          .state = uint32_t(state),
          .serial = 1u,
          .steps = 0u,
          .flags = flags,
          .launch = launchVelocity(1u, origin)};
}

TEST(NeonChains, AFollowerConvergesGeometricallyToAStillHead) {
  constexpr uint32_t P = 3;
  const glm::vec3 head{1.0f, 2.0f, 3.0f}, start{5.0f, -1.0f, 0.5f};
  std::vector<HeadState> heads{headIn(ChainState::Alive, head, 0.75f)};
  heads[0].launch = glm::vec3(0.0f);  // no launch, in a still field: the head stays
  std::vector<glm::vec4> previous{glm::vec4(head, 0.0f), glm::vec4(start, 0.0f), glm::vec4(start, 0.0f)}, next(P);
  const float lerp = 0.2f;
  for (int n = 1; n <= 30; ++n) {
    stepChains(heads, P, previous, next, stillField(lerp));
    ASSERT_EQ(glm::vec3(next[0]), head);
    const float expected = std::pow(1.0f - lerp, float(n)) * glm::length(start - head);
    ASSERT_NEAR(glm::length(glm::vec3(next[1]) - head), expected, 1e-5f + 1e-5f * expected) << "frame " << n;
    // Straight in: the follower stays on the segment from its start to the head.
    ASSERT_NEAR(glm::length(glm::cross(glm::vec3(next[1]) - head, start - head)), 0.0f, 1e-4f);
    ASSERT_EQ(next[1].w, 0.75f);  // life copied from the head, for the fade
    std::swap(previous, next);
  }
  // The second follower chases the first: it lags, but it gets there too.
  EXPECT_GT(glm::length(glm::vec3(previous[2]) - head), glm::length(glm::vec3(previous[1]) - head));
  EXPECT_LT(glm::length(glm::vec3(previous[2]) - head), 0.1f);
}

TEST(NeonChains, FollowersChaseLastFramesPositions) {
  // lerp = 1 closes the whole gap: every follower lands exactly where the one ahead was last frame,
  // not where it is now, so the chain shifts by one.
  constexpr uint32_t P = 4;
  const std::vector<HeadState> heads{headIn(ChainState::Alive, {}, 1.0f)};
  std::vector<glm::vec4> previous(P), next(P);
  for (uint32_t k = 0; k < P; ++k) previous[k] = glm::vec4(scatter(k, 3u), 0.0f);
  const ChainParams p{0.1f, 1.0f, 2.0f, 0.5f, 1.5};
  stepChains(heads, P, previous, next, p);
  const glm::vec3 velocity = maths::flowVelocity(glm::vec3(previous[0]), chainField(p));
  const glm::vec3 moved =
      glm::vec3(previous[0]) + (velocity * p.fieldStrength + heads[0].launch) * p.dt;
  EXPECT_EQ(glm::vec3(next[0]), moved);
  EXPECT_GT(glm::length(moved - glm::vec3(previous[0])), 1e-3f);  // the field is not zero there
  for (uint32_t k = 1; k < P; ++k) EXPECT_EQ(glm::vec3(next[k]), glm::vec3(previous[k - 1])) << k;
}

TEST(NeonChains, InitialisingPlacesTheChainAndInactiveLeavesIt) {
  constexpr uint32_t P = 4;
  const std::vector<HeadState> heads{headIn(ChainState::Initialising, {7.0f, 8.0f, 9.0f}, 1.0f),
                                     headIn(ChainState::Inactive, {7.0f, 8.0f, 9.0f}, 0.0f)};
  std::vector<glm::vec4> previous(2 * P), next(2 * P);
  for (uint32_t i = 0; i < 2 * P; ++i) previous[i] = glm::vec4(scatter(i, 4u), 0.5f);
  stepChains(heads, P, previous, next, {0.1f, 0.3f, 1.0f, 0.5f, 0.0});
  for (uint32_t k = 0; k < P; ++k) {
    EXPECT_EQ(next[k], glm::vec4(7.0f, 8.0f, 9.0f, 1.0f)) << k;
    EXPECT_EQ(next[P + k], glm::vec4(glm::vec3(previous[P + k]), 0.0f)) << k;  // stays, life 0: invisible
  }
}

TEST(NeonChains, RejectsShortBuffers) {
  const std::vector<HeadState> heads(2);
  std::vector<glm::vec4> previous(7), next(8);
  EXPECT_THROW(stepChains(heads, 4, previous, next, stillField(0.5f)), std::invalid_argument);
}

TEST(NeonChains, PushBlockCarriesTheDriftComputedInDouble) {
  const ChainParams p{0.02f, 0.3f, 1.5f, 0.4f, 1234.5};
  const shader::NeonChainPush push = chainPush(16, 32, p);
  const maths::FieldSettings field = maths::fieldAtTime(maths::FieldKind::Curl, 0.4f, 0.0f, 1234.5);
  EXPECT_EQ(push.offsetY, field.offsetY);
  EXPECT_EQ(push.offsetZ, field.offsetZ);
  EXPECT_NE(push.offsetY, maths::kPotentialOffsetY);  // the drift is in
  EXPECT_EQ(push.chainCount, 16u);
  EXPECT_EQ(push.particlesPerChain, 32u);
  EXPECT_EQ(push.dt, 0.02f);
  EXPECT_EQ(push.lerp, 0.3f);
  EXPECT_EQ(push.fieldStrength, 1.5f);
  EXPECT_EQ(push.noiseScale, 0.4f);
}

// A free head leaves its release point even in a still field (field_strength 0), so its tube has
// length and shows; a steered one stays exactly where its pen is.
TEST(NeonChains, AFreeHeadMovesInAStillFieldAndASteeredOneStaysOnItsPen) {
  constexpr uint32_t P = 8;
  const glm::vec3 origin{1.0f, 6.0f, 4.0f};
  const std::vector<HeadState> heads{headIn(ChainState::Alive, origin, 1.0f),
                                     headIn(ChainState::Alive, origin, 1.0f, kHeadSteered)};
  std::vector<glm::vec4> previous(2 * P, glm::vec4(origin, 1.0f)), next(2 * P);
  for (int n = 0; n < 60; ++n) {  // one second at 60 Hz
    stepChains(heads, P, previous, next, stillField(followerLerp(0.3f, 1.0f / 60.0f)));
    std::swap(previous, next);
  }
  EXPECT_NEAR(glm::length(glm::vec3(previous[0]) - origin), kLaunchSpeed, 1e-4f);
  EXPECT_GT(glm::length(glm::vec3(previous[0]) - glm::vec3(previous[P - 1])), 0.15f) << "a tube with length";
  EXPECT_EQ(glm::vec3(previous[P]), origin);
  EXPECT_EQ(launchVelocity(7u, origin), launchVelocity(7u, origin));
  EXPECT_NE(launchVelocity(7u, origin), launchVelocity(8u, origin)) << "each tube its own direction";
}

// The follower's share per step scales with the step, so a followers' lag, dt / share, is the same
// at every step rate; at 60 Hz it is the parameter itself.
TEST(NeonChains, FollowerLerpKeepsTheLagInSeconds) {
  EXPECT_FLOAT_EQ(followerLerp(0.3f, 1.0f / 60.0f), 0.3f);
  for (float dt : {1.0f / 240.0f, 1.0f / 120.0f, 1.0f / 60.0f, 1.0f / 30.0f})
    EXPECT_NEAR(dt / followerLerp(0.3f, dt), (1.0f / 60.0f) / 0.3f, 1e-5f) << dt;
  EXPECT_EQ(followerLerp(0.9f, 0.1f), 1.0f);  // never past the particle ahead
  EXPECT_EQ(followerLerp(0.3f, 0.0f), 0.0f);  // no time, no motion
}

// A free head launched at a steady 3 m/s in a still field, simulated for the same two seconds in 60 Hz
// steps (the gallery) and in 240 Hz steps (`record --fps 30 --spp 8`): its tube has the same length
// within 10 % (with a share of the gap per step instead of per second, the 240 Hz tube would be about
// 4x shorter).
float freeTubeLength(float dt) {
  constexpr uint32_t P = 32;
  std::vector<HeadState> heads{headIn(ChainState::Alive, {0.0f, 5.0f, 4.0f}, 1.0f)};
  heads[0].launch = glm::vec3(3.0f, 0.0f, 0.0f);
  std::vector<glm::vec4> previous(P, glm::vec4(0.0f, 5.0f, 4.0f, 1.0f)), next(P);
  const int steps = int(std::lround(2.0f / dt));
  for (int n = 1; n <= steps; ++n) {
    stepChains(heads, P, previous, next, {dt, followerLerp(0.3f, dt), 0.0f, 0.22f, 0.0});
    std::swap(previous, next);
  }
  float length = 0.0f;
  for (uint32_t k = 1; k < P; ++k) length += glm::length(glm::vec3(previous[k]) - glm::vec3(previous[k - 1]));
  return length;
}

TEST(NeonChains, TubeLengthIsTheSameAtTheGallerysStepAndARecordingsStep) {
  const float gallery = freeTubeLength(1.0f / 60.0f), recording = freeTubeLength(1.0f / 240.0f);
  EXPECT_GT(gallery, 1.0f) << "a tube metres long";
  EXPECT_NEAR(recording / gallery, 1.0f, 0.1f) << gallery << " m at 60 Hz steps, " << recording << " m at 240 Hz";
}

// -------------------------------------------------------------------------------- the pen

TEST(NeonEngine, APenIsOneHeadThatFollowsSteerAndKeepsItsLifeUntilLetGo) {
  ParticleEngine engine({8, 0.5f}, EngineMode::LockStep);
  engine.release({1.0f, 2.0f, 3.0f}, true);
  for (int i = 0; i < 10; ++i) {
    engine.steer({1.0f + float(i), 2.0f, 3.0f});
    engine.step(0.1f);
  }
  const Snapshot& drawn = engine.latest();
  EXPECT_EQ(drawn.releases, 1u) << "a drag is one release";
  EXPECT_EQ(chainState(drawn.heads[0]), ChainState::Alive);
  EXPECT_TRUE(steered(drawn.heads[0]));
  EXPECT_EQ(drawn.heads[0].origin, glm::vec3(10.0f, 2.0f, 3.0f));
  EXPECT_EQ(drawn.heads[0].life, 1.0f) << "full life while it draws";
  engine.endSteer();
  engine.steer({-5.0f, 0.0f, 0.0f});  // no pen any more: ignored
  engine.step(0.1f);
  const Snapshot& free = engine.latest();
  EXPECT_FALSE(steered(free.heads[0]));
  EXPECT_EQ(free.heads[0].origin, glm::vec3(10.0f, 2.0f, 3.0f));
  EXPECT_NEAR(free.heads[0].life, kFadeLife * (1.0f - 0.1f / kDrawnFadeSeconds), 1e-6f)
      << "let go, it fades from full brightness over kDrawnFadeSeconds";
  EXPECT_NE(free.heads[0].flags & kHeadDrawn, 0u) << "and keeps its drawn shape";
  for (int i = 0; i < 18; ++i) engine.step(0.1f);
  EXPECT_EQ(chainState(engine.latest().heads[0]), ChainState::Alive) << "fading for kDrawnFadeSeconds";
  engine.step(0.1f);
  engine.step(0.1f);
  EXPECT_EQ(chainState(engine.latest().heads[0]), ChainState::Inactive) << "gone after kDrawnFadeSeconds";
}

TEST(NeonEngine, AFullEngineNeverReplacesThePen) {
  ParticleEngine engine({3, 0.5f}, EngineMode::LockStep);
  engine.release({0.0f, 0.0f, 0.0f}, true);  // slot 0, the oldest
  engine.step(0.1f);
  for (int i = 0; i < 5; ++i) {
    engine.release({float(i), 1.0f, 0.0f});
    engine.step(0.1f);
  }
  const Snapshot& s = engine.latest();
  EXPECT_TRUE(steered(s.heads[0]));
  EXPECT_EQ(s.heads[0].serial, 1u);
  EXPECT_EQ(s.releases, 6u);
}

// A pen's chain records its path: the cursor moving round a quarter circle in small steps leaves a
// point every 0.6 m on the circle, the oldest at the start; let go, the drawn chain stays as it is.
TEST(NeonChains, APenRecordsItsPathAndADrawnChainKeepsIt) {
  constexpr uint32_t P = 16;
  constexpr float kRadius = 5.0f;
  const glm::vec3 centre{0.0f, 8.0f, 4.0f};
  const auto onCircle = [&](float angle) {
    return centre + kRadius * glm::vec3(std::cos(angle), std::sin(angle), 0.0f);
  };
  std::vector<HeadState> heads{headIn(ChainState::Alive, onCircle(0.0f), 1.0f, kHeadSteered | kHeadDrawn)};
  std::vector<glm::vec4> previous(P, glm::vec4(onCircle(0.0f), 1.0f)), next(P);
  const ChainParams p{1.0f / 60.0f, 0.3f, 1.6f, 0.22f, 0.0};
  constexpr int kSteps = 200;  // 0.05 m a step: 10 m of path, more than the 15 followers hold
  for (int n = 1; n <= kSteps; ++n) {
    heads[0].origin = onCircle(0.01f * float(n));
    stepChains(heads, P, previous, next, p);
    std::swap(previous, next);
  }
  EXPECT_EQ(glm::vec3(previous[0]), onCircle(0.01f * kSteps)) << "the head is the pen";
  for (uint32_t k = 1; k < P; ++k) {
    EXPECT_NEAR(glm::length(glm::vec3(previous[k]) - centre), kRadius, 1e-3f) << "on the path " << k;
    const float gap = glm::length(glm::vec3(previous[k]) - glm::vec3(previous[k - 1]));
    // A point where the pen first was 0.6 m from the last (in 0.05 m steps, up to 0.65 m from it).
    EXPECT_GE(gap, k == 1 ? 0.0f : 0.6f - 1e-4f) << k;
    EXPECT_LE(gap, 0.65f + 1e-4f) << k;
  }
  heads[0].flags = kHeadDrawn;  // let go
  const std::vector<glm::vec4> drawnChain = previous;
  for (int n = 0; n < 30; ++n) {
    stepChains(heads, P, previous, next, p);
    std::swap(previous, next);
  }
  for (uint32_t k = 0; k < P; ++k) EXPECT_EQ(glm::vec3(previous[k]), glm::vec3(drawnChain[k])) << k;
}

TEST(NeonChains, WorkgroupsCoverEveryParticleWithinDeviceLimits) {
  constexpr uint32_t kGroup = 64;  // chains.comp's local size (the scene asks the program for it)
  for (uint64_t particles : {1ull, 64ull, 65ull, 512ull, 65535ull * 64, 65536ull * 64, 65536ull * 64 + 1}) {
    const glm::uvec2 groups = chainGroups(particles, kGroup);
    const uint64_t invocations = uint64_t(groups.x) * groups.y * kGroup;
    EXPECT_LE(groups.x, 65535u) << particles;
    EXPECT_GE(invocations, particles) << particles;
    EXPECT_LT(invocations - particles, uint64_t(groups.y + 1) * kGroup) << "few spare groups";
  }
  EXPECT_EQ(chainGroups(16 * 32, kGroup), glm::uvec2(8u, 1u));
  EXPECT_EQ(chainGroups(65536ull * 64, kGroup).y, 2u);
  EXPECT_EQ(chainGroups(0, kGroup), glm::uvec2(0u, 0u));
  EXPECT_EQ(chainGroups(512, 256), glm::uvec2(2u, 1u)) << "any local size";
}

}  // namespace
}  // namespace vitrine::neon
