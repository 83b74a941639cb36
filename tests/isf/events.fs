/*{
  "DESCRIPTION": "An event flashes the next frame white; a persistent buffer remembers how many fired",
  "ISFVSN": "2",
  "INPUTS": [
    {"NAME": "strike", "TYPE": "event"},
    {"NAME": "reset", "TYPE": "event"}
  ],
  "PASSES": [
    {"TARGET": "count", "PERSISTENT": true, "FLOAT": true, "WIDTH": "1", "HEIGHT": "1"},
    {}
  ]
}*/

void main() {
  if (PASSINDEX == 0) {
    float n = reset ? 0.0 : IMG_PIXEL(count, vec2(0.5)).r + (strike ? 1.0 : 0.0);
    gl_FragColor = vec4(n, 0.0, 0.0, 1.0);
  } else {
    float n = IMG_PIXEL(count, vec2(0.5)).r;
    gl_FragColor = strike ? vec4(1.0) : vec4(vec3(fract(n / 10.0)), 1.0);
  }
}
