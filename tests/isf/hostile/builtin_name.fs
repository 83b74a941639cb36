/*{
  "ISFVSN": "2",
  "INPUTS": [
    {"NAME": "TIME", "TYPE": "float"}
  ]
}*/
void main() { gl_FragColor = vec4(TIME); }
