#!/usr/bin/env bash
# The test of the function-length scanner (function_lengths.py): it must find in fixture.cpp exactly the functions
# clang-tidy's readability-function-size finds there, with the same lengths (checked once by running clang-tidy on
# the fixture with LineThreshold 0), not counting the braces of comments, literals, a macro, a data table or a lambda
# at namespace scope, and it must report the two functions longer than 12 lines and exit with status 1.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
cd "$here"
expected_all="fixture.cpp:28: long_function 15
fixture.cpp:46: long_with_lambda 14
fixture.cpp:63: Integrator 2
fixture.cpp:66: operator() 0
fixture.cpp:67: operator== 2
fixture.cpp:80: Integrator::scaled 2
fixture.cpp:86: main 0"
expected_long="fixture.cpp:28: function 'long_function' has 15 lines (at most 12)
fixture.cpp:46: function 'long_with_lambda' has 14 lines (at most 12)"

all=$(python3 function_lengths.py --all fixture.cpp)
status=0
long=$(python3 function_lengths.py --max 12 fixture.cpp) || status=$?
failed=0
if [ "$all" != "$expected_all" ]; then
  printf 'function_lengths_selftest: --all printed\n%s\nexpected\n%s\n' "$all" "$expected_all" >&2
  failed=1
fi
if [ "$long" != "$expected_long" ] || [ "$status" -ne 1 ]; then
  printf 'function_lengths_selftest: --max 12 printed (status %d)\n%s\nexpected (status 1)\n%s\n' \
    "$status" "$long" "$expected_long" >&2
  failed=1
fi
[ "$failed" -eq 0 ] && echo "function_lengths_selftest: the scanner finds the fixture's functions and lengths"
exit "$failed"
