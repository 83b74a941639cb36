#pragma once
// The maths of the bloom scene (seed 000, "The Bloom"), in plain C++ that shaders/bloom/ mirrors and
// GoogleTest checks: the octahedral crystal and its lattice, the diffusion's passes (the CPU reference
// of diffuse.comp) and the plan of explicit sub-steps or Runge-Kutta-Legendre stages a frame takes,
// the phase colours, the cursor's ray into the crystal, the CPU proxy of the seed, and the phase
// detector.
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <fmt/format.h>
#include <optional>

#include <string>
#include <string_view>
#include <vector>

namespace vitrine::bloom {

// ------------------------------------------------------------------------------------ the crystal
// An octahedron |x| + |y| + |z| <= R about the origin. The lattice of N^3 voxels spans its bounding
// box [-R, R]^3; voxel i's centre is at normalised coordinate (i + 0.5) / N * 2 - 1.
inline constexpr float kCrystalRadius = 0.8f;  // world units, centre to vertex

inline glm::vec3 voxelCentre(glm::uvec3 voxel, uint32_t n) { return (glm::vec3(voxel) + 0.5f) / float(n) * 2.0f - 1.0f; }
inline bool insideCrystal(glm::vec3 normalised) {
  return std::abs(normalised.x) + std::abs(normalised.y) + std::abs(normalised.z) <= 1.0f;
}
// The interior whose state the phases report: the octahedron scaled by 0.7 about the centre (34 % of
// the crystal's voxels). The zero outside drains a shell under the surface that never saturates
// however long the vapour flows, so the crystal's state is read where it can be saturated.
inline constexpr float kCoreRadius = 0.7f;  // of the crystal's radius
inline bool insideCore(glm::vec3 normalised) {
  return std::abs(normalised.x) + std::abs(normalised.y) + std::abs(normalised.z) <= kCoreRadius;
}

// The volume samples for a chord of `span` through the crystal when its longest chord (2R, vertex to
// vertex) takes `samples`: the step is never longer than that chord's, so a short chord near an edge or
// a facet costs a few samples, not as many as the longest. Lines through a convex body are on average
// 4 V / S long (Cauchy): 0.77 R for the octahedron, 0.385 of its longest, so a frame takes ~2.6x fewer
// samples than a fixed count per ray would, at the same sample spacing or finer.
inline uint32_t crystalSamples(float span, float radius, uint32_t samples) {
  const float wanted = std::ceil(span / (2.0f * radius) * float(samples));
  return std::clamp(uint32_t(std::max(wanted, 1.0f)), 1u, std::max(samples, 1u));
}

// ---------------------------------------------------------------------------------- the diffusion
// dc/dt = L(c) = D (sum of the six neighbours - 6 c) + source - decay c inside the crystal, zero
// outside, clamped to [0, kMaxConcentration] after each step.
// Rates are given for a 96^3 lattice and scaled with it, so a finer lattice shows the same picture:
// D (voxels^2 / s) grows with (N / 96)^2 and the source's sigma (voxels) with N / 96.
inline constexpr float kMaxConcentration = 1.05f;
inline constexpr uint32_t kReferenceLattice = 96;
// The explicit scheme is stable when D dt 6 < 1 per sub-step; 0.9 keeps a margin (and no overshoot
// ringing, which starts at 0.5 per axis pair for oscillating modes of the 3D Laplacian stencil).
inline constexpr float kStabilityLimit = 0.9f;

struct DiffusionParams {
  float diffusion = 0.0f;  // D, voxels^2 / s at this lattice size
  float decay = 0.0f;      // per second
  float dt = 0.0f;         // one step (an explicit sub-step, or a super step of stages), seconds
  bool sourceOn = false;
  glm::vec3 source{0.0f};  // the source centre, in voxel coordinates (0..N)
  float sigma = 1.0f;      // voxels
  float sourceRate = 0.0f; // concentration per second at the source centre
};

inline float scaledDiffusion(float diffusionAt96, uint32_t n) {
  const float s = float(n) / float(kReferenceLattice);
  return diffusionAt96 * s * s;
}
inline float scaledSigma(float sigmaAt96, uint32_t n) { return sigmaAt96 * float(n) / float(kReferenceLattice); }

// How many explicit steps of the frame's time the stability limit allows (real: 1.7 needs two).
inline float explicitStepsFor(float diffusion, float frameDt) { return 6.0f * diffusion * frameDt / kStabilityLimit; }
// Fixed sub-steps for a frame of frameDt seconds so that D dt 6 stays at or under the limit.
inline uint32_t substepsFor(float diffusion, float frameDt) {
  return std::max(1u, uint32_t(std::ceil(explicitStepsFor(diffusion, frameDt))));
}

// A frame's diffusion: explicit sub-steps, or one super step of Runge-Kutta-Legendre stages (RKL1,
// Meyer, Balsara & Aslam 2014). The explicit step's limit makes a frame's sub-steps grow with D, so
// with the lattice squared: 48 at 512^3. s RKL1 stages form the Legendre polynomial P_s(1 + w z),
// w = 2 / (s^2 + s), which is bounded by 1 for a step (s^2 + s) / 2 times the explicit limit: 10
// passes do the work of 55 sub-steps. First order in time like the explicit step (its s = 1 case),
// and at 0.9 of the limit it damps the fastest modes to 0.3-0.5 of themselves each super step.
struct DiffusionPlan {
  uint32_t superSteps = 1;  // each ends with the clamp
  uint32_t stages = 1;      // passes in each; 1: the explicit step
  float dt = 0.0f;          // one super step, seconds
  uint32_t passes() const { return superSteps * stages; }
};
// The fewest stages whose super step covers `explicitSteps` explicit ones.
inline uint32_t rklStagesFor(float explicitSteps) {
  uint32_t s = 1;
  while (float(s * s + s) * 0.5f < explicitSteps) ++s;
  return s;
}
// The stages where they take fewer passes than the sub-steps, and exactly the sub-steps where not
// (the default 96^3 lattice at 60 Hz: two explicit sub-steps, as before).
inline DiffusionPlan diffusionPlan(float diffusion, float frameDt) {
  const uint32_t substeps = substepsFor(diffusion, frameDt);
  const uint32_t stages = rklStagesFor(explicitStepsFor(diffusion, frameDt));
  if (stages < substeps) return {1, stages, frameDt};
  return {substeps, 1, frameDt / float(substeps)};
}

// Stage j (1..s) of an s-stage super step of dt: next = keep * here + older * (the stage before
// here) + step * dt * L(here). Stage 1 of one stage is the explicit step: {1, 0, 1}.
struct StageWeights {
  float keep = 1.0f, older = 0.0f, step = 1.0f;
};
inline StageWeights rklStage(uint32_t j, uint32_t stages) {
  const float w = 2.0f / float(stages * stages + stages);
  if (j <= 1) return {1.0f, 0.0f, w};
  const float mu = float(2 * j - 1) / float(j);
  return {mu, 1.0f - mu, mu * w};
}
// The stages rotate three lattices: slot 0 holds the frame's state, a stage reads the last two
// results and writes the third slot. Stage 1 writes slot 1, or slot 2 where that would leave the
// super step's result in slot 2, so the result always lands in slot 0 or 1: a lattice pair the
// scene flips between, plus a scratch lattice that never holds the state.
inline uint32_t firstStageSlot(uint32_t stages) { return stages % 3 == 2 ? 2u : 1u; }
// The slot stage j writes, given the slots of the last result (here) and the one before (older).
inline uint32_t stageSlot(uint32_t j, uint32_t stages, uint32_t here, uint32_t older) {
  return j == 1 ? firstStageSlot(stages) : 3u - here - older;
}
inline uint32_t resultSlot(uint32_t stages) {  // 0 or 1
  uint32_t older = 0, here = 0;
  for (uint32_t j = 1; j <= stages; ++j) {
    const uint32_t next = stageSlot(j, stages, here, older);
    older = here, here = next;
  }
  return here;
}

inline float sourceAt(glm::vec3 voxelCentreCoords, const DiffusionParams& p) {
  if (!p.sourceOn) return 0.0f;
  const glm::vec3 d = voxelCentreCoords - p.source;
  return p.sourceRate * std::exp(-glm::dot(d, d) / (2.0f * p.sigma * p.sigma));
}

// One voxel's stage, given its value, the stage before's, and the sum of its six (edge-clamped)
// neighbours; the last stage of a super step clamps.
inline float stageVoxel(float here, float older, float neighbourSum, glm::vec3 voxelCoords, bool inside,
                        const DiffusionParams& p, const StageWeights& w, bool last) {
  if (!inside) return 0.0f;
  const float change = p.diffusion * (neighbourSum - 6.0f * here) + sourceAt(voxelCoords, p) - p.decay * here;
  const float next = w.keep * here + w.older * older + w.step * p.dt * change;
  return last ? std::clamp(next, 0.0f, kMaxConcentration) : next;
}

// The CPU reference of one pass of shaders/bloom/diffuse.comp over an n^3 lattice (x fastest);
// `older` is read only where w.older is not zero.
inline void diffusionStage(const std::vector<float>& in, const std::vector<float>& older, std::vector<float>& out,
                           uint32_t n, const DiffusionParams& p, const StageWeights& w, bool last) {
  out.resize(in.size());
  const auto at = [&](int x, int y, int z) {
    const int end = int(n) - 1;  // zero flux: an edge voxel's missing neighbour is itself
    x = std::clamp(x, 0, end), y = std::clamp(y, 0, end), z = std::clamp(z, 0, end);
    return in[(size_t(z) * n + size_t(y)) * n + size_t(x)];
  };
  for (uint32_t z = 0; z < n; ++z)
    for (uint32_t y = 0; y < n; ++y)
      for (uint32_t x = 0; x < n; ++x) {
        const int ix = int(x), iy = int(y), iz = int(z);
        const float sum = at(ix - 1, iy, iz) + at(ix + 1, iy, iz) + at(ix, iy - 1, iz) + at(ix, iy + 1, iz) +
                          at(ix, iy, iz - 1) + at(ix, iy, iz + 1);
        const glm::uvec3 v{x, y, z};
        const size_t i = (size_t(z) * n + y) * n + x;
        out[i] = stageVoxel(in[i], w.older != 0.0f ? older[i] : 0.0f, sum, glm::vec3(v) + 0.5f,
                            insideCrystal(voxelCentre(v, n)), p, w, last);
      }
}
// One explicit step of p.dt.
inline void diffuseLattice(const std::vector<float>& in, std::vector<float>& out, uint32_t n,
                           const DiffusionParams& p) {
  diffusionStage(in, in, out, n, p, StageWeights{}, true);
}
// A frame of the plan, in place (p.dt is the plan's).
inline void diffuseFrame(std::vector<float>& lattice, uint32_t n, DiffusionParams p, const DiffusionPlan& plan) {
  p.dt = plan.dt;
  std::vector<float> older, next;
  for (uint32_t step = 0; step < plan.superSteps; ++step) {
    older = lattice;
    for (uint32_t j = 1; j <= plan.stages; ++j) {
      diffusionStage(lattice, older, next, n, p, rklStage(j, plan.stages), j == plan.stages);
      older.swap(lattice);
      lattice.swap(next);
    }
  }
}

// The fraction of the interior (insideCore) past each of four thresholds: the CPU mirror of stats.comp.
inline std::array<float, 4> interiorFractions(const std::vector<float>& lattice, uint32_t n,
                                              const std::array<float, 4>& thresholds) {
  std::array<uint32_t, 4> above{};
  uint32_t interior = 0;
  for (uint32_t z = 0; z < n; ++z)
    for (uint32_t y = 0; y < n; ++y)
      for (uint32_t x = 0; x < n; ++x) {
        if (!insideCore(voxelCentre({x, y, z}, n))) continue;
        ++interior;
        const float v = lattice[(size_t(z) * n + y) * n + x];
        for (size_t i = 0; i < 4; ++i) above[i] += v > thresholds[i] ? 1u : 0u;
      }
  std::array<float, 4> f{};
  for (size_t i = 0; i < 4; ++i) f[i] = interior ? float(above[i]) / float(interior) : 0.0f;
  return f;
}

// ------------------------------------------------------------------------------------ the colours
// The crystal's colour states, linear RGB: a cool clear white, then a saturated amber (sRGB about
// 250, 170, 40), a rose (236, 110, 150) and a crimson that is deep red (150, 8, 36). Warm states on a
// cool pristine crystal in a bone-white chamber.
inline constexpr glm::vec3 kPristine{0.86f, 0.89f, 0.93f};
inline constexpr glm::vec3 kAmber{0.955f, 0.40f, 0.021f};
inline constexpr glm::vec3 kRose{0.84f, 0.155f, 0.30f};
inline constexpr glm::vec3 kCrimson{0.30f, 0.0025f, 0.017f};
inline constexpr std::array<glm::vec3, 4> kPhaseColours{kPristine, kAmber, kRose, kCrimson};

// The chamber's glow shows the state the phase detector reports, flipping with the label: from the
// previous state's colour to the new one's over kFlipSeconds (a flip, not a fade; softer under reduced
// motion). The crystal's own samples are coloured by their concentration (vapourColour), which also
// sets how dense they are (sampleDensity): the drained shell is thin glass the chamber shows through,
// the vapour-filled interior deep and opaque.
inline constexpr float kFlipSeconds = 0.12f;
inline constexpr float kReducedMotionFlipSeconds = 0.6f;
inline glm::vec3 flipColour(glm::vec3 from, glm::vec3 to, float age, float seconds) {
  const float t = std::clamp(age / seconds, 0.0f, 1.0f);
  return glm::mix(from, to, t * t * (3.0f - 2.0f * t));
}
// Each volume sample takes its colour from its own concentration (the seed's phaseColor), so the vapour
// is seen moving through the crystal as colour fronts: amber where it has arrived, white where it has
// not, crimson throughout only once saturated. Three smoothsteps kColourEdge wide, each centred
// kColourLead under its phase's threshold (0.20 / 0.40 / 0.60 at the defaults, the seed's numbers): a
// sample flips just before the interior's share of it names the phase.
inline constexpr float kColourEdge = 0.06f, kColourLead = 0.05f;
inline float smoothstep(float e0, float e1, float x) {
  const float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}
inline glm::vec3 vapourColour(float v, glm::vec3 thresholds) {  // amber, rose, crimson
  glm::vec3 c = kPristine;
  for (int k = 0; k < 3; ++k) {
    const float at = thresholds[k] - kColourLead;
    c = glm::mix(c, kPhaseColours[size_t(k + 1)], smoothstep(at - 0.5f * kColourEdge, at + 0.5f * kColourEdge, v));
  }
  return c;
}

// Vapour under kCoverFrom changes nothing a viewer sees (white, and under 4 % of the glass's density):
// the crystal is clear glass while no voxel is past it.
inline constexpr float kCoverFrom = 0.04f;
// The extinction (per world unit) of a volume sample: thin glass plus what the vapour adds, growing
// with the square of its concentration. The vapour fronts are graded shells (white outside, crimson
// at the heart), and a square keeps the thin outer grades translucent while a saturated heart is
// opaque, so a crimson heart shows as crimson through its amber rim (a density that was already full
// at 0.2 hid everything behind the first amber).
inline constexpr float kGlassDensity = 0.9f, kVapourDensity = 18.0f;
inline float sampleDensity(float v) { return kGlassDensity + kVapourDensity * v * v; }
// How strongly a sample's colour counts where it shows (crystal.frag weighs each sample's colour by
// its share of the path's opacity and this): its concentration squared, as its pigment, so a thin
// amber rim over a saturated heart tints it little; the glass's own white, kGlassPigment, counts only
// where there is no vapour. Compositing by opacity alone showed a saturated crystal as a pink mix of
// the rims in front of its heart.
inline constexpr float kGlassPigment = 0.01f;
inline float vapourPigment(float v) { return kGlassPigment + v * v; }

// ------------------------------------------------------------------------------------ the camera
inline constexpr glm::vec3 kEye{0.0f, 0.2f, 3.0f};
inline constexpr float kFieldOfViewY = 0.75f;  // radians: room above the crystal for its words

struct Ray {
  glm::vec3 origin, direction;
};
// The ray through a point of the output, normalised 0..1 with the origin top-left.
inline Ray cameraRay(float u, float v, float aspect) {
  const glm::vec3 forward = glm::normalize(-kEye);
  const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f)));
  const glm::vec3 up = glm::cross(right, forward);
  const float h = std::tan(kFieldOfViewY * 0.5f);
  const glm::vec3 d = forward + right * ((u * 2.0f - 1.0f) * h * aspect) + up * ((1.0f - v * 2.0f) * h);
  return {kEye, glm::normalize(d)};
}

