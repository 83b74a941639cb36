varying vec2 local;

void main() {
  isf_vertShaderInit();
  local = isf_FragNormCoord;
  gl_Position.xy *= 0.5;
}
