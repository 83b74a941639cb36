#pragma once
// The filter chain and transition values the command line gives: --filter FILE in order, each with the
// --set filter.NAME.KEY=VALUE pairs naming it.
#include "app/options.h"
#include "host/filters/filter_chain.h"

#include <vector>

namespace vitrine::host {

// Throws vitrine::Error when a filter.NAME.KEY names no --filter (saying which there are).
std::vector<FilterSpec> filterSpecs(const Options& options);

}  // namespace vitrine::host