// Where a world point shows, normalised 0..1 with the origin top-left (the inverse of cameraRay).
inline glm::vec2 projectToView(glm::vec3 world, float aspect) {
  const glm::vec3 forward = glm::normalize(-kEye);
  const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f)));
  const glm::vec3 up = glm::cross(right, forward);
  const float h = std::tan(kFieldOfViewY * 0.5f);
  const glm::vec3 d = world - kEye;
  const float depth = glm::dot(d, forward);
  return {(glm::dot(d, right) / depth / (h * aspect) + 1.0f) * 0.5f, (1.0f - glm::dot(d, up) / depth / h) * 0.5f};
}

// The chord of a ray through the octahedron |x| + |y| + |z| <= radius (its 8 half-spaces), as the
// ray's parameters where it enters and leaves; none where it misses.
struct Chord {
  float in, out;
};
inline std::optional<Chord> octahedronChord(const Ray& ray, float radius) {
  Chord chord{-1e30f, 1e30f};
  for (int k = 0; k < 8; ++k) {
    const glm::vec3 n((k & 1) ? 1.0f : -1.0f, (k & 2) ? 1.0f : -1.0f, (k & 4) ? 1.0f : -1.0f);
    const float towards = glm::dot(n, ray.direction), room = radius - glm::dot(n, ray.origin);
    if (towards > 1e-6f) chord.out = std::min(chord.out, room / towards);
    else if (towards < -1e-6f) chord.in = std::max(chord.in, room / towards);
    else if (room < 0.0f) return std::nullopt;  // parallel to a face, outside it
  }
  if (chord.out <= std::max(chord.in, 0.0f)) return std::nullopt;
  return chord;
}

