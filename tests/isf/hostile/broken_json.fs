/*{
  "DESCRIPTION": "a comma is missing after the next line",
  "ISFVSN": "2"
  "INPUTS": []
}*/
void main() { gl_FragColor = vec4(1.0); }
