/*{
  "DESCRIPTION": "Three passes: a half-size blur buffer, a float accumulator that persists, and the output",
  "ISFVSN": "2.0",
  "INPUTS": [
    {"NAME": "blurAmount", "TYPE": "float", "MIN": 0.0, "MAX": 64.0, "DEFAULT": 12.0},
    {"NAME": "decay", "TYPE": "float", "MIN": 0.0, "MAX": 1.0, "DEFAULT": 0.95}
  ],
  "PASSES": [
    {"TARGET": "small", "WIDTH": "$WIDTH/2.0", "HEIGHT": "floor($HEIGHT*0.5)+1"},
    {"TARGET": "trail", "PERSISTENT": true, "FLOAT": true, "WIDTH": "max($WIDTH,$blurAmount*10)", "HEIGHT": "$HEIGHT"},
    {}
  ]
}*/

void main() {
  vec2 uv = isf_FragNormCoord;
  if (PASSINDEX == 0) {
    float spot = smoothstep(0.2, 0.0, length(uv - vec2(0.5 + 0.3 * sin(TIME), 0.5)));
    gl_FragColor = vec4(spot, spot * 0.5, 1.0 - spot, 1.0);
  } else if (PASSINDEX == 1) {
    vec2 texel = 1.0 / IMG_SIZE(small);
    vec4 blurred = (IMG_NORM_PIXEL(small, uv + texel * blurAmount) + IMG_NORM_PIXEL(small, uv - texel * blurAmount)) * 0.5;
    gl_FragColor = max(blurred, IMG_THIS_NORM_PIXEL(trail) * decay);
  } else {
    gl_FragColor = IMG_NORM_PIXEL(trail, uv) + 0.1 * IMG_PIXEL(small, gl_FragCoord.xy * 0.5);
  }
}