// Where the cursor puts the vapour, and whether it does. It injects while its ray meets the crystal
// grown by `reach` (the silhouette, and a margin around it): the rule follows the footprint, so a
// vertex plays like the centre. The source sits on the ray's point nearest the centre, pulled in to
// kSourcePull of that distance: the vapour arrives first on the cursor's side, and there is room
// around the source for it to reach the far side of the interior. Measured on the CPU reference at
// 48^3 and 96^3: with the pull at 1 (the source where the ray passes) a vertex never reached the
// climax; at 0.4, with sourceBoost, it takes 1.25x the centre's time.
inline constexpr float kSourcePull = 0.4f;
struct CursorVapour {
  glm::vec3 point;
  bool over;
};
inline CursorVapour cursorVapour(const Ray& ray, float reach) {
  const float t = std::max(0.0f, -glm::dot(ray.origin, ray.direction));
  return {(ray.origin + ray.direction * t) * kSourcePull, octahedronChord(ray, reach * kCrystalRadius).has_value()};
}

// The share of a Gaussian source's mass (sigma and centre in the lattice's normalised cube [-1, 1]^3)
// that falls inside the crystal, where the diffusion injects it: a midpoint sum over a 16^3 grid, close
// enough for a ratio (within 1 % of a 64^3 sum).
inline float sourceMassInside(glm::vec3 centre, float sigma) {
  constexpr int kGrid = 16;
  float mass = 0.0f;
  for (int z = 0; z < kGrid; ++z)
    for (int y = 0; y < kGrid; ++y)
      for (int x = 0; x < kGrid; ++x) {
        const glm::vec3 p = voxelCentre(glm::uvec3(x, y, z), kGrid);
        if (!insideCrystal(p)) continue;
        const glm::vec3 d = p - centre;
        mass += std::exp(-glm::dot(d, d) / (2.0f * sigma * sigma));
      }
  return mass;
}
// How much stronger the source runs away from the heart, so the crystal takes in the same vapour a
// second wherever the cursor is: the heart's mass inside over this centre's, at most kMaxSourceBoost.
inline constexpr float kMaxSourceBoost = 2.0f;
inline float sourceBoost(glm::vec3 centre, float sigma) {
  return std::clamp(sourceMassInside(glm::vec3(0.0f), sigma) / std::max(sourceMassInside(centre, sigma), 1e-6f), 1.0f,
                    kMaxSourceBoost);
}

