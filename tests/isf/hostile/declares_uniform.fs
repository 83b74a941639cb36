/*{
  "ISFVSN": "2"
}*/

uniform float brightness;

void main() { gl_FragColor = vec4(brightness); }
