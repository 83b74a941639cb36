/*{
  "ISFVSN": "2",
  "PASSES": [
    {"TARGET": "nothing", "WIDTH": "-$WIDTH", "HEIGHT": "$HEIGHT"},
    {}
  ]
}*/
void main() { gl_FragColor = IMG_THIS_PIXEL(nothing); }
