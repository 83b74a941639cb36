#!/usr/bin/env bash
# run.sh COMMAND...: runs one test of the sanitizer build with the sanitizers' options, so that
# `ctest -L sanitize` behaves the same from scripts/test-sanitize, CI or a shell. Any report fails the
# test: AddressSanitizer and UBSan halt at the first one; LeakSanitizer checks at exit. Only the
# third-party leaks listed (with reasons) in lsan.supp are suppressed.
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
export ASAN_OPTIONS=detect_leaks=1:halt_on_error=1:abort_on_error=0:check_initialization_order=1:detect_stack_use_after_return=1:strict_init_order=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}
export LSAN_OPTIONS=suppressions=$here/lsan.supp:print_suppressions=0${LSAN_OPTIONS:+:$LSAN_OPTIONS}
# Brief: a failing test prints its failure and not the hundreds of passing lines around it (CI keeps a
# short tail of the log).
export GTEST_BRIEF=${GTEST_BRIEF:-1}
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}
exec "$@"
