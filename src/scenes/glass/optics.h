#pragma once
// The glass scene's optics in plain C++: what the unit tests check and shaders/glass/optics.glsl
// mirrors function for function. Wavelengths are in nanometres; eta is always n_transmitted / n_incident.
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <optional>

namespace vitrine::glass {

// Snell's law for a unit direction d meeting a surface whose unit normal n faces against d
// (dot(d, n) < 0), going from index n_i into n_t with eta = n_t / n_i. None at total internal reflection.
inline std::optional<glm::vec3> refractDir(glm::vec3 d, glm::vec3 n, float eta) {
  const float cosI = -glm::dot(d, n);
  const float k = 1.0f - (1.0f - cosI * cosI) / (eta * eta);
  if (k < 0.0f) return std::nullopt;
  return glm::normalize(d / eta + (cosI / eta - std::sqrt(k)) * n);
}

inline glm::vec3 reflectDir(glm::vec3 d, glm::vec3 n) { return d - 2.0f * glm::dot(d, n) * n; }

// Schlick's approximation of the reflectance at an interface (the original's per-wavelength Fresnel).
// cosI: cosine of the angle of incidence on the incident side.
inline float fresnelSchlick(float cosI, float eta) {
  const float r0 = (eta - 1.0f) / (eta + 1.0f);
  const float f0 = r0 * r0;
  const float m = 1.0f - glm::clamp(cosI, 0.0f, 1.0f);
  return f0 + (1.0f - f0) * m * m * m * m * m;
}

// The exact unpolarised dielectric reflectance (mean of s and p), 1 at total internal reflection.
inline float fresnelDielectric(float cosI, float eta) {
  cosI = glm::clamp(cosI, 0.0f, 1.0f);
  const float sinT2 = (1.0f - cosI * cosI) / (eta * eta);
  if (sinT2 >= 1.0f) return 1.0f;
  const float cosT = std::sqrt(1.0f - sinT2);
  const float rs = (cosI - eta * cosT) / (cosI + eta * cosT);
  const float rp = (eta * cosI - cosT) / (eta * cosI + cosT);
  return 0.5f * (rs * rs + rp * rp);
}

}  // namespace vitrine::glass