// World position to voxel coordinates (0..n across the bounding box), clamped into the lattice.
inline glm::vec3 worldToVoxel(glm::vec3 world, uint32_t n) {
  return glm::clamp((world / kCrystalRadius * 0.5f + 0.5f) * float(n), glm::vec3(0.0f), glm::vec3(float(n)));
}

// ---------------------------------------------------------------------------- the CPU proxy (seed)
// dV/dt = S - D V: S = 0.20/s while the cursor is on the crystal, D = 0.10/s rising, 0.40/s venting.
struct ProxyRates {
  float source = 0.20f, decayRising = 0.10f, decayVenting = 0.40f;
};
inline float proxyStep(float v, bool sourceOn, float dt, const ProxyRates& r = {}) {
  const float s = sourceOn ? r.source : 0.0f;
  const float d = sourceOn ? r.decayRising : r.decayVenting;
  return std::clamp(v + (s - d * v) * dt, 0.0f, kMaxConcentration);
}

// --------------------------------------------------------------------------------- the phases
// Phase k (amber, rose, crimson) is reached on the way up when its signal rises to `on`, left on the
// way down when it falls below `off` (< on: hysteresis, so noise at a threshold cannot chatter);
// the climax likewise. Phases rise and fall in order.
enum class Phase { Pristine, Amber, Rose, Crimson };
inline constexpr std::array<std::string_view, 4> kPhaseNames{"pristine", "amber", "rose", "crimson"};

