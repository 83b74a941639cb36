/*{
  "ISFVSN": "2",
  "PASSES": [
    {"TARGET": "vast", "WIDTH": "$WIDTH*1000", "HEIGHT": "$HEIGHT"},
    {}
  ]
}*/
void main() { gl_FragColor = IMG_THIS_PIXEL(vast); }
