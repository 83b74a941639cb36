/*{
  "ISFVSN": "2",
  "PASSES": [
    {"TARGET": "a", "WIDTH": "$b", "HEIGHT": "$HEIGHT"},
    {"TARGET": "b", "WIDTH": "$a"},
    {}
  ]
}*/
void main() { gl_FragColor = vec4(1.0); }
