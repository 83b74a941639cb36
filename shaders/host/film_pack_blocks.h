// A film's frame packed on the GPU into the bytes its encoder takes, one declaration for both sides:
// host/offline/film_frames.cpp fills the push block, film_pack.comp reads it.
#ifndef HOST_FILM_PACK_BLOCKS_H
#define HOST_FILM_PACK_BLOCKS_H
#include "../common/interop.h"

VITRINE_SHARED_BEGIN
// film::DisplayLayout's values: how the packed bytes lie.
#define FILM_PACK_RGB24 0u  // R, G, B at 8 bits: four pixels into three words
#define FILM_PACK_BGR0 1u   // B, G, R, 0 at 8 bits: a pixel a word
#define FILM_PACK_RGB48 2u  // R, G, B at 16 bits: two pixels into three words
#define FILM_PACK_RGB0 3u   // R, G, B, 0 at 8 bits: a pixel a word

struct HostFilmPackPush {
  uint width;
  uint height;
  uint packing;  // FILM_PACK_*
  uint groups;  // invocations: pixels / pixels an invocation packs, rounded up
};
VITRINE_SHARED_END

#endif
