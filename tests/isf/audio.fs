/*{
  "DESCRIPTION": "Draws the sound: the wave as a line, the spectrum as bars",
  "ISFVSN": "2",
  "INPUTS": [
    {"NAME": "wave", "TYPE": "audio", "MAX": 512},
    {"NAME": "fft", "TYPE": "audioFFT", "MAX": 32},
    {"NAME": "gain", "TYPE": "float", "MIN": 0.1, "MAX": 10.0, "DEFAULT": 1.0}
  ]
}*/

void main() {
  vec2 uv = isf_FragNormCoord;
  float w = IMG_NORM_PIXEL(wave, vec2(uv.x, 0.5)).r;
  float line = smoothstep(0.01, 0.0, abs(uv.y - w));
  float bar = step(uv.y, IMG_NORM_PIXEL(fft, vec2(floor(uv.x * 32.0) / 32.0, 0.5)).r * gain);
  gl_FragColor = vec4(line, bar * 0.6, bar, 1.0);
}
