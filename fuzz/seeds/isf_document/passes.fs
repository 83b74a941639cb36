/*{
  "INPUTS": [{"NAME": "k", "TYPE": "float", "DEFAULT": 4}],
  "PASSES": [
    {"TARGET": "a", "WIDTH": "floor($WIDTH/3)+1", "HEIGHT": "max($HEIGHT*0.25, $k*8)"},
    {"TARGET": "b", "PERSISTENT": 1, "FLOAT": "true"},
    {"TARGET": "a", "WIDTH": "floor($WIDTH/3)+1", "HEIGHT": "max($HEIGHT*0.25, $k*8)"},
    {}
  ],
  "IMPORTED": [{"NAME": "img", "PATH": "x.png"}]
}*/
void main() { gl_FragColor = IMG_THIS_PIXEL(a) + IMG_NORM_PIXEL(b, vec2(0.5)) + IMG_SIZE(img).xyxy; }
