/*{
  "DESCRIPTION": "A generator with its own vertex shader (inset.vs) that draws its quad at half size in the middle",
  "ISFVSN": "2",
  "INPUTS": [{"NAME": "shade", "TYPE": "color", "DEFAULT": [0.2, 0.8, 0.4, 1.0]}]
}*/

varying vec2 local;

void main() {
  gl_FragColor = vec4(shade.rgb * (0.5 + 0.5 * local.x), 1.0);
}
