/*{
  "DESCRIPTION": "A filter with its own vertex shader (rotate.vs) that turns the picture's coordinates",
  "ISFVSN": "2",
  "INPUTS": [
    {"NAME": "inputImage", "TYPE": "image"},
    {"NAME": "angle", "TYPE": "float", "MIN": -3.1416, "MAX": 3.1416, "DEFAULT": 0.3}
  ]
}*/

#if __VERSION__ <= 120
varying vec2 turned;
varying vec2 neighbours[2];
#else
in vec2 turned;
in vec2 neighbours[2];
#endif

void main() {
  if (any(lessThan(turned, vec2(0.0))) || any(greaterThan(turned, vec2(1.0)))) {
    gl_FragColor = vec4(0.0);
    return;
  }
  gl_FragColor = (IMG_NORM_PIXEL(inputImage, turned) * 2.0 + IMG_NORM_PIXEL(inputImage, neighbours[0]) +
                  IMG_NORM_PIXEL(inputImage, neighbours[1])) * 0.25;
}
