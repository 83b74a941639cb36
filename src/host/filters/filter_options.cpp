#include "host/filters/filter_options.h"

#include <fmt/format.h>

#include "core/error.h"

namespace vitrine::host {

std::vector<FilterSpec> filterSpecs(const Options& options) {
  std::vector<FilterSpec> chain;
  std::string names;
  for (const std::string& file : options.filters) {
    chain.push_back({file, {}});
    names += (names.empty() ? "" : ", ") + filterName(file);
  }
  for (const FilterSetting& setting : options.filterParameters) {
    bool named = false;
    for (FilterSpec& spec : chain)
      if (filterName(spec.file) == setting.filter) spec.values.emplace_back(setting.key, setting.value), named = true;
    if (!named)
      throw Error(fmt::format("--set filter.{}.{}={}: no --filter is named {} ({})", setting.filter, setting.key,
                              setting.value, setting.filter,
                              names.empty() ? std::string("there is no --filter") : "the filters are " + names));
  }
  return chain;
}

}  // namespace vitrine::host
