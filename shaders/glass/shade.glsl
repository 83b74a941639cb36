// The spectral work, only where a proxy covers the screen: the primary ray meets the glass (sphere
// trace, analytic for the diamond), and each of N stratified wavelengths refracts in with its own IOR,
// finds its own exit (or the hero wavelength's, in approx mode; the diamond walks its TIR bounce
// chain), refracts out and fetches what it sees. Each wavelength's fetch is weighted by the sRGB
// colour of its CIE matching functions and the sums are normalised per channel, so glass that does
// not disperse passes the background through unchanged.
#ifndef GLASS_SHADE_GLSL
#define GLASS_SHADE_GLSL
#include "common/hash.glsl"
#include "glass/instance.glsl"
#include "glass/optics.glsl"

layout(set = 0, binding = 1) uniform sampler2D backdrop;
layout(set = 0, binding = 2) uniform sampler2D panorama;


// GlassFrame::diamondDebug
const int DIAMOND_DEBUG_WIREFRAME = 1;
const int DIAMOND_DEBUG_FACETS = 2;
const int DIAMOND_DEBUG_TIR = 3;

// The frame's options, fixed per pipeline (frame_block.h's GLASS_SHADE_* bits, from F's optics,
// environment, approxExits and sellmeier): only the paths they choose are compiled.
layout(constant_id = 1) const uint GLASS_SHADE_OPTIONS = 0u;
bool shadeOption(uint bit) { return (GLASS_SHADE_OPTIONS & bit) != 0u; }
bool physical() { return shadeOption(GLASS_SHADE_PHYSICAL); }

float iorAt(float lambda) {
  if (shadeOption(GLASS_SHADE_SELLMEIER)) return sellmeierIor(lambda, F.sellmeierB, F.sellmeierC);
  return cauchyIor(lambda, F.ior, F.abbe);
}

// What a ray leaving the glass at world point o along world direction d sees.
vec3 sceneAlong(vec3 o, vec3 d, float lod) {
  if (shadeOption(GLASS_SHADE_ENVIRONMENT)) return textureLod(panorama, equirectUv(d), 0.0).rgb * F.exposure;
  // The photo hangs `depth` behind the glass, screen-aligned: a ray that does not bend lands on the
  // texel of its own pixel. Rays heading back toward the camera see its mirror image.
  d.z = -max(abs(d.z), 1e-3);
  float t = (-F.photoDepth - o.z) / d.z;
  vec2 pixel = worldToPixel(o + d * t);
  return textureLod(backdrop, pixel / F.viewPixels, lod).rgb;
}

// The seed's exit: the refracted direction leaned back toward the view ray by `strength`.
vec3 seen(vec3 view, vec3 exitDir) { return physical() ? exitDir : normalize(mix(view, exitDir, F.strength)); }

// The original's LOD: grazing-angle minification plus the turn of a rounded rim's normal.
float exitLod(float cosT, vec3 normal) {
  float rim = (GLASS_SHAPE == SHAPE_CUBE || GLASS_SHAPE == SHAPE_PLATE)
                  ? (1.0 - max(max(abs(normal.x), abs(normal.y)), abs(normal.z))) * 8.0 : 0.0;
  return clamp(-log2(max(cosT, 1e-4)) - 1.0 + rim, 0.0, 6.0);
}

struct Shaded {
  vec3 colour;
  vec2 motion;         // pixels from here to where this surface point was last frame
  float eyeDistance;   // to the front hit: overlapping instances sort by it
};

// Where one pixel's ray first meets one instance's glass, before any wavelength: enough to tell which
// of several instances a pixel sees, so the compute path shades only that one (glassFrontHit, then
// shadeFrontHit). On lavapipe, which runs a branch's code for every lane whatever the branch decides,
// shading each candidate instance cost the whole shading four times over for every pixel.
struct FrontHit {
  vec3 rayOrigin, rayDir;  // the primary ray, world space
  vec3 rd;                 // its direction in object space
  vec3 p1, n1;             // the hit and the outward normal there, object space
  int facet;               // the diamond's facet hit (-1 for the other shapes)
  float eyeDistance;       // from the ray's origin: overlapping instances sort by it
};

// The pixel's primary ray, world space, with the frame's sub-pixel offset under TAA (undone by the
// resolve's reprojection): the same for every instance.
void glassPrimaryRay(vec2 fragCoord, out vec3 origin, out vec3 dir) {
  const uvec2 pixel = uvec2(fragCoord);
  vec2 sub = fragCoord;
  if (F.taa != 0u) sub += vec2(hash01(uvec3(pixel, F.frame * 2u)), hash01(uvec3(pixel, F.frame * 2u + 1u))) - 0.5;
  primaryRay(sub, origin, dir);
}

