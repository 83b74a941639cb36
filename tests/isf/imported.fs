/*{
  "DESCRIPTION": "An imported picture, tiled and scrolled",
  "ISFVSN": "2",
  "INPUTS": [{"NAME": "tiles", "TYPE": "float", "MIN": 1.0, "MAX": 8.0, "DEFAULT": 3.0}],
  "IMPORTED": {"stamp": {"PATH": "stamp.png"}}
}*/

void main() {
  vec2 uv = fract(isf_FragNormCoord * tiles + vec2(TIME * 0.1, 0.0));
  gl_FragColor = IMG_NORM_PIXEL(stamp, uv) * vec4(vec3(0.5 + 0.5 * float(IMG_SIZE(stamp).x > 0.0)), 1.0);
}
