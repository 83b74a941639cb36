#version 330
layout(location = 0) out vec4 result;
out vec4 other;
in vec2 turned;
uniform float oops;
void main() { result = vec4(PASSINDEX == 0 ? 1.0 : IMG_PIXEL(trail, gl_FragCoord.xy).r); }
