#include "scenes/neon/settings.h"

namespace vitrine::neon {
namespace {
constexpr int kFewestChains = 16;  // the chains parameter's minimum
}

const params::Schema& schema() {
  using S = Settings;
  using params::kLogarithmic, params::kRebuilds, params::kTransient;
  static const params::Schema table = [] {
    auto s = params::Schema::forStruct<S>();
    s.add(params::intParam<S>({"chains", "chains", "Tubes alive at once at most.", "tubes", kRebuilds | kLogarithmic},
                              &S::chains, kFewestChains, 16384));
    s.add(params::intParam<S>({"particles", "particles per chain", "Particles in each tube's chain.", "tubes",
                               kRebuilds},
                              &S::particles, 4, 64));
    s.add(params::floatParam<S>({"decay", "decay", "Life lost per second once a tube is alive.", "tubes",
                                 kLogarithmic},
                                &S::decay, 0.02, 4.0));
    s.add(params::floatParam<S>({"lerp", "follower lerp", "Share of the gap to the particle ahead that each "
                                 "particle closes in 1/60 s (the same tube at any step rate).", "tubes"},
                                &S::lerp, 0.01, 1.0));
    s.add(params::floatParam<S>({"field_strength", "field strength", "Speed of the curl-noise flow the heads ride, "
                                 "m/s.", "tubes"},
                                &S::fieldStrength, 0.0, 10.0));
    s.add(params::floatParam<S>({"field_scale", "field scale", "Noise cells per metre: larger makes tighter "
                                 "swirls.", "tubes", kLogarithmic},
                                &S::fieldScale, 0.01, 2.0));
    s.add(params::floatParam<S>({"radius", "tube radius", "Radius of the glass tube, m.",
                                 "tubes"},
                                &S::radius, 0.005, 0.5));
    s.add(params::colourParam<S>({"colour_a", "colour A", "One of the three neon colours a tube is lit in.", "tubes"}, &S::colourA));
    s.add(params::colourParam<S>({"colour_b", "colour B", "Another of the tubes' three colours.", "tubes"},
                                 &S::colourB));
    s.add(params::colourParam<S>({"colour_c", "colour C", "The third.", "tubes"}, &S::colourC));
    s.add(params::floatParam<S>({"glow", "glow", "Emissive intensity of the gas.", "tubes", kLogarithmic},
                                &S::glow, 0.1, 50.0));
    s.add(params::floatParam<S>({"autopilot_idle", "autopilot after", "Seconds without input before the "
                                 "autopilot plays; input takes over at once.", "input"},
                                &S::autopilotIdle, 0.0, 60.0));
    s.add(params::floatParam<S>({"autopilot_rate", "autopilot rate", "Heads the autopilot releases per second.",
                                 "input", kLogarithmic},
                                &S::autopilotRate, 0.2, 5000.0));
    s.add(params::floatParam<S>({"bloom_strength", "bloom strength", "How much of the blurred tubes is added "
                                 "back.", "look"},
                                &S::bloomStrength, 0.0, 4.0));
    s.add(params::floatParam<S>({"bloom_radius", "bloom radius", "Spread of the upsampling tent.", "look"},
                                &S::bloomRadius, 0.2, 3.0));
    s.add(params::floatParam<S>({"focal_distance", "focal distance", "Distance in focus, m from the camera.",
                                 "look", kLogarithmic},
                                &S::focalDistance, 1.0, 100.0));
    s.add(params::floatParam<S>({"aperture", "aperture", "Circle-of-confusion scale: 0 keeps all in focus.",
                                 "look"},
                                &S::aperture, 0.0, 4.0));
    s.add(params::colourParam<S>({"tint_a", "tint A", "One colour of the noise-driven tint.", "look"}, &S::tintA));
    s.add(params::colourParam<S>({"tint_b", "tint B", "The other.", "look"}, &S::tintB));
    s.add(params::floatParam<S>({"tint_strength", "tint strength", "How much of the linear-burn tint is mixed "
                                 "in.", "look"},
                                &S::tintStrength, 0.0, 1.0));
    s.add(params::floatParam<S>({"vignette", "vignette", "Darkening toward the corners.", "look"}, &S::vignette,
                                0.0, 1.0));
    s.add(params::floatParam<S>({"grain", "grain", "Film grain.", "look"}, &S::grain, 0.0, 0.3));
    s.add(params::floatParam<S>({"aberration", "aberration", "RGB shift at the corners, pixels.", "look"},
                                &S::aberration, 0.0, 8.0));
    s.add(params::floatParam<S>({"mirror", "mirror", "Strength of the ground's reflection.", "look"}, &S::mirror,
                                0.0, 1.0));
    s.add(params::floatParam<S>({"distortion", "mirror distortion", "How far the ground's normal map bends the "
                                 "reflection.", "look"},
                                &S::distortion, 0.0, 2.0));
    s.add(params::choiceParam<S>({"stage", "stage", "Show the frame after this stage: base, tubes, bloom, dof, "
                                  "tint, final.", "look", kTransient},
                                 &S::stage, {"base", "tubes", "bloom", "dof", "tint", "final"}));
    s.audioMapping("audio.beat=burst");
    s.audioMapping("audio.level=glow:2:4.5 curve=log attack=0.02 release=0.4");
    s.preset({"dense", "Many tubes at once, each distinct: the autopilot releasing four a second into 256 chains.",
              {{"chains", "256"}, {"autopilot_rate", "4"}}});
    s.preset({"clean", "No post effects: the tubes and their bloom.",
              {{"aperture", "0"}, {"tint_strength", "0"}, {"vignette", "0"}, {"grain", "0"}, {"aberration", "0"}}});
    addQualityParams<S>(s, "Render scale of the facade, tubes and post passes; medium takes 3/4 of the chains, low half "
                           "of them and half the depth of field's taps", 16.0f);
    return s;
  }();
  return table;
}

int tierChains(int chains, Tier tier) { return tierCount(chains, tier, kFewestChains); }
float tierRenderScale(Tier tier) { return tier == Tier::Low ? 0.4f : tierScale(tier); }

constexpr std::string_view kReleaseArgs[] = {"x", "y", "z"};
constexpr SceneAction kActions[] = {
    {"release", kReleaseArgs, "a tube head released at (x, y, z) metres: x across, y up from the floor, z depth"},
    {"burst", {}, "a tube from each of the autopilot's pens at once, where they are now (a beat, with live audio)"},
};

constinit const SceneInfo kSceneInfo{"neon", "Neon", 3, &schema,
    "Drag to draw a neon tube along the cursor's path; leave it alone and the autopilot plays.", kActions};

}  // namespace vitrine::neon
