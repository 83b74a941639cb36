/*{
  "DESCRIPTION": "A bright spot where the file's only point2D is: the cursor's drag moves it",
  "ISFVSN": "2",
  "INPUTS": [
    {"NAME": "spot", "TYPE": "point2D", "DEFAULT": [0.25, 0.75], "MIN": [0.0, 0.0], "MAX": [1.0, 1.0], "LABEL": "Spot"},
    {"NAME": "radius", "TYPE": "float", "MIN": 0.01, "MAX": 0.5, "DEFAULT": 0.08}
  ]
}*/

void main() {
  float d = length((isf_FragNormCoord - spot) * vec2(RENDERSIZE.x / RENDERSIZE.y, 1.0));
  gl_FragColor = vec4(vec3(step(d, radius)), 1.0);
}
