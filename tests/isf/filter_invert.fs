/*{
  "DESCRIPTION": "Each colour channel turned over, 1 - x, by an amount; alpha kept",
  "ISFVSN": "2",
  "CATEGORIES": ["Color Effect"],
  "INPUTS": [
    {"NAME": "inputImage", "TYPE": "image"},
    {"NAME": "amount", "LABEL": "Amount", "TYPE": "float", "MIN": 0.0, "MAX": 1.0, "DEFAULT": 1.0}
  ]
}*/

void main() {
  vec4 colour = IMG_THIS_PIXEL(inputImage);
  gl_FragColor = vec4(mix(colour.rgb, 1.0 - colour.rgb, amount), colour.a);
}