struct PhaseEvent {
  enum class Kind { Up, Climax, Vent } kind;
  Phase phase;         // Up: reached; Vent: left (Crimson for a climax that ended: see fromClimax)
  bool fromClimax = false;
  std::string_view name() const {
    if (kind == Kind::Climax) return "chroma";
    if (kind == Kind::Up) return kPhaseNames[size_t(phase)];
    return "vent";
  }
  std::string_view left() const { return fromClimax ? "chroma" : kPhaseNames[size_t(phase)]; }
};

struct Hysteresis {
  float on, off;
};

class PhaseDetector {
 public:
  // signal[k] for amber, rose, crimson, climax; bands[k] its on/off levels.
  std::vector<PhaseEvent> observe(const std::array<float, 4>& signal, const std::array<Hysteresis, 4>& bands) {
    std::vector<PhaseEvent> events;
    // Down first, from the top, so a fast vent reports every phase it leaves in order.
    if (climax_ && signal[3] < bands[3].off) {
      climax_ = false;
      events.push_back({PhaseEvent::Kind::Vent, Phase::Crimson, true});
    }
    while (phase_ > 0 && !climax_ && signal[size_t(phase_ - 1)] < bands[size_t(phase_ - 1)].off) {
      events.push_back({PhaseEvent::Kind::Vent, Phase(phase_), false});
      --phase_;
    }
    while (phase_ < 3 && signal[size_t(phase_)] >= bands[size_t(phase_)].on) {
      ++phase_;
      events.push_back({PhaseEvent::Kind::Up, Phase(phase_), false});
    }
    if (!climax_ && phase_ == 3 && signal[3] >= bands[3].on) {
      climax_ = true;
      events.push_back({PhaseEvent::Kind::Climax, Phase::Crimson, false});
    }
    return events;
  }
  Phase phase() const { return Phase(phase_); }
  bool climax() const { return climax_; }
  void reset() { phase_ = 0, climax_ = false; }

