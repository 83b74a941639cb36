/*{
  "DESCRIPTION": "Fails to compile on its line 12, where it names a variable it never declared",
  "ISFVSN": "2",
  "INPUTS": [{"NAME": "level", "TYPE": "float", "DEFAULT": 0.5}]
}*/

void main() {
  vec3 base = vec3(level);
  // a comment, so the error is not on the line the body starts on
  /* and a block comment
     over two lines */
  gl_FragColor = vec4(base * brightnes, 1.0);
}
