/*{
  "ISFVSN": "2",
  "DESCRIPTION": "café in Latin-1"
}*/
void main() { gl_FragColor = vec4(1.0); }
