#pragma once
// Everything the bloom panel, --set and the settings file can change, declared once (params/schema.h),
// with the write-up's numbers as defaults.
#include "scenes/quality.h"
#include "params/schema.h"
#include "scenes/catalogue.h"

namespace vitrine::bloom {

enum class PhaseSource { Gpu, Cpu };

struct Settings {
  int lattice = 96;                // voxels per side
  float diffusion = 15.0f;         // D, voxels^2 / s at 96^3 (with the source: bloom_math.h, kFractionBands)
  float decayRising = 0.10f;       // per second while vapour flows in
  float decayVenting = 0.40f;      // per second once it stops
  float sourceRate = 0.5f;         // concentration per second at the source centre, hovering
  float breath = 0.0f;             // without the cursor: a source at the heart, times sourceRate (live input)
  float dragBoost = 2.5f;          // times the source rate while the button is held
  float sigma = 20.0f;             // source width, voxels at 96^3
  float reach = 1.1f;              // the cursor injects while its ray meets the crystal grown by this
  PhaseSource phaseSource = PhaseSource::Gpu;
  float thresholdAmber = 0.25f;    // concentrations whose crossing is a phase event
  float thresholdRose = 0.45f;
  float thresholdCrimson = 0.65f;
  float thresholdChroma = 0.82f;
  int samples = 56;                // volume samples entry to exit
  float volume = 0.8f;
  bool mute = false;
  float reverbWet = 0.28f;         // how far the plate reverb opens at the climax
  float fill = 0.0f;               // transient: start (or restart) with the crystal at this concentration
  bool vent = false;               // transient action: empty the lattice now
  Tier tier = Tier::Auto;  // render scale 1, 0.7, 0.5 (scenes/quality.h), and the lattice (tierLattice)
  float targetMs = 16.0f;
};

const params::Schema& schema();
// What the scene is by name: its title, key, help line and actions, with the schema above.
extern const SceneInfo kSceneInfo;

// What a quality tier costs beside its render scale: the lattice's side, and with it the diffusion's
// passes (which grow with its square) and the statistics, and the raymarch's samples in proportion,
// so that a sample spans the same share of a voxel. High: as set; medium 0.8 of the side; low 2/3
// (96^3 -> 64^3: 30 % of the voxels). The physics are scaled to the side (bloom_math.h), so every tier
// shows the same vapour in the same places. Sides stay multiples of 8 and within the parameter's range.
int tierLattice(int lattice, Tier tier);
int tierSamples(int samples, int lattice, int latticeInUse);

}  // namespace vitrine::bloom
