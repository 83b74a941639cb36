#version 460
// One strand per instance, drawn as an indexed triangle list (src/scenes/noodles/tube_mesh.h): vertex
// v is ring corner v % 9 of node v / 9, so the instance count is the strand count and neighbouring
// segments share their ring's vertices. Each ring is the node's frame normal and binormal turned
// round the tangent, so the tube is watertight. All eight sides are drawn; back-face culling drops
// the ones turned away from the eye.
#extension GL_GOOGLE_include_directive : require
#include "noodles/packing.glsl"
#include "noodles/palette.glsl"
#include "noodles/tube_push.glsl"

layout(binding = 0, std430) readonly buffer Nodes { uvec4 nodes[]; };  // this chunk's nodes

layout(location = 0) out vec3 outNormal;
layout(location = 1) out vec3 outColour;
layout(location = 2) out float outSide;  // ring position in sides from corner 0; 8 on the seam's copy of corner 0

const uint RING_VERTICES = 9u;  // kRingVertices: corner 8 repeats corner 0
const float SIDE_ANGLE = 6.28318530718 / 8.0;

void main() {
  uint local = uint(gl_InstanceIndex);
  uint nodeIndex = uint(gl_VertexIndex) / RING_VERTICES;
  uint corner = uint(gl_VertexIndex) - nodeIndex * RING_VERTICES;
  uvec4 node = nodes[nodeSlot(pc.chunkStrands, local, nodeIndex)];
  Frame frame = nodeFrame(node);
  // The seam's copy takes corner 0's angle exactly, so the two land on the same point.
  float angle = float(corner & 7u) * SIDE_ANGLE;
  vec3 radial = cos(angle) * frame.normal + sin(angle) * frame.binormal;

  // The rings at a strand's two ends shrink to points, closing the tube with cones: back-face
  // culling would otherwise let the eye see through an open end.
  bool tip = pc.segments > 1u && (nodeIndex == 0u || nodeIndex == pc.segments);
  float radius = tip ? 0.0 : pc.radius;

  gl_Position = pc.viewProjection * vec4(nodePosition(node) + radial * radius, 1.0);
  outNormal = radial;
  outColour = strandColour(pc.firstStrand + local, pc.strands, pc.colouring);
  outSide = float(corner);
}
