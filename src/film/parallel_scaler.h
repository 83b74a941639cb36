#pragma once
// swscale's RGB to Y'CbCr conversion of a whole frame on several threads, with exactly the bytes one
// scaler over the whole frame gives. The frame is cut into bands of rows; each band's scaler reads its
// rows and a margin above and below (wider than the chroma filter), and only its own rows are kept. Band
// edges fall on multiples of 16 rows, so the vertical chroma filter's phase and swscale's 8-row ordered
// dither see the same row numbers as in the whole frame. Only src/film/*.cpp include this (FFmpeg).
#include "film/libav.h"

#include <cstdint>
#include <string>
#include <vector>

namespace vitrine::film {

class ParallelScaler {
 public:
  // Full-range RGB (`source`: RGB24 or RGB48) into `target` on BT.709's matrix, `fullRange` or
  // limited. `bands` 0: one a hardware thread, as many as the height allows. Throws vitrine::Error
  // naming `film` when swscale cannot convert.
  ParallelScaler(AVPixelFormat source, AVPixelFormat target, uint32_t width, uint32_t height, bool fullRange,
                 const std::string& film, uint32_t bands = 0);
  // `packed` (rows of `stride` bytes, top first) into `out`, a frame of the target format and size.
  void scale(const uint8_t* packed, size_t stride, AVFrame& out);
  size_t bands() const { return bands_.size(); }

 private:
  struct Band {
    uint32_t first = 0, rows = 0;  // the output rows it owns
    uint32_t from = 0, height = 0; // the input rows it reads (its rows and the margins)
    ScalerPtr scaler;
    FramePtr frame;  // its output, margins included; none for a band that is the whole frame
  };
  std::vector<Band> bands_;
  AVPixelFormat target_;
  uint32_t width_;
};

}  // namespace vitrine::film
