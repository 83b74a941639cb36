/*{
  "DESCRIPTION": "A straight mix from the start picture to the end picture, with an optional dip through a colour",
  "ISFVSN": "2",
  "CATEGORIES": ["Transition"],
  "INPUTS": [
    {"NAME": "startImage", "TYPE": "image"},
    {"NAME": "endImage", "TYPE": "image"},
    {"NAME": "progress", "TYPE": "float", "MIN": 0.0, "MAX": 1.0, "DEFAULT": 0.0},
    {"NAME": "dip", "LABEL": "Dip", "TYPE": "float", "MIN": 0.0, "MAX": 1.0, "DEFAULT": 0.0},
    {"NAME": "dipColour", "LABEL": "Dip colour", "TYPE": "color", "DEFAULT": [0.0, 0.0, 0.0, 1.0]}
  ]
}*/

void main() {
  vec4 from = IMG_THIS_NORM_PIXEL(startImage);
  vec4 to = IMG_THIS_NORM_PIXEL(endImage);
  // The dip's weight peaks half-way and is nothing at either end, so progress 0 and 1 are the pictures.
  float through = dip * (1.0 - abs(2.0 * progress - 1.0));
  gl_FragColor = mix(mix(from, to, progress), dipColour, through);
}
