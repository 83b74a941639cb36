#pragma once
// One shader specialised several ways, each variant a pipeline built the first time a frame asks for
// it. Options that choose whole shader paths (glass' optics, kifs' stage, noodles' integrator) are
// specialization constants rather than uniform branches: a driver keeps the code of a path a uniform
// branch skips, and llvmpipe pays for it (docs/PERFORMANCE.md). Building on first use keeps start-up
// to the variants a run shows; a variant is kept for the program's life once built.
#include "core/error.h"
#include "gpu/program.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <vector>

namespace vitrine::gpu {

template <class Program, class Source>
class ProgramVariants {
 public:
  static constexpr size_t kMaxConstants = 4;

  ProgramVariants(ProgramLibrary& library, Source source) : library_(library), source_(std::move(source)) {}

  // The variant whose constant_id i takes constants[i]. Looked up without allocating; built (and
  // its pipeline compiled) only the first time.
  const Program& operator()(std::initializer_list<int32_t> constants) const {
    if (constants.size() > kMaxConstants) throw Error("a program variant takes at most 4 specialization constants");
    Key key{};
    key.count = uint32_t(constants.size());
    std::copy(constants.begin(), constants.end(), key.values.begin());
    for (const Built& built : built_)
      if (built.key == key) return *built.program;
    ProgramOptions options{.specialization = std::vector<int32_t>(constants)};
    built_.push_back({key, std::make_unique<Program>(library_, source_, options)});
    return *built_.back().program;
  }

 private:
  struct Key {
    std::array<int32_t, kMaxConstants> values;
    uint32_t count;
    bool operator==(const Key&) const = default;
  };
  struct Built {
    Key key;
    std::unique_ptr<Program> program;
  };

  ProgramLibrary& library_;
  Source source_;
  mutable std::vector<Built> built_;  // a few dozen at most: a linear search
};

using ComputeVariants = ProgramVariants<ComputeProgram, std::string>;
using GraphicsVariants = ProgramVariants<GraphicsProgram, GraphicsState>;

}  // namespace vitrine::gpu
