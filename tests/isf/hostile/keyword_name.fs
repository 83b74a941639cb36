/*{
  "ISFVSN": "2",
  "INPUTS": [
    {"NAME": "uniform", "TYPE": "bool"}
  ]
}*/
void main() { gl_FragColor = vec4(1.0); }
