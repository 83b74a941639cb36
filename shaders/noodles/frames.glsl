// Up-vector and rotation-minimising (double reflection) frames, and frame <-> quaternion;
// mirrors src/scenes/noodles/frames.h.
#ifndef NOODLES_FRAMES_GLSL
#define NOODLES_FRAMES_GLSL

const uint FRAMES_UP = 0u;
const uint FRAMES_RMF = 1u;
const vec3 WORLD_UP = vec3(0.0, 0.0, 1.0);
const float PARALLEL_SQUARED = 1e-12;
const float NO_TURN_SQUARED = 1e-20;

struct Frame {
  vec3 normal;
  vec3 binormal;  // tangent x normal
  vec3 tangent;
};

Frame upVectorFrame(vec3 tangent) {
  vec3 side = cross(tangent, WORLD_UP);
  if (dot(side, side) < PARALLEL_SQUARED) side = cross(tangent, vec3(1.0, 0.0, 0.0));
  vec3 normal = normalize(side);
  return Frame(normal, cross(tangent, normal), tangent);
}

Frame transportFrame(Frame from, vec3 fromPoint, vec3 toPoint, vec3 toTangent) {
  vec3 chord = toPoint - fromPoint;
  float chordSquared = dot(chord, chord);
  vec3 normal = from.normal;
  vec3 tangent = from.tangent;
  if (chordSquared > NO_TURN_SQUARED) {
    normal -= chord * (2.0 * dot(chord, normal) / chordSquared);
    tangent -= chord * (2.0 * dot(chord, tangent) / chordSquared);
  }
  vec3 turn = toTangent - tangent;
  float turnSquared = dot(turn, turn);
  if (turnSquared > NO_TURN_SQUARED) normal -= turn * (2.0 * dot(turn, normal) / turnSquared);
  normal = normalize(normal - toTangent * dot(toTangent, normal));
  return Frame(normal, cross(toTangent, normal), toTangent);
}

// frames.h's four cases, chosen with selects rather than branches (a warp's strands face every way,
// so branches diverge); each case's arithmetic is as there, so both sides give the same bits.
vec4 frameToQuaternion(Frame f) {
  vec3 n = f.normal, b = f.binormal, t = f.tangent;
  float trace = n.x + b.y + t.z;
  uint which = trace > 0.0 ? 3u : (n.x > b.y && n.x > t.z) ? 0u : b.y > t.z ? 1u : 2u;  // the largest component
  float radicand = which == 3u ? trace + 1.0
                 : which == 0u ? 1.0 + n.x - b.y - t.z
                 : which == 1u ? 1.0 + b.y - n.x - t.z
                               : 1.0 + t.z - n.x - b.y;
  float s = sqrt(radicand) * 2.0;
  // Each other component's numerator: a difference paired with w, a sum between x, y and z.
  vec4 numerators = which == 3u ? vec4(b.z - t.y, t.x - n.z, n.y - b.x, 0.0)
                  : which == 0u ? vec4(0.0, b.x + n.y, t.x + n.z, b.z - t.y)
                  : which == 1u ? vec4(b.x + n.y, 0.0, t.y + b.z, t.x - n.z)
                                : vec4(t.x + n.z, t.y + b.z, 0.0, n.y - b.x);
  vec4 q = numerators / s;
  float big = 0.25 * s;
  return vec4(which == 0u ? big : q.x, which == 1u ? big : q.y, which == 2u ? big : q.z, which == 3u ? big : q.w);
}

Frame quaternionToFrame(vec4 q) {
  float x = q.x, y = q.y, z = q.z, w = q.w;
  return Frame(vec3(1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y + w * z), 2.0 * (x * z - w * y)),
               vec3(2.0 * (x * y - w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z + w * x)),
               vec3(2.0 * (x * z + w * y), 2.0 * (y * z - w * x), 1.0 - 2.0 * (x * x + y * y)));
}

#endif
