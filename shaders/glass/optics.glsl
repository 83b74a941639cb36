// The glass scene's optics; mirrors src/scenes/glass/optics.h function for function.
#ifndef GLASS_OPTICS_GLSL
#define GLASS_OPTICS_GLSL

// Snell's law, eta = n_t / n_i, n facing against d. ok = false at total internal reflection.
vec3 refractDir(vec3 d, vec3 n, float eta, out bool ok) {
  float cosI = -dot(d, n);
  float k = 1.0 - (1.0 - cosI * cosI) / (eta * eta);
  ok = k >= 0.0;
  return ok ? normalize(d / eta + (cosI / eta - sqrt(k)) * n) : vec3(0.0);
}

vec3 reflectDir(vec3 d, vec3 n) { return d - 2.0 * dot(d, n) * n; }

float fresnelSchlick(float cosI, float eta) {
  float r0 = (eta - 1.0) / (eta + 1.0);
  float f0 = r0 * r0;
  float m = 1.0 - clamp(cosI, 0.0, 1.0);
  return f0 + (1.0 - f0) * m * m * m * m * m;
}

float fresnelDielectric(float cosI, float eta) {
  cosI = clamp(cosI, 0.0, 1.0);
  float sinT2 = (1.0 - cosI * cosI) / (eta * eta);
  if (sinT2 >= 1.0) return 1.0;
  float cosT = sqrt(1.0 - sinT2);
  float rs = (cosI - eta * cosT) / (cosI + eta * cosT);
  float rp = (eta * cosI - cosT) / (eta * cosI + cosT);
  return 0.5 * (rs * rs + rp * rp);
}

#endif
