#include "image/image_compare.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace vitrine {

CompareResult compareImages(const ImageRgba& reference, const ImageRgba& candidate,
                            const CompareThresholds& thresholds) {
  CompareResult result;
  result.referenceWidth = reference.width, result.referenceHeight = reference.height;
  result.candidateWidth = candidate.width, result.candidateHeight = candidate.height;
  result.sizeMatches = reference.width == candidate.width && reference.height == candidate.height &&
                       reference.pixels.size() == candidate.pixels.size();
  if (!result.sizeMatches) return result;
  const size_t count = size_t(reference.width) * reference.height;
  double sum = 0.0;
  for (size_t i = 0; i < count; ++i) {
    float worst = 0.0f;
    bool fails = false, badReference = false, badCandidate = false;
    for (int c = 0; c < 4; ++c) {
      const float ref = reference.pixels[i * 4 + c];
      const float got = candidate.pixels[i * 4 + c];
      // A NaN or infinity on either side fails the pixel; it takes no part in the differences, which
      // it would make NaN (and so invisible to every comparison) or infinite.
      if (!std::isfinite(ref) || !std::isfinite(got)) {
        badReference |= !std::isfinite(ref);
        badCandidate |= !std::isfinite(got);
        fails = true;
        continue;
      }
      const float diff = std::fabs(got - ref);
      worst = std::max(worst, diff);
      if (diff > thresholds.absolute && diff > thresholds.relative * std::fabs(ref)) fails = true;
    }
    result.nonFiniteReference += badReference;
    result.nonFinite += badCandidate;
    sum += worst;
    result.maxDifference = std::max(result.maxDifference, worst);
    if (fails) ++result.failing;
  }
  result.failingFraction = count ? double(result.failing) / double(count) : 0.0;
  result.meanDifference = count ? sum / double(count) : 0.0;
  result.passed = result.nonFinite == 0 && result.nonFiniteReference == 0 &&
                  result.failingFraction <= thresholds.failFraction && result.maxDifference <= thresholds.hardLimit;
  return result;
}

std::string CompareResult::summary() const {
  if (!sizeMatches)
    return fmt::format("size mismatch: reference {}x{}, candidate {}x{}", referenceWidth, referenceHeight,
                       candidateWidth, candidateHeight);
  return fmt::format(
      "{}: {} failing pixels ({:.4f}%), max difference {:.5f}, mean {:.6f}, {} non-finite in the reference, {} in "
      "the candidate",
      passed ? "pass" : "FAIL", failing, failingFraction * 100.0, maxDifference, meanDifference, nonFiniteReference,
      nonFinite);
}

}  // namespace vitrine
