/*{
  "ISFVSN": "2",
  "PASSES": [
    {"TARGET": "echo"}
  ]
}*/
void main() { gl_FragColor = IMG_THIS_PIXEL(echo) * 0.9 + vec4(0.1); }
