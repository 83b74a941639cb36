#include "core/stats.h"

#include <algorithm>
#include <cmath>

namespace vitrine {

double percentile(std::vector<double> samples, double p) {
  if (samples.empty()) return 0.0;
  std::sort(samples.begin(), samples.end());
  const double rank = std::ceil(p / 100.0 * double(samples.size()));
  const size_t index = rank < 1.0 ? 0 : std::min(samples.size() - 1, size_t(rank) - 1);
  return samples[index];
}

}  // namespace vitrine
