/*{
  "DESCRIPTION": "A filter written as for GLES 2: precision qualifiers, texture2D, gl_FragColor, a GL_ES block",
  "ISFVSN": "2",
  "INPUTS": [
    {"NAME": "inputImage", "TYPE": "image"},
    {"NAME": "amount", "TYPE": "float", "MIN": 0.0, "MAX": 1.0, "DEFAULT": 0.5}
  ]
}*/
#ifdef GL_ES
precision mediump float;
#endif
precision highp float;

const lowp vec3 kLuma = vec3(0.2126, 0.7152, 0.0722);

mediump vec3 desaturate(mediump vec3 c, float by) {
  return mix(c, vec3(dot(c, kLuma)), by);
}

void main() {
  vec4 source = texture2D(inputImage, isf_FragNormCoord);
  vec4 shifted = texture2DRect(inputImage, gl_FragCoord.xy + vec2(2.0, 0.0));
  gl_FragColor = vec4(desaturate(mix(source.rgb, shifted.rgb, 0.5), amount), source.a);
}
