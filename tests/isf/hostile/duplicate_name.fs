/*{
  "ISFVSN": "2",
  "INPUTS": [
    {"NAME": "glow", "TYPE": "float"}
  ],
  "PASSES": [
    {"TARGET": "glow"},
    {}
  ]
}*/
void main() { gl_FragColor = vec4(glow); }
