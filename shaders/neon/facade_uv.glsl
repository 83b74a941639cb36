// Texture coordinates for the facade's lighting texture, projected along the dominant axis of the
// normal (the seed's trick: the building needs no authored UVs). Mirrors facadeUv in
// src/scenes/neon/facade.h, whose tests check the axis each normal picks.
#ifndef NEON_FACADE_UV_GLSL
#define NEON_FACADE_UV_GLSL

// The world box mapped onto the texture, metres: the facade's width and height, and the ground's depth
// from behind the building to past the camera. Matches kFacadeUvMin / kFacadeUvMax in facade.h.
const vec3 kFacadeUvMin = vec3(-10.0, 0.0, -10.0);
const vec3 kFacadeUvMax = vec3(10.0, 20.0, 40.0);

// 1 when a > b, else 0, with no branch (the seed's when_gt; a tie gives 0).
float whenGt(float a, float b) { return 1.0 - step(a, b); }

// `range` is the seed's (start, end): where the box's two edges land in texture space, (0, 1) for once
// across. The texture is upright: its top row lights the top of the building.
vec2 facadeUv(vec3 worldPos, vec3 normal, vec2 range) {
  vec3 t = (worldPos - kFacadeUvMin) / (kFacadeUvMax - kFacadeUvMin);
  t.y = 1.0 - t.y;
  const vec3 s = mix(vec3(range.x), vec3(range.y), t);
  const vec3 a = abs(normal);  // no normalize: comparing magnitudes does not need unit length
  // Start from the sides (normal along x), switch to the top view when y dominates, then to the front
  // when z does; exactly one switch can fire for a normal with one largest component.
  vec2 uv = mix(s.zy, s.xz, min(whenGt(a.y, a.x), whenGt(a.y, a.z)));
  uv = mix(uv, s.xy, min(whenGt(a.z, a.x), whenGt(a.z, a.y)));
  return uv;
}

// The ground's own light: wet asphalt, the storefront's warm spill falling off away from the foot
// (groundLight in facade.h). Faces facing up below kGroundTop are ground.
const float kGroundTop = 0.2;
vec3 groundLight(vec3 worldPos) {
  const vec3 sky = vec3(0.010, 0.012, 0.022);
  const vec3 spill = vec3(0.26, 0.13, 0.05);
  const float across = worldPos.x / 8.0;
  const float away = max(worldPos.z, 0.0) / 3.0;  // metres in front of the facade, in falloffs
  return sky + spill * exp(-across * across - away);
}

#endif
