#!/usr/bin/env bash
# expect_error.sh REGEX -- COMMAND...: passes when COMMAND exits non-zero without crashing (no signal,
# no uncaught exception) and its stderr matches REGEX: bad input gets a sentence, not a stack trace.
set -u
regex=$1; shift; [ "$1" = "--" ] && shift
err=$("$@" 2>&1 >/dev/null); code=$?
if [ $code -eq 0 ]; then echo "expected failure, got exit 0: $*"; exit 1; fi
if [ $code -ge 128 ]; then echo "crashed with signal $((code - 128)): $*"; echo "$err"; exit 1; fi
if ! grep -Eq -e "$regex" <<<"$err"; then echo "stderr did not match /$regex/:"; echo "$err"; exit 1; fi
echo "ok (exit $code): $err"
