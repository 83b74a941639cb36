/*{
  "DESCRIPTION": "A wipe with a soft edge from the start picture to the end picture",
  "ISFVSN": "2",
  "CATEGORIES": ["Transition"],
  "INPUTS": [
    {"NAME": "startImage", "TYPE": "image"},
    {"NAME": "endImage", "TYPE": "image"},
    {"NAME": "progress", "TYPE": "float", "MIN": 0.0, "MAX": 1.0, "DEFAULT": 0.0},
    {"NAME": "softness", "TYPE": "float", "MIN": 0.0, "MAX": 0.5, "DEFAULT": 0.1}
  ]
}*/

void main() {
  float edge = mix(-softness, 1.0 + softness, progress);
  float t = smoothstep(edge - softness, edge + softness, isf_FragNormCoord.x);
  gl_FragColor = mix(IMG_THIS_PIXEL(endImage), IMG_THIS_PIXEL(startImage), t);
}
