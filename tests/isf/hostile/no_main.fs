/*{ "ISFVSN": "2" }*/
vec4 colour() { return vec4(1.0); }
