#include "scenes/bloom/settings.h"

#include <algorithm>
#include <cmath>

namespace vitrine::bloom {
namespace {
constexpr int kSmallestLattice = 48;  // the lattice parameter's minimum
}

const params::Schema& schema() {
  using S = Settings;
  using params::kLogarithmic, params::kRebuilds, params::kTransient;
  static const params::Schema table = [] {
    auto s = params::Schema::forStruct<S>();
    s.add(params::intParam<S>({"lattice", "lattice", "Voxels per side of the vapour lattice (at the high tier).", "vapour", kRebuilds},
                              &S::lattice, kSmallestLattice, 512));
    s.add(params::floatParam<S>({"diffusion", "diffusion", "How fast vapour spreads, voxels^2 per second at 96^3 "
                                 "(scaled with the lattice).", "vapour", kLogarithmic},
                                &S::diffusion, 0.5, 200.0));
    s.add(params::floatParam<S>({"decay_rising", "decay rising", "Decay per second while vapour flows in.", "vapour"},
                                &S::decayRising, 0.0, 2.0));
    s.add(params::floatParam<S>({"decay_venting", "decay venting", "Decay per second once the cursor leaves.",
                                 "vapour"},
                                &S::decayVenting, 0.0, 4.0));
    s.add(params::floatParam<S>({"source", "source strength", "Concentration per second the hovering cursor "
                                 "injects at its centre.", "vapour"},
                                &S::sourceRate, 0.0, 10.0));
    s.add(params::floatParam<S>({"breath", "breath", "Without the cursor, vapour drawn in at the crystal's heart, "
                                 "times the source strength (live audio breathes it with the level).", "vapour"},
                                &S::breath, 0.0, 3.0));
    s.add(params::floatParam<S>({"drag_boost", "drag boost", "Times stronger while the button is held.", "vapour"},
                                &S::dragBoost, 1.0, 10.0));
    s.add(params::floatParam<S>({"sigma", "source sigma", "Width of the Gaussian source, voxels at 96^3.", "vapour"},
                                &S::sigma, 2.0, 60.0));
    s.add(params::floatParam<S>({"reach", "reach", "The cursor injects while its ray meets the crystal grown by "
                                 "this factor: its silhouette and a margin around it.", "vapour"},
                                &S::reach, 1.0, 3.0));
    s.add(params::choiceParam<S>({"phase_source", "phase source", "gpu: the lattice's own statistics; cpu: the "
                                  "write-up's proxy dV/dt = S - D V.", "phases"},
                                 &S::phaseSource, {"gpu", "cpu"}));
    s.add(params::floatParam<S>({"threshold_amber", "amber at", "The concentration whose crossing (by 45 % of the "
                                 "crystal's interior) is the amber phase.", "phases"},
                                &S::thresholdAmber, 0.05, 1.0));
    s.add(params::floatParam<S>({"threshold_rose", "rose at", "The rose phase's concentration.", "phases"},
                                &S::thresholdRose, 0.05, 1.0));
    s.add(params::floatParam<S>({"threshold_crimson", "crimson at", "The crimson phase's concentration.", "phases"},
                                &S::thresholdCrimson, 0.05, 1.0));
    s.add(params::floatParam<S>({"threshold_chroma", "climax at", "The concentration half the crystal's interior "
                                 "must pass for the climax.", "phases"},
                                &S::thresholdChroma, 0.05, 1.05));
    s.add(params::intParam<S>({"samples", "samples", "Volume samples along the crystal's longest chord (vertex to vertex); shorter chords take fewer, at the same spacing.", "render"}, &S::samples,
                              8, 256));
    s.add(params::floatParam<S>({"volume", "volume", "Master volume.", "sound"}, &S::volume, 0.0, 1.0));
    s.add(params::boolParam<S>({"mute", "mute", "Silence (M in the gallery).", "sound"}, &S::mute));
    s.add(params::floatParam<S>({"reverb_wet", "reverb wet", "How far the plate reverb opens at the climax.",
                                 "sound"},
                                &S::reverbWet, 0.0, 1.0));
    s.add(params::floatParam<S>({"fill", "fill", "Restart with the whole crystal at this concentration (tests, "
                                 "stills).", "actions", kTransient},
                                &S::fill, 0.0, 1.05));
    s.add(params::boolParam<S>({"vent", "vent now", "Empty the lattice at once.", "actions", kTransient}, &S::vent));
    s.audioMapping("audio.level=breath:0:1.2 attack=0.05 release=0.8");
    s.preset({"fine", "A 160^3 lattice with more samples.", {{"lattice", "160"}, {"samples", "96"}}});
    s.preset({"quick", "A 64^3 lattice, fast phases: for slow devices.",
              {{"lattice", "64"}, {"source", "3"}, {"samples", "40"}}});
    addQualityParams<S>(s, "Render scale of the raymarch and the word, and the lattice's side (medium 0.8, low 2/3) "
                           "with the samples in proportion", 16.0f);
    return s;
  }();
  return table;
}

int tierLattice(int lattice, Tier tier) { return tierCount(lattice, tier, kSmallestLattice, {0.8, 2.0 / 3.0}, 8); }

int tierSamples(int samples, int lattice, int latticeInUse) {
  if (latticeInUse == lattice) return samples;
  return std::max(8, int(std::lround(double(samples) * latticeInUse / lattice)));
}

constinit const SceneInfo kSceneInfo{"bloom", "The Bloom", 1, &schema,
    "Move the cursor near the crystal: it is the vapour. Hold the button to breathe harder. M mutes."};

}  // namespace vitrine::bloom
