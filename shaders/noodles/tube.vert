#version 460
// One tube segment per instance: an 8-sided prism between two strand nodes, as a 16-vertex triangle
// strip with no index or vertex buffer. Each ring is the node's frame normal and binormal turned
// round the tangent, so neighbouring segments share rings and the tube is watertight.
// Sixteen strip vertices close only seven of the eight sides, so the side left out is chosen per
// instance as the one facing straight away from the eye: it is always a back face, so the prism
// looks exactly like a closed one.
#extension GL_GOOGLE_include_directive : require
#include "noodles/packing.glsl"
#include "noodles/palette.glsl"
#include "noodles/tube_push.glsl"

layout(binding = 0, std430) readonly buffer Nodes { uvec4 nodes[]; };  // this chunk's nodes

layout(location = 0) out vec3 outNormal;
layout(location = 1) out vec3 outColour;
layout(location = 2) out float outSide;  // ring position in sides from corner 0, unwrapped along the strip

const float SIDE_ANGLE = 6.28318530718 / 8.0;

void main() {
  // Instances run node-major, like the nodes: neighbouring instances read neighbouring records.
  uint instance = uint(gl_InstanceIndex);
  uint segment = instance / pc.chunkStrands;
  uint local = instance - segment * pc.chunkStrands;
  uvec4 startNode = nodes[nodeSlot(pc.chunkStrands, local, segment)];
  uvec4 endNode = nodes[nodeSlot(pc.chunkStrands, local, segment + 1u)];
  Frame startFrame = nodeFrame(startNode);
  Frame endFrame = nodeFrame(endNode);

  // The side whose outward normal points most directly away from the eye, at angle (first + 7.5)
  // sides round from the normal, is the one the strip leaves out. The direction is averaged over
  // both rings, which differ where up-vector frames twist.
  vec3 fromEye = 0.5 * (nodePosition(startNode) + nodePosition(endNode)) - pc.eye;
  vec2 awayAtStart = vec2(dot(fromEye, startFrame.normal), dot(fromEye, startFrame.binormal));
  vec2 awayAtEnd = vec2(dot(fromEye, endFrame.normal), dot(fromEye, endFrame.binormal));
  vec2 away = awayAtStart / max(length(awayAtStart), 1e-20) + awayAtEnd / max(length(awayAtEnd), 1e-20);
  uint first = uint(int(floor(atan(away.y, away.x) / SIDE_ANGLE - 7.0)) & 7);

  // Even strip vertices on the end ring, odd on the start ring: counter-clockwise seen from outside.
  bool atEnd = (gl_VertexIndex & 1) == 0;
  uint corner = (first + uint(gl_VertexIndex >> 1)) & 7u;
  float angle = float(corner) * SIDE_ANGLE;
  uvec4 node = atEnd ? endNode : startNode;
  Frame frame = atEnd ? endFrame : startFrame;
  vec3 radial = cos(angle) * frame.normal + sin(angle) * frame.binormal;

  // The rings at a strand's two ends shrink to points, closing the tube with cones: back-face
  // culling would otherwise let the eye see through an open end.
  uint nodeIndex = segment + (atEnd ? 1u : 0u);
  bool tip = pc.segments > 1u && (nodeIndex == 0u || nodeIndex == pc.segments);
  float radius = tip ? 0.0 : pc.radius;

  gl_Position = pc.viewProjection * vec4(nodePosition(node) + radial * radius, 1.0);
  outNormal = radial;
  outColour = strandColour(pc.firstStrand + local, pc.strands, pc.colouring);
  outSide = float(first + uint(gl_VertexIndex >> 1));
}
