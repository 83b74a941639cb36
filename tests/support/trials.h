#pragma once
// How many random trials a brute-force test runs: all of them in the Release suite, a fifth in the
// sanitizer build (scripts/test-sanitize), whose -O0 instrumented code runs such loops 10-20x slower
// (the noodles capsule, reverb and diamond tests were 62 of its 160 CPU-s) and whose checks (memory
// errors, undefined behaviour) the first trials meet on the same code paths as the last. Trials are
// drawn in the same order either way, so a sanitized run is the Release run's first part.
namespace vitrine::test {

#if defined(__SANITIZE_ADDRESS__)  // GCC
inline constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)  // clang
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif
#else
inline constexpr bool kSanitized = false;
#endif

constexpr int trials(int releaseTrials) { return kSanitized ? (releaseTrials + 4) / 5 : releaseTrials; }

}  // namespace vitrine::test
