#!/usr/bin/env bash
# A shared block whose C++ and GLSL layouts disagree fails the build with a message that names the
# shader and the member: the shader is compiled, the layout checks generated from its SPIR-V, and the
# result compiled as the build compiles block_layout_checks.cpp.
# Usage: block_layout_drift.sh GLSLANG_VALIDATOR BLOCK_LAYOUTS_TOOL CXX SOURCE_ROOT OUT_DIR
set -euo pipefail
glslang=$1 tool=$2 cxx=$3 root=$4 out=$5
mkdir -p "$out"
cd "$root"
"$glslang" --quiet -V --target-env vulkan1.3 -o "$out/drifted.spv" tests/interop/drifted_block.comp
"$tool" "$out/drifted_checks.cpp" tests/interop/drifted_block.h --spirv "interop/drifted_block.comp=$out/drifted.spv"
if "$cxx" -std=c++20 -fsyntax-only -I"$root" "$out/drifted_checks.cpp" 2>"$out/drifted.log"; then
  echo "FAIL: the drifted block compiled"; exit 1
fi
grep -q 'interop/drifted_block.comp: DriftedBlock::tint is at byte 16 in the shader' "$out/drifted.log" ||
  { echo "FAIL: the message does not name the shader and member:"; cat "$out/drifted.log"; exit 1; }
grep -q 'steps 32 bytes per DriftedBlock' "$out/drifted_checks.cpp" ||
  { echo "FAIL: no check on the array's stride"; cat "$out/drifted_checks.cpp"; exit 1; }
echo "refused as it should be: $(grep -o 'interop/drifted_block.comp: DriftedBlock::tint[^"]*' "$out/drifted.log" | head -1)"
