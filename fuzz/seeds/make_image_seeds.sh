#!/usr/bin/env bash
# Writes the image targets' seeds: tiny self-made pictures (generated patterns, a few bytes each) in the
# variants Vitrine meets: 8/16-bit, grey/RGB/RGBA PNG; half/float EXR with several compressions; HDR.
# Needs oiiotool (Debian: openimageio-tools). The outputs are checked in; run again only to change them.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
mkdir -p "$here/image_png" "$here/image_exr" "$here/image_hdr"
checker() { oiiotool --pattern checker:width=2:height=2:color1=0.9,0.3,0.1,1:color2=0.1,0.2,0.8,0.5 "$1" "$2" "${@:3}"; }
checker 8x6 3 -d uint8 -o "$here/image_png/rgb8.png"
checker 5x7 4 -d uint16 -o "$here/image_png/rgba16.png"
checker 6x4 1 -d uint8 -o "$here/image_png/grey8.png"
checker 3x3 2 -d uint8 -o "$here/image_png/grey_alpha8.png"
checker 8x6 4 -d half --compression none -o "$here/image_exr/rgba_half_none.exr"
checker 8x6 3 -d half --compression zip -o "$here/image_exr/rgb_half_zip.exr"
checker 6x5 4 -d float --compression piz -o "$here/image_exr/rgba_float_piz.exr"
checker 7x3 1 -d half --compression rle -o "$here/image_exr/grey_half_rle.exr"
oiiotool --pattern fill:top=0.2,0.5,1:bottom=40,20,5 8x6 3 -o "$here/image_hdr/sky.hdr"
checker 9x2 3 -o "$here/image_hdr/checker.hdr"
