#pragma once
// The golden-frame metric (docs/ARCHITECTURE.md, "Golden frames"). Gates on the worst pixels, not
// the mean: a pixel fails when its largest channel difference exceeds both an absolute and a
// relative tolerance; the image fails when too many pixels fail, when any pixel differs by more than
// the hard limit, or when either image holds a NaN or an infinity (a reference with one is broken).
#include "image/image.h"

#include <string>

namespace vitrine {

struct CompareThresholds {
  float absolute = 0.02f;       // linear units: ~5/255 near mid-grey after sRGB encoding
  float relative = 0.10f;       // of the reference channel value
  double failFraction = 0.002;  // 0.2 % of pixels may fail (lavapipe on a CPU of another generation)
  float hardLimit = 0.25f;      // no pixel may differ by more than this
  // The second comparison, for pictures whose single pixels may flip (chaotic sparkles): both images
  // averaged over blocks of `block` x `block` pixels (0: off). A block fails when a channel differs by
  // more than blockAbsolute and blockRelative of the reference; the image fails when more than
  // blockFailFraction of the blocks fail or any differs by more than blockHardLimit. Flips average
  // out; a region, colour or exposure change moves whole blocks and fails. (Calibration in
  // docs/RELIABILITY.md.)
  int block = 0;
  float blockAbsolute = 0.05f;
  float blockRelative = 0.10f;
  double blockFailFraction = 0.01;
  float blockHardLimit = 0.12f;
};

struct CompareResult {
  bool sizeMatches = false;
  uint32_t referenceWidth = 0, referenceHeight = 0, candidateWidth = 0, candidateHeight = 0;
  size_t nonFinite = 0;           // pixels of the candidate holding a NaN or an infinity
  size_t nonFiniteReference = 0;  // the same in the reference
  size_t failing = 0;
  double failingFraction = 0.0;
  float maxDifference = 0.0f;
  double meanDifference = 0.0;
  size_t failingBlocks = 0;          // the low-passed comparison's, when thresholds.block > 0
  size_t blocks = 0;
  float maxBlockDifference = 0.0f;
  bool passed = false;
  std::string summary() const;
};

// `image` averaged over block x block tiles (a partial tile at the right or bottom edge averages what it has).
ImageRgba boxFilter(const ImageRgba& image, int block);

CompareResult compareImages(const ImageRgba& reference, const ImageRgba& candidate,
                            const CompareThresholds& thresholds = {});

}  // namespace vitrine
