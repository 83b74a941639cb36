/*{
  "DESCRIPTION": "The lower half of the picture stretched over all of it: which way is up, made visible",
  "ISFVSN": "2",
  "CATEGORIES": ["Distortion Effect"],
  "INPUTS": [
    {"NAME": "inputImage", "TYPE": "image"}
  ]
}*/

void main() {
  // ISF's y grows upwards: y = 0 is the picture's bottom row, 0.5 its middle.
  gl_FragColor = IMG_NORM_PIXEL(inputImage, vec2(isf_FragNormCoord.x, isf_FragNormCoord.y * 0.5));
}
