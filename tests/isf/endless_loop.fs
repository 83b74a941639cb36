/*{
  "DESCRIPTION": "Loops forever as written: only the host's loop guard ends it (red: the guard's bound of 65536 iterations counted; green: where a chaotic sequence got to, so no compiler can skip the work)",
  "ISFVSN": "2"
}*/

void main() {
  float n = 0.0;
  float x = isf_FragNormCoord.x;
  while (true) {
    x = fract(x * 3.7 + 0.1);
    n += 1.0;
  }
  for (;;) {
    n += 1.0;  // never runs: the bound is spent
  }
  gl_FragColor = vec4(n / 65536.0, x, 0.0, 1.0);
}
