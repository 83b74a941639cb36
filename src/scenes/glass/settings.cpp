#include "scenes/glass/settings.h"

#include "scenes/glass/materials.h"
#include "scenes/glass/optics.h"
#include "scenes/glass/studio.h"

namespace vitrine::glass {
namespace {

// The panoramas scripts/setup fetches (Blender's studio lights): names a remote client may choose.
std::vector<std::string> panoramaBuiltIns() {
  return {std::string(kStudioPanorama), "city", "courtyard", "forest", "interior", "night", "studio", "sunrise",
          "sunset"};
}

std::vector<std::string> materialNames() {
  std::vector<std::string> names{"custom"};
  for (const Material& material : kMaterials) names.emplace_back(material.key);
  return names;
}

}  // namespace

int sampleCount(const Settings& settings) { return kSampleCounts[size_t(settings.samplesIndex)]; }

int tierWavelengths(int wavelengths, Tier tier, bool jitter) {
  return jitter ? tierCount(wavelengths, tier, 8) : wavelengths;
}

const params::Schema& schema() {
  using S = Settings;
  using params::kLogarithmic, params::kTransient;
  static const params::Schema table = [] {
    auto s = params::Schema::forStruct<S>();
    // glass
    s.add(params::choiceParam<S>({"n", "wavelengths", "Wavelengths traced per pixel, stratified over 380-700 nm.",
                                  "glass"},
                                 &S::samplesIndex, {"3", "8", "16", "32", "64"}));
    s.add(params::choiceParam<S>({"material", "material", "A real or fantasy glass; custom uses ior and abbe. "
                                  "Moving either slider makes it custom.", "glass"},
                                 &S::material, materialNames()));
    s.add(params::floatParam<S>({"ior", "IOR n_d", "Refractive index at the helium d line, 587.56 nm.", "glass"},
                                &S::ior, 1.0, 3.5));
    s.add(params::floatParam<S>({"abbe", "Abbe V_d", "Abbe number: lower disperses more.", "glass", kLogarithmic},
                                &S::abbe, 1.0, 100.0));
    s.add(params::floatParam<S>({"spread", "dispersion spread", "Multiplies the dispersion of the Abbe fit: 1 as the "
                                 "glass has it, 2 twice the rainbow (live audio plays it with the highs).", "glass",
                                 kLogarithmic},
                                &S::spread, 0.25, 4.0));
    s.add(params::floatParam<S>({"strength", "refraction strength", "Seed optics: how far the exit ray leans from "
                                 "the view ray toward the refracted direction.", "glass"},
                                &S::strength, 0.0, 1.0));
    s.add(params::choiceParam<S>({"mode", "refraction", "exact: every wavelength finds its own exit; approx: one "
                                  "exit at a hero wavelength per frame.", "glass"},
                                 &S::mode, {"exact", "approx"}));
    s.add(params::boolParam<S>({"jitter", "temporal jitter", "Per-pixel and per-frame wavelength jitter; off "
                                "samples the stratum centres.", "glass"},
                               &S::jitter));
    s.add(params::choiceParam<S>({"optics", "optics", "seed: the original's (Schlick, all-or-nothing TIR, leaning "
                                  "exit, clipped); physical: exact Fresnel with the split carried, true exit "
                                  "directions, filmic tone map.", "glass"},
                                 &S::optics, {"seed", "physical"}));
    s.add(params::choiceParam<S>({"dispersion", "dispersion", "abbe: Cauchy from n_d and V_d; sellmeier: the "
                                  "published coefficients of a real material (others keep abbe).", "glass"},
                                 &S::dispersion, {"abbe", "sellmeier"}));
    s.add(params::floatParam<S>({"depth", "photo depth", "Physical optics: how far behind the glass the photo "
                                 "hangs, world units (the view is 1073 tall).", "glass", kLogarithmic},
                                &S::depth, 20.0, 5000.0));
    // shape
    s.add(params::choiceParam<S>({"shape", "shape", "The glass: four of a shape, or one diamond.", "shape"},
                                 &S::shape, {"pill", "prism", "cube", "plate", "diamond"}));
    s.add(params::floatParam<S>({"pill_length", "pill length", "Pill length, world units.", "shape"},
                                &S::pillLength, 40.0, 1000.0));
    s.add(params::floatParam<S>({"pill_height", "pill height", "Pill height.", "shape"}, &S::pillHeight, 20.0, 600.0));
    s.add(params::floatParam<S>({"pill_thickness", "pill thickness", "Pill thickness.", "shape"}, &S::pillThickness,
                                4.0, 400.0));
    s.add(params::floatParam<S>({"pill_edge", "pill edge", "Rim rounding radius (at most half the thickness).",
                                 "shape"},
                                &S::pillEdge, 0.0, 200.0));
    s.add(params::boolParam<S>({"smooth_curvature", "smooth curvature", "Pill, cube and plate: an L4 squircle "
                                "rim, its radius compensated to cut the corner as a round rim of the edge radius "
                                "would; off: round rims.", "shape"},
                               &S::smoothCurvature));
    s.add(params::floatParam<S>({"prism_length", "prism length", "Prism length along x.", "shape"}, &S::prismLength,
                                40.0, 1000.0));
    s.add(params::floatParam<S>({"prism_width", "prism width", "The triangle's base.", "shape"}, &S::prismWidth,
                                20.0, 600.0));
    s.add(params::floatParam<S>({"prism_depth", "prism depth", "Base to apex, toward the camera.", "shape"},
                                &S::prismDepth, 10.0, 600.0));
    s.add(params::floatParam<S>({"cube_size", "cube size", "Cube side.", "shape"}, &S::cubeSize, 20.0, 600.0));
    s.add(params::floatParam<S>({"cube_edge", "cube edge", "Cube rounding radius.", "shape"}, &S::cubeEdge, 0.0,
                                150.0));
    s.add(params::floatParam<S>({"plate_size", "plate size", "Plate side.", "shape"}, &S::plateSize, 40.0, 800.0));
    s.add(params::floatParam<S>({"plate_thickness", "plate thickness", "Uniform plate thickness.", "shape"},
                                &S::plateThickness, 4.0, 200.0));
    s.add(params::floatParam<S>({"plate_edge", "plate edge", "Plate rim rounding.", "shape"}, &S::plateEdge, 0.0,
                                50.0));
    s.add(params::floatParam<S>({"wave_amplitude", "wave amplitude", "Height of the plate's waves.", "shape"},
                                &S::waveAmplitude, 0.0, 80.0));
    s.add(params::floatParam<S>({"wave_length", "wavelength", "Length of the plate's waves.", "shape",
                                 kLogarithmic},
                                &S::waveLength, 50.0, 2000.0));
    // diamond
    s.add(params::floatParam<S>({"diamond_size", "diamond size", "Girdle diameter.", "diamond"}, &S::diamondSize,
                                50.0, 900.0));
    s.add(params::choiceParam<S>({"diamond_view", "view", "top (T), side (S), bottom (B) or a free tumble (F).",
                                  "diamond"},
                                 &S::diamondView, {"top", "side", "bottom", "free"}));
    s.add(params::choiceParam<S>({"diamond_debug", "debug view", "wireframe, facet colours, or TIR (pink: bounce "
                                  "budget spent, orange: exit missed).", "diamond", kTransient},
                                 &S::diamondDebug, {"none", "wireframe", "facets", "tir"}));
    s.add(params::intParam<S>({"bounces", "TIR bounces", "Internal reflections a ray may take before giving up.",
                               "diamond"},
                              &S::bounces, 1, 32));
    // background
    s.add(params::fileParam<S>(
        {"background", "background", "page (text over a photo), photo (R cycles), gradient, checker, or an image "
         "file or folder (also: drop one on the window).", "background"},
        &S::background, {"page", "photo", "gradient", "checker"}));
    s.add(params::boolParam<S>({"environment", "HDR environment", "An HDR panorama for background, refraction and "
                                "reflection.", "background"},
                               &S::environment));
    s.add(params::fileParam<S>(
        {"panorama", "panorama", "photo_studio (built in: a light cyclorama, softboxes and strip lights), a "
         "fetched panorama's name (studio, city, ...) or an equirectangular EXR.",
         "background"},
        &S::panorama, panoramaBuiltIns()));
    s.add(params::floatParam<S>({"exposure", "exposure", "Multiplies the panorama.", "background", kLogarithmic},
                                &S::exposure, 0.05, 8.0));
    s.add(params::floatParam<S>({"env_rotation", "rotation", "Turns the panorama about the vertical, radians.",
                                 "background"},
                                &S::envRotation, -3.14159265, 3.14159265));
    // camera and quality
    s.add(params::choiceParam<S>({"projection", "projection", "Perspective or orthographic.", "camera"},
                                 &S::projection, {"perspective", "orthographic"}));
    s.add(params::floatParam<S>({"fov", "FOV", "Vertical field of view, degrees.", "camera"}, &S::fov, 10.0, 120.0));
    s.add(params::boolParam<S>({"stop_world", "stop the world", "Freeze rotations and waves; the history turns "
                                "into a progressive average.", "camera", kTransient},
                               &S::stopWorld));
    s.add(params::choiceParam<S>({"aa", "AA", "none, FXAA (spatial) or TAA (sub-pixel jitter, reprojection).",
                                  "camera"},
                                 &S::aa, {"none", "fxaa", "taa"}));
    s.add(params::floatParam<S>({"history_alpha", "history alpha", "Weight of the new frame in the running "
                                 "average.", "camera"},
                                &S::historyAlpha, 0.02, 1.0));
    s.add(params::boolParam<S>({"show_proxy", "show proxy", "Tint every proxy fragment pink.", "camera",
                                kTransient},
                               &S::showProxy));

    s.add(params::choiceParam<S>({"pass", "spectral pass", "raster: each instanced proxy's fragments shade the "
                                  "pixels it covers; compute: one compute pass tests each pixel against the "
                                  "instances' screen rectangles (the same picture, ~28x faster on an H100, whose "
                                  "graphics part is two TPCs).", "camera"},
                                 &S::pass, {"raster", "compute"}));

    s.audioMapping("audio.high=spread:1:2.5 curve=log attack=0.02 release=0.4");
    // The original's presets, value for value. A preset sets everything that makes its look, so it
    // gives the same picture whatever was chosen before it (physical optics, Sellmeier, another
    // panorama...): the original's common values (perspective at 45 degrees, exact refraction, jitter
    // on, no AA, history 0.5, the world running), its optics (seed, Cauchy from n_d and V_d), smooth
    // curvature on, and the environment. The backdrop stays the user's, as the original's photo does.
    const params::KeyValues common{{"material", "custom"}, {"fov", "45"}, {"projection", "perspective"},
                                   {"mode", "exact"}, {"jitter", "on"}, {"aa", "none"}, {"history_alpha", "0.5"},
                                   {"stop_world", "off"}, {"show_proxy", "off"}, {"optics", "seed"},
                                   {"dispersion", "abbe"}, {"depth", "400"}, {"smooth_curvature", "on"},
                                   {"diamond_debug", "none"}, {"diamond_view", "free"}, {"bounces", "6"}};
    // Non-diamond presets turn the environment off so the split lands on the backdrop; the studio's
    // values are reset with it, so a later environment=on starts from the lit default.
    const params::KeyValues noEnvironment{{"environment", "off"}, {"panorama", std::string(kStudioPanorama)},
                                          {"exposure", "1"}, {"env_rotation", "0"}};
    auto preset = [&](std::string name, std::string help, params::KeyValues values, bool environment = false) {
      values.insert(values.begin(), common.begin(), common.end());
      if (!environment) values.insert(values.end(), noEnvironment.begin(), noEnvironment.end());
      s.preset({std::move(name), std::move(help), std::move(values)});
    };
    preset("subtle_pill", "Four pills of crown glass, barely dispersing.",
           {{"shape", "pill"}, {"n", "8"}, {"ior", "1.517"}, {"abbe", "6.5"}, {"strength", "0.035"},
            {"pill_length", "400"}, {"pill_height", "115"}, {"pill_thickness", "62"}, {"pill_edge", "100"}});
    preset("prism_rainbow", "Four triangular prisms splitting the photo into bands.",
           {{"shape", "prism"}, {"n", "16"}, {"ior", "1.6"}, {"abbe", "12"}, {"strength", "0.155"},
            {"prism_length", "393"}, {"prism_width", "149"}, {"prism_depth", "117"}});
    preset("rotating_cube", "The opening scene: four tumbling cubes of a strongly dispersing glass.",
           {{"shape", "cube"}, {"n", "16"}, {"ior", "1.272"}, {"abbe", "2"}, {"strength", "0.15"},
            {"cube_size", "230"}, {"cube_edge", "44"}});
    preset("wavy_plate", "Four tumbling plates with waves running through them.",
           {{"shape", "plate"}, {"n", "16"}, {"ior", "1.272"}, {"abbe", "2"}, {"strength", "0.2"},
            {"plate_size", "346"}, {"plate_thickness", "60"}, {"plate_edge", "10.5"}, {"wave_amplitude", "17"},
            {"wave_length", "535"}});
    // The original lit its diamond with a photo studio panorama (exposure 0.75, rotation -1.0995); this
    // one stands in the program's own studio (studio.h), exposure and rotation chosen by looking, and
    // leans its exits not at all (settings.h says why; the original's strength is 0.2).
    preset("diamond", "One round brilliant in a bright photo studio.",
           {{"shape", "diamond"}, {"n", "16"}, {"ior", "2.418"}, {"abbe", "55"},
            {"strength", params::formatFloat(kDiamondStrength)},
            {"diamond_size", "560"}, {"environment", "on"}, {"panorama", std::string(kStudioPanorama)},
            {"exposure", params::formatFloat(kDiamondExposure)},
            {"env_rotation", params::formatFloat(kDiamondRotation)}},
           true);
    addQualityParams<S>(s, "Render scale of the glass and its history, and with jitter on the wavelengths a frame "
                           "traces (medium 3/4, low half, at least 8)", 16.0f);
    return s;
  }();
  return table;
}

constexpr SceneAction kActions[] = {
    {"shuffle", {}, "the shapes to new places (Space)"},
    {"next_photo", {}, "the next photo behind the glass (R)"},
};

constinit const SceneInfo kSceneInfo{"glass", "Spectral Glass", 2, &schema,
    "Drag a shape to move it. Space shuffles them, hold Z for three wavelengths without jitter, T / S / B / F show "
    "the diamond from the top, side, below or tumbling, R shows the next photo; drop an image (or an EXR panorama) on the window.", kActions};

}  // namespace vitrine::glass
