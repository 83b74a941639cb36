#include "image/image_compare.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <vector>

namespace vitrine {

ImageRgba boxFilter(const ImageRgba& image, int block) {
  const uint32_t size = uint32_t(std::max(block, 1));
  ImageRgba out{(image.width + size - 1) / size, (image.height + size - 1) / size, {}};
  out.pixels.assign(size_t(out.width) * out.height * 4, 0.0f);
  std::vector<uint32_t> counts(size_t(out.width) * out.height, 0);
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) {
      const size_t tile = size_t(y / size) * out.width + x / size;
      for (int c = 0; c < 4; ++c) out.pixels[tile * 4 + c] += image.at(x, y)[c];
      ++counts[tile];
    }
  for (size_t tile = 0; tile < counts.size(); ++tile)
    for (int c = 0; c < 4; ++c) out.pixels[tile * 4 + c] /= float(std::max(counts[tile], 1u));
  return out;
}

namespace {

// The low-passed comparison: counts the blocks whose channels differ by more than both tolerances.
void compareBlocks(const ImageRgba& reference, const ImageRgba& candidate, const CompareThresholds& thresholds,
                   CompareResult& result) {
  const ImageRgba ref = boxFilter(reference, thresholds.block), got = boxFilter(candidate, thresholds.block);
  result.blocks = size_t(ref.width) * ref.height;
  for (size_t i = 0; i < ref.pixels.size(); i += 4) {
    bool fails = false;
    for (size_t c = 0; c < 4; ++c) {
      const float diff = std::fabs(got.pixels[i + c] - ref.pixels[i + c]);
      if (!std::isfinite(diff)) continue;  // the per-pixel comparison has already failed the image
      result.maxBlockDifference = std::max(result.maxBlockDifference, diff);
      if (diff > thresholds.blockAbsolute && diff > thresholds.blockRelative * std::fabs(ref.pixels[i + c])) fails = true;
    }
    result.failingBlocks += fails;
  }
}

}  // namespace

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
  if (thresholds.block > 0) compareBlocks(reference, candidate, thresholds, result);
  result.passed = result.nonFinite == 0 && result.nonFiniteReference == 0 &&
                  result.failingFraction <= thresholds.failFraction && result.maxDifference <= thresholds.hardLimit &&
                  (thresholds.block <= 0 ||
                   (double(result.failingBlocks) <= thresholds.blockFailFraction * double(result.blocks) &&
                    result.maxBlockDifference <= thresholds.blockHardLimit));
  return result;
}

std::string CompareResult::summary() const {
  if (!sizeMatches)
    return fmt::format("size mismatch: reference {}x{}, candidate {}x{}", referenceWidth, referenceHeight,
                       candidateWidth, candidateHeight);
  // Named apart from the member `blocks` it reports (a local of that name read itself, uninitialised,
  // in its own initialiser: std::bad_alloc at -O2 on every failing low-passed golden; -Wshadow now
  // fails the build on that).
  const std::string lowPassed = maxBlockDifference > 0.0f || failingBlocks > 0
                                    ? fmt::format(", {} of {} blocks failing low-passed (max difference {:.5f})",
                                                  failingBlocks, blocks, maxBlockDifference)
                                    : std::string();
  return fmt::format(
      "{}: {} failing pixels ({:.4f}%), max difference {:.5f}, mean {:.6f}, {} non-finite in the reference, {} in "
      "the candidate{}",
      passed ? "pass" : "FAIL", failing, failingFraction * 100.0, maxDifference, meanDifference, nonFiniteReference,
      nonFinite, lowPassed);
}

}  // namespace vitrine