 private:
  int phase_ = 0;
  bool climax_ = false;
};

// The GPU source: the fraction of the interior's voxels (insideCore) above each event threshold. A
// phase is reached when 45 % of the interior is past its threshold and left below 25 %; the climax
// needs half of it past 0.82. With the default rates a hovering cursor's interior plateaus at
// 100 / 99 / 94 / 79 % past the four thresholds at every lattice size 48-256 (the held button's at
// 100 / 100 / 100 / 99 %), where the whole crystal, shell included, stops at 53 / 39 / 28 % past the
// last three: a hover reaches every phase and the climax, and the hysteresis keeps a margin.
inline constexpr std::array<Hysteresis, 4> kFractionBands{{{0.45f, 0.25f}, {0.45f, 0.25f}, {0.45f, 0.25f}, {0.5f, 0.25f}}};

// The words fade with the vapour, not on a clock. A phase's name is as present as the lattice stands in
// the phase: full from its flip, fading as its own signal falls towards leaving (a vent) or as the next
// phase's rises towards its flip (crimson's next is the climax).
inline float labelPresence(int phase, const std::array<float, 4>& signal, const std::array<Hysteresis, 4>& bands) {
  if (phase < 1 || phase > 3) return 0.0f;
  const size_t own = size_t(phase - 1), next = size_t(phase);
  return smoothstep(bands[own].off, bands[own].on, signal[own]) *
         (1.0f - smoothstep(bands[next].off, bands[next].on, signal[next]));
}
// CHROMA holds while the climax does, then fades with the vent: from full as the climax ends (the
// crimson signal then at `crimsonAtVent`) to nothing as the crystal leaves crimson.
inline float chromaPresence(bool climax, float crimsonSignal, float crimsonAtVent, const Hysteresis& crimsonBand) {
  if (climax) return 1.0f;
  return smoothstep(crimsonBand.off, std::max(crimsonAtVent, crimsonBand.off + 1e-3f), crimsonSignal);
}

