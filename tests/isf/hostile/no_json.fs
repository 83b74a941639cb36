// A plain GLSL shader with no ISF header.
void main() { gl_FragColor = vec4(1.0); }
