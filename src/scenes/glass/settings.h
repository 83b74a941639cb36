#pragma once
// Everything the glass panel, --set, presets and the settings file can change, declared once
// (params/schema.h), with the original's ranges and defaults (its "Rotating cube" opening scene).
#include "scenes/quality.h"
#include "params/schema.h"
#include "scenes/catalogue.h"
#include "scenes/glass/shapes.h"

#include <string>

namespace vitrine::glass {

enum class RefractionMode { Exact, Approx };  // per-wavelength exits, or one at a hero wavelength
enum class Optics { Seed, Physical };
enum class Dispersion { Abbe, Sellmeier };
enum class Projection { Perspective, Orthographic };
enum class Antialiasing { None, Fxaa, Taa };
enum class DiamondDebug { None, Wireframe, Facets, Tir };
enum class SpectralPass { Raster, Compute };  // proxies' fragments, or a compute pass over the screen

struct Settings {
  int samplesIndex = 2;           // N = kSampleCounts[i] (optics.h): 16
  int material = 0;               // 0: custom (ior and abbe below); else kMaterials[material - 1]
  float ior = 1.272f;             // n_d
  float abbe = 2.0f;              // V_d
  float spread = 1.0f;            // multiplies the dispersion of abbe's Cauchy fit (live audio plays it)
  float strength = 0.15f;         // seed optics: how far the exit ray leans from the view ray toward the refraction
  RefractionMode mode = RefractionMode::Exact;
  bool jitter = true;
  Optics optics = Optics::Seed;
  Dispersion dispersion = Dispersion::Abbe;
  float depth = 400.0f;           // physical optics: the photo's distance behind the glass, world units

  ShapeKind shape = ShapeKind::Cube;
  float pillLength = 400.0f, pillHeight = 115.0f, pillThickness = 62.0f, pillEdge = 100.0f;
  bool smoothCurvature = true;   // pill, cube and plate: L4 squircle rims (the original's default)
  float prismLength = 393.0f, prismWidth = 149.0f, prismDepth = 117.0f;
  float cubeSize = 230.0f, cubeEdge = 44.0f;
  float plateSize = 346.0f, plateThickness = 60.0f, plateEdge = 10.5f;
  float waveAmplitude = 17.0f, waveLength = 535.0f;
  float diamondSize = 560.0f;   // 52 % of the view's height (the original's 400 looked small)
  DiamondView diamondView = DiamondView::Free;
  DiamondDebug diamondDebug = DiamondDebug::None;
  int bounces = 6;

  std::string background = "page";  // page | photo | gradient | checker | an image file or a folder of them
  bool environment = false;
  std::string panorama = "photo_studio";  // the built-in studio (studio.h), a fetched panorama's name, or an EXR
  float exposure = 1.0f;
  float envRotation = 0.0f;         // radians about the vertical axis: 0 faces the studio's lit cyclorama

  Projection projection = Projection::Perspective;
  float fov = 45.0f;                // degrees, vertical
  bool stopWorld = false;           // freeze rotation and waves; accumulation turns progressive
  Antialiasing aa = Antialiasing::None;
  float historyAlpha = 0.5f;
  bool showProxy = false;
  SpectralPass pass = SpectralPass::Compute;

  bool operator==(const Settings&) const = default;
  Tier tier = Tier::Auto;  // render scale: high 1, medium 0.7, low 0.5 (scenes/quality.h)
  float targetMs = 16.0f;
};

int sampleCount(const Settings& settings);
// The wavelengths a frame traces at a quality tier: with jitter on, whose frames take new strata that
// the history averages, medium 3/4 and low half of them (never fewer than 8, nor more than set): the
// converged rainbow is the same, a frame costs less. Jitter off samples fixed stratum centres, whose
// count is the picture: every tier keeps it.
int tierWavelengths(int wavelengths, Tier tier, bool jitter);

// The diamond preset's exposure and panorama rotation in the built-in studio, chosen by looking.
inline constexpr float kDiamondExposure = 1.0f;
inline constexpr float kDiamondRotation = 0.0f;
// The diamond preset's seed-optics lean: none. Light the stone returns leaves far from the view ray
// (through the crown, back toward the camera), and leaning it toward that ray by the original's 0.2
// looks through the stone at the wall behind it and shrinks the wavelengths' angular split fivefold,
// the fire. Unleaned, the seed's stone has a diamond's dark-and-white contrast and coloured flashes.
inline constexpr float kDiamondStrength = 1.0f;

const params::Schema& schema();
// What the scene is by name: its title, key, help line and actions, with the schema above.
extern const SceneInfo kSceneInfo;

}  // namespace vitrine::glass
