/*{
  "DESCRIPTION": "Vitrine's test generator: one input of every ISF 2 type, each visibly used",
  "CREDIT": "Vitrine tests",
  "ISFVSN": "2.0",
  "VSN": "1.0",
  "CATEGORIES": ["Test", "Generator"],
  "INPUTS": [
    {"NAME": "flash", "TYPE": "event", "LABEL": "Flash"},
    {"NAME": "invert", "TYPE": "bool", "DEFAULT": false},
    {"NAME": "bands", "TYPE": "long", "VALUES": [2, 4, 8], "LABELS": ["two", "four", "eight"], "DEFAULT": 4, "IDENTITY": 2},
    {"NAME": "speed", "TYPE": "float", "MIN": 0.0, "MAX": 4.0, "DEFAULT": 1.0, "IDENTITY": 0.0},
    {"NAME": "centre", "TYPE": "point2D", "DEFAULT": [0.5, 0.5], "MIN": [0, 0], "MAX": [1, 1]},
    {"NAME": "tint", "TYPE": "color", "DEFAULT": [1.0, 0.6, 0.2, 1.0]},
    {"NAME": "photo", "TYPE": "image"},
    {"NAME": "wave", "TYPE": "audio", "MAX": 256},
    {"NAME": "spectrum", "TYPE": "audioFFT", "MAX": 64}
  ]
}*/

void main() {
  vec2 uv = isf_FragNormCoord;
  float ring = length(uv - centre) * float(bands);
  float stripes = 0.5 + 0.5 * sin(6.2831853 * (ring - TIME * speed));
  vec4 picture = IMG_NORM_PIXEL(photo, uv);
  float level = IMG_NORM_PIXEL(spectrum, vec2(uv.x, 0.5)).r;
  float sample = IMG_NORM_PIXEL(wave, vec2(uv.x, 0.5)).r;
  vec3 colour = tint.rgb * stripes + 0.25 * picture.rgb + 0.1 * vec3(level, sample, 0.0);
  if (invert) colour = 1.0 - colour;
  if (flash) colour = vec3(1.0);
  gl_FragColor = vec4(colour, tint.a);
}
