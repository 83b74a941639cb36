#pragma once
#include <vector>

namespace vitrine {
// Nearest-rank percentile (p in 0..100) of the samples; 0 for none. Takes a copy: it sorts.
double percentile(std::vector<double> samples, double p);
}  // namespace vitrine
