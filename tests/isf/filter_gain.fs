/*{
  "DESCRIPTION": "Every colour channel multiplied by a gain; alpha kept",
  "ISFVSN": "2",
  "CATEGORIES": ["Color Adjustment"],
  "INPUTS": [
    {"NAME": "inputImage", "TYPE": "image"},
    {"NAME": "gain", "LABEL": "Gain", "TYPE": "float", "MIN": 0.0, "MAX": 4.0, "DEFAULT": 0.5}
  ]
}*/

void main() {
  vec4 colour = IMG_NORM_PIXEL(inputImage, isf_FragNormCoord.xy);
  gl_FragColor = vec4(colour.rgb * gain, colour.a);
}
