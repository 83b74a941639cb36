/*{
  "DESCRIPTION": "Fragment work only, for speed: a value-noise field warped twice (five fbm of six octaves a pixel), drawn by the ISF runner and by its native twin, shaders/test/speed_twin.frag",
  "ISFVSN": "2.0",
  "INPUTS": [
    {"NAME": "zoom", "TYPE": "float", "MIN": 0.5, "MAX": 8.0, "DEFAULT": 3.0}
  ]
}*/

float lattice(vec2 cell) {
  uvec2 p = uvec2(ivec2(cell) + 4096);
  uint h = p.x * 1664525u + p.y * 1013904223u;
  h ^= h >> 16;
  h *= 747796405u;
  h ^= h >> 13;
  return float(h & 65535u) / 65535.0;
}

float noise(vec2 p) {
  vec2 cell = floor(p), f = fract(p);
  vec2 u = f * f * (3.0 - 2.0 * f);
  return mix(mix(lattice(cell), lattice(cell + vec2(1.0, 0.0)), u.x),
             mix(lattice(cell + vec2(0.0, 1.0)), lattice(cell + vec2(1.0, 1.0)), u.x), u.y);
}

float fbm(vec2 p) {
  float sum = 0.0, amplitude = 0.5;
  for (int octave = 0; octave < 6; ++octave) {
    sum += amplitude * noise(p);
    p = p * 2.03 + vec2(1.7, 9.2);
    amplitude *= 0.5;
  }
  return sum;
}

void main() {
  vec2 p = isf_FragNormCoord * vec2(RENDERSIZE.x / RENDERSIZE.y, 1.0) * zoom;
  vec2 q = vec2(fbm(p + 0.1 * TIME), fbm(p + vec2(5.2, 1.3)));
  vec2 r = vec2(fbm(p + 4.0 * q + vec2(1.7, 9.2)), fbm(p + 4.0 * q + vec2(8.3, 2.8)));
  float f = fbm(p + 4.0 * r);
  vec3 colour = mix(vec3(0.10, 0.20, 0.40), vec3(0.90, 0.60, 0.30), f);
  colour = mix(colour, vec3(0.20, 0.70, 0.60), 0.5 * length(q));
  gl_FragColor = vec4(colour, 1.0);
}
