// The fixed camera of the bloom chamber; mirrors cameraRay in src/scenes/bloom/bloom_math.h.
const vec3 kEye = vec3(0.0, 0.2, 3.0);
const float kFieldOfViewY = 0.75;

vec3 cameraDirection(vec2 uv, float aspect) {  // uv: 0..1, origin top-left
  const vec3 forward = normalize(-kEye);
  const vec3 right = normalize(cross(forward, vec3(0.0, 1.0, 0.0)));
  const vec3 up = cross(right, forward);
  const float h = tan(kFieldOfViewY * 0.5);
  return normalize(forward + right * ((uv.x * 2.0 - 1.0) * h * aspect) + up * ((1.0 - uv.y * 2.0) * h));
}
