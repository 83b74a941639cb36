/*{
  "ISFVSN": "2",
  "PASSES": [
    {"TARGET": "a", "PERSISTENT": true, "FLOAT": true, "WIDTH": "16000", "HEIGHT": "16000"},
    {}
  ]
}*/
void main() { gl_FragColor = IMG_THIS_PIXEL(a); }
