/*{
  "DESCRIPTION": "Written as for GLES 2: a moving dot leaves a trail in an 8-bit persistent buffer read with texture2D",
  "ISFVSN": "2",
  "INPUTS": [{"NAME": "fade", "TYPE": "float", "MIN": 0.5, "MAX": 0.99, "DEFAULT": 0.9}],
  "PASSES": [{"TARGET": "trail", "PERSISTENT": true}, {}]
}*/
#ifdef GL_ES
precision mediump float;
#endif

void main() {
  if (PASSINDEX == 0) {
    vec2 spot = vec2(0.5 + 0.35 * cos(TIME * 3.0), 0.5 + 0.35 * sin(TIME * 3.0));
    float lit = step(length(isf_FragNormCoord - spot), 0.05);
    gl_FragColor = max(texture2D(trail, isf_FragNormCoord) * fade, vec4(lit));
  } else {
    gl_FragColor = vec4(texture2D(trail, isf_FragNormCoord).rgb * vec3(1.0, 0.7, 0.3), 1.0);
  }
}
