/*{
  "DESCRIPTION": "Loops forever as written: only the host's loop guard ends it (white: the guard's bound of 65536 iterations counted)",
  "ISFVSN": "2"
}*/

void main() {
  float n = 0.0;
  while (true) {
    n += 1.0;
  }
  for (;;) {
    n += 1.0;  // never runs: the bound is spent
  }
  gl_FragColor = vec4(vec3(n / 65536.0), 1.0);
}
