/*{
  "ISFVSN": "2",
  "INPUTS": [
    {"NAME": "level", "TYPE": "float"},
    {"NAME": "spin", "TYPE": "quaternion"}
  ]
}*/
void main() { gl_FragColor = vec4(level); }
