#version 460
// Uses tests/interop/drifted_block.h in a storage buffer; only its layout matters.
#extension GL_GOOGLE_include_directive : require
#include "drifted_block.h"

layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer Blocks { DriftedBlock blocks[]; };

void main() { blocks[0].weight = blocks[0].tint.x; }