// After the climax the crystal blooms for kBloomSeconds with the vapour still flowing, then exhales:
// no vapour enters until it has vented back to pristine, whether or not the cursor stays.
inline constexpr double kBloomSeconds = 2.5;
// The four event thresholds must rise; the message names the first pair that does not.
inline std::string thresholdOrderError(const std::array<float, 4>& t) {
  static constexpr std::array<std::string_view, 4> kNames{"amber", "rose", "crimson", "climax"};
  for (size_t i = 0; i + 1 < t.size(); ++i)
    if (!(t[i] < t[i + 1]))
      return fmt::format("the thresholds must rise (amber < rose < crimson < climax), but {} {} is not below {} {}",
                         kNames[i], t[i], kNames[i + 1], t[i + 1]);
  return {};
}

// One n^3 lattice of 32-bit floats.
inline constexpr uint64_t latticeBytes(uint32_t n) { return 4ull * n * n * n; }

// What bounds the lattice on a device: its 3D images (the crystal's view), one storage buffer's binding
// (a lattice is bound whole: 128 MiB on lavapipe, 4 GiB on NVIDIA) and its memory.
struct LatticeLimits {
  uint32_t maxImageDimension3D = 0;
  uint64_t maxStorageBufferRange = 0;
  uint64_t deviceLocalHeap = 0;
};

// Whether an n^3 lattice fits the device: within its largest 3D image and one storage buffer's
// binding, and its four copies (three storage buffers a stage reads two of and writes the third, and
// the view the crystal samples) within half its device memory, the rest left to the frame's images,
// the other scenes and the driver.
inline constexpr uint32_t kLatticeCopies = 4;
inline std::string latticeFitError(uint32_t n, const LatticeLimits& limits, std::string_view deviceName) {
  if (n > limits.maxImageDimension3D)
    return fmt::format("a {}^3 lattice is larger than the {}^3 3D images {} can make", n, limits.maxImageDimension3D,
                       deviceName);
  if (latticeBytes(n) > limits.maxStorageBufferRange)
    return fmt::format("a {}^3 lattice is {} MiB, more than the {} MiB one storage buffer binding spans on {}", n,
                       latticeBytes(n) >> 20, limits.maxStorageBufferRange >> 20, deviceName);
  const uint64_t bytes = kLatticeCopies * latticeBytes(n);
  if (bytes > limits.deviceLocalHeap / 2)
    return fmt::format("a {}^3 lattice needs {} MiB of device memory ({} copies), more than half of the {} MiB on {}",
                       n, bytes >> 20, kLatticeCopies, limits.deviceLocalHeap >> 20, deviceName);
  return {};
}

// The CPU source: the proxy's V against the thresholds themselves, 0.03 below to leave.
inline std::array<Hysteresis, 4> proxyBands(const std::array<float, 4>& thresholds) {
  std::array<Hysteresis, 4> bands{};
  for (size_t i = 0; i < 4; ++i) bands[i] = {thresholds[i], thresholds[i] - 0.03f};
  return bands;
}

}  // namespace vitrine::bloom
