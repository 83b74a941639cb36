#pragma once
// Everything the neon panel, --set, presets and the settings file can change, declared once
// (params/schema.h). Lengths are metres in front of a facade about 20 m wide.
#include "scenes/quality.h"
#include "params/schema.h"
#include "scenes/catalogue.h"

#include <glm/vec3.hpp>

namespace vitrine::neon {

// What the frame shows: the facade alone, then each stage of the composite added (the seed's closing
// figure, stage by stage).
enum class Stage { Base, Tubes, Bloom, Dof, Tint, Final };

struct Settings {
  int chains = 64;                 // tubes alive at once at most
  int particles = 64;              // particles per chain: the tube's length in steps
  float decay = 0.11f;             // life lost per second once alive
  float lerp = 0.26f;              // how far a follower moves toward the particle ahead in 1/60 s
  float fieldStrength = 1.6f;      // the curl-noise flow's speed, m/s
  float fieldScale = 0.22f;        // noise cells per metre
  float radius = 0.1f;             // tube radius, m
  glm::vec3 colourA = params::hexColour(0xff2a6d);  // neon pink
  glm::vec3 colourB = params::hexColour(0x05d9e8);  // neon cyan
  glm::vec3 colourC = params::hexColour(0xffa41b);  // neon amber
  float glow = 3.0f;               // emissive intensity
  float autopilotIdle = 3.0f;      // seconds without input before the autopilot plays
  float autopilotRate = 0.7f;      // heads the autopilot releases per second
  float bloomStrength = 2.0f;
  float bloomRadius = 1.0f;
  float focalDistance = 26.0f;     // m from the camera: the release plane, where the tubes are
  float aperture = 0.6f;           // circle-of-confusion scale
  glm::vec3 tintA = params::hexColour(0xf7c6ff);
  glm::vec3 tintB = params::hexColour(0x9ad7ff);
  float tintStrength = 0.35f;
  float vignette = 0.45f;
  float grain = 0.04f;
  float aberration = 0.6f;         // pixels at the corners
  float mirror = 0.45f;
  float distortion = 0.35f;
  Stage stage = Stage::Final;

  bool operator==(const Settings&) const = default;
  Tier tier = Tier::Auto;  // render scale 1, 0.7, 0.4 (tierRenderScale), and the chains (tierChains)
  float targetMs = 16.0f;
};

const params::Schema& schema();
// What the scene is by name: its title, key, help line and actions, with the schema above.
extern const SceneInfo kSceneInfo;

// What a quality tier costs beside its render scale: the chains the engine releases into (high: as set;
// medium 3/4; low 1/2, never under the parameter's 16), which the chains and tubes passes step and
// draw. The default's autopilot keeps about six alive, under every tier's; a dense field thins out, each
// tube the same, the bloom's exposure following the count (tube_light.h).
int tierChains(int chains, Tier tier);
// The render scale: quality.h's, but 0.4 rather than 0.5 at the low tier. There, on a CPU device, the
// look's passes over the frame (bloom, depth of field, composite: texture taps, which llvmpipe pays
// for one by one) are three quarters of the frame (docs/PERFORMANCE.md, neon, Decisions). The tubes
// stay lines; the facade is softer.
float tierRenderScale(Tier tier);

}  // namespace vitrine::neon