// False when the pixel's ray misses the instance's glass.
bool glassFrontHit(vec3 rayOrigin, vec3 rayDir, int instance, out FrontHit hit) {
  const mat3 toObject = mat3(F.rotation);
  const vec3 centre = vec3(F.instances[instance].centre, 0.0);
  hit.rayOrigin = rayOrigin;
  hit.rayDir = rayDir;
  const vec3 ro = toObject * (rayOrigin - centre);
  hit.rd = toObject * rayDir;
  float tHit;
  if (!shapeEnter(glassDims(), ro, hit.rd, tHit, hit.n1, hit.facet)) return false;
  hit.p1 = ro + hit.rd * tHit;
  hit.eyeDistance = distance(rayOrigin, centre + transpose(toObject) * hit.p1);
  return true;
}

// The pixel's colour and motion through the instance it meets at `hit`.
Shaded shadeFrontHit(vec2 fragCoord, int instance, FrontHit hit) {
  const GlassShapeDims dims = glassDims();
  const mat3 toWorld = transpose(mat3(F.rotation));
  const vec3 centre = vec3(F.instances[instance].centre, 0.0);
  const uvec2 pixel = uvec2(fragCoord);
  const vec3 rayOrigin = hit.rayOrigin, rayDir = hit.rayDir, rd = hit.rd, p1 = hit.p1, n1 = hit.n1;
  const int facet = hit.facet;
  const vec3 hitWorld = centre + toWorld * p1;
  Shaded shaded;
  shaded.eyeDistance = hit.eyeDistance;

  // Where this surface point was a frame ago: last frame's rotation and centre.
  const vec3 previousWorld = vec3(F.instances[instance].previousCentre, 0.0) + transpose(mat3(F.previousRotation)) * p1;
  shaded.motion = worldToPixel(previousWorld) - worldToPixel(hitWorld);

  if (GLASS_SHAPE == SHAPE_DIAMOND && F.diamondDebug == DIAMOND_DEBUG_FACETS) {
    shaded.colour = facetColour(facet);
    return shaded;
  }

  const int n = F.wavelengths;
  const bool approx = shadeOption(GLASS_SHADE_APPROX);
  const float phase = spectralPhase(pixel, F.frame, F.seed, F.jitter != 0u);
  const float cosI = -dot(rd, n1);
  const vec3 reflected = toWorld * reflectDir(rd, n1);

  // Approx: one back exit, found at the frame's hero wavelength, shared by every wavelength.
  vec3 heroPoint = vec3(0.0), heroNormal = vec3(0.0);
  bool heroExit = false;
  if (approx) {
    bool ok;
    float t;
    int exitFacet;
    const vec3 heroDir = refractDir(rd, n1, iorAt(F.heroLambda), ok);
    heroExit = ok && shapeExit(dims, p1, heroDir, t, heroNormal, exitFacet);
    heroPoint = p1 + heroDir * t;
  }

  // The front surface's reflection is the same for every wavelength; only its Fresnel weight differs.
  const vec3 reflection = sceneAlong(hitWorld, reflected, 0.0);
  // Exact mode's exits stay reuseExit across wavelengths: each wavelength first tries the previous
  // one's exit plane, exact on a flat face and accepted only if it lands on the surface; a rim or a
  // wave sends it to the full exit search.
  vec3 previousPoint = vec3(0.0), previousNormal = vec3(0.0);
  bool reuseExit = false;
  const float onSurface = 1e-3 * shapeScale(dims);

  // The diamond's wavelengths mostly leave by the same facets: each walk tries the last one's route first.
  uvec2 route = NO_ROUTE;

  vec3 sum = vec3(0.0), weights = vec3(0.0);
  bool exhausted = false, missed = false;
  for (int i = 0; i < n; ++i) {
    const float lambda = stratifiedLambda(i, n, phase);
    const float eta = iorAt(lambda);
    const vec3 w = spectralWeight(lambda);
    const float fresnel = physical() ? fresnelDielectric(cosI, eta) : fresnelSchlick(cosI, eta);
    bool ok;
    const vec3 inside = refractDir(rd, n1, eta, ok);
    vec3 transmitted = reflection;  // a ray that cannot enter (never for eta > 1) shows the reflection

    if (ok && GLASS_SHAPE == SHAPE_DIAMOND && !approx) {
      DiamondWalk walk = diamondWalkStart(p1, inside, 1.0, F.bounces, route);
      vec3 exitDir;
      float exitWeight;
      vec3 light = vec3(0.0);
      float emitted = 0.0;
      while (diamondStep(walk, eta, physical(), exitDir, exitWeight)) {
        if (exitWeight == 0.0) continue;  // total internal reflection: nothing leaves, nothing to look up
        light += exitWeight * sceneAlong(centre + toWorld * walk.p, seen(rayDir, toWorld * exitDir), 0.0);
        emitted += exitWeight;
      }
      route = walk.route;
      exhausted = exhausted || walk.status == WALK_EXHAUSTED;
      missed = missed || walk.status == WALK_MISSED;
      // Light still trapped when the budget runs out leaves along its last direction, split by
      // wavelength like any exit (the original showed the front reflection there, the same for
      // every wavelength: grey patches where a diamond's light should still be coloured).
      float trapped = max(1.0 - emitted, 0.0);
      if (trapped > 0.0) light += trapped * sceneAlong(centre + toWorld * walk.p, seen(rayDir, toWorld * walk.d), 0.0);
      transmitted = light;
    } else if (ok) {
      float t;
      vec3 n2;
      int exitFacet;
      vec3 p2;
      bool found;
      if (approx) {
        found = heroExit;
        p2 = heroPoint;
        n2 = heroNormal;
      } else {
        found = false;
        const float facing = dot(inside, previousNormal);
        if (reuseExit && facing > 1e-3) {
          p2 = p1 + inside * (dot(previousNormal, previousPoint - p1) / facing);
          n2 = previousNormal;
          found = abs(shapeSdf(dims, p2)) < onSurface;
        }
        if (!found) {
          found = shapeExit(dims, p1, inside, t, n2, exitFacet);
          p2 = p1 + inside * t;
          reuseExit = found;
          previousPoint = p2;
          previousNormal = n2;
        }
      }
      if (found) {
        bool leaves;
        const vec3 outside = refractDir(inside, -n2, 1.0 / eta, leaves);
        const float cosT = dot(inside, n2);
        if (leaves) {
          const vec3 exitWorld = centre + toWorld * p2;
          vec3 through = sceneAlong(exitWorld, seen(rayDir, toWorld * outside), exitLod(abs(dot(outside, n2)), n2));
          if (physical()) {  // the back face reflects its share inward; it leaves roughly along the mirror
            const float back = fresnelDielectric(cosT, 1.0 / eta);
            through = mix(through, sceneAlong(exitWorld, toWorld * reflectDir(inside, -n2), 2.0), back);
          }
          transmitted = through;
        } else if (physical()) {  // total internal reflection at the back: it leaves by the mirror path
          transmitted = sceneAlong(centre + toWorld * p2, toWorld * reflectDir(inside, -n2), 2.0);
        }  // the seed's TIR fallback: the external reflection
      } else {
        missed = true;
      }
    }
    sum += w * mix(transmitted, reflection, fresnel);
    weights += w;
  }
  vec3 result = sum / max(weights, vec3(1e-6));

  // Facet edges about a pixel and a half wide.
  if (GLASS_SHAPE == SHAPE_DIAMOND && F.diamondDebug == DIAMOND_DEBUG_WIREFRAME) {
    const float worldPerPixel = F.viewWorld.x / F.viewPixels.x;
    result = mix(result, vec3(1.0), 1.0 - smoothstep(0.5, 1.5, diamondEdgeDistance(p1) / worldPerPixel));
  }
  if (GLASS_SHAPE == SHAPE_DIAMOND && F.diamondDebug == DIAMOND_DEBUG_TIR) {
    if (missed) result = vec3(1.0, 0.55, 0.0);
    else if (exhausted) result = vec3(1.0, 0.3, 0.75);
  }
  shaded.colour = result;
  return shaded;
}

// One pixel through one instance (the render-pass path, whose fragments each know theirs); false when
// its ray misses the glass.
bool shadeGlass(vec2 fragCoord, int instance, out Shaded shaded) {
  vec3 origin, dir;
  glassPrimaryRay(fragCoord, origin, dir);
  FrontHit hit;
  if (!glassFrontHit(origin, dir, instance, hit)) return false;
  shaded = shadeFrontHit(fragCoord, instance, hit);
  return true;
}

#endif
