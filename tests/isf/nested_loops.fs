/*{
  "DESCRIPTION": "A nest of loops whose counts are fixed (1000 by 1000) past the loop budget, then an endless one: the nest is charged as each loop starts, so 64 of the inner loops run whole and the rest not at all (red: the inner iterations counted over 64000; green: what the endless loop added, none)",
  "ISFVSN": "2"
}*/

void main() {
  float n = 0.0, after = 0.0;
  for (int i = 0; i < 1000; ++i) {
    for (int j = 0; j < 1000; ++j) {
      n += 1.0;
    }
  }
  while (true) {
    after += 1.0;
  }
  gl_FragColor = vec4(n / 64000.0, after, 0.0, 1.0);
}
