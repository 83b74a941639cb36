#if __VERSION__ <= 120
varying vec2 turned;
varying vec2 neighbours[2];
#else
out vec2 turned;
out vec2 neighbours[2];
#endif

void main() {
  isf_vertShaderInit();
  vec2 centred = (isf_FragNormCoord - 0.5) * RENDERSIZE;
  float c = cos(angle), s = sin(angle);
  turned = vec2(c * centred.x - s * centred.y, s * centred.x + c * centred.y) / RENDERSIZE + 0.5;
  vec2 step = vec2(1.0 / RENDERSIZE.x, 0.0);
  neighbours[0] = turned - step;
  neighbours[1] = turned + step;
}
