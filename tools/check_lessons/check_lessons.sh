#!/usr/bin/env bash
# The chapter programs' shape check: each chapter program is a lesson read top to bottom, so no chapter source file
# is longer than 250 lines and no function in one is longer than 80, counted as clang-tidy's
# readability-function-size counts them (from a body's opening brace to its closing one, a lambda's lines counted in
# the function that holds it). Data tables are initialisers, not functions, and are not counted. The function
# lengths are found by function_lengths.py, a scanner that gives clang-tidy's findings (compared over the chapters
# at lower thresholds) without parsing the chapters' Eigen, so the whole check takes well under a second.
# Exit status 0 when every file passes, 1 when one does not, 2 when the check could not run.
#
#   tools/check_lessons/check_lessons.sh
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
cd "$here/../.."
max_file_lines=250
max_function_lines=80

too_long=$(wc -l chapters/*/*.cpp chapters/*/*.hpp |
  awk -v max="$max_file_lines" \
    '$2 != "total" && $1 > max { print "check_lessons: " $2 " has " $1 " lines (at most " max ")" }')
problems=0
if [ -n "$too_long" ]; then
  echo "$too_long"
  problems=$(echo "$too_long" | wc -l)
fi

status=0
long_functions=$(python3 "$here/function_lengths.py" --max "$max_function_lines" chapters/*/*.cpp chapters/*/*.hpp) ||
  status=$?
if [ "$status" -gt 1 ]; then
  echo "check_lessons: the function lengths could not be read" >&2
  exit 2
fi
if [ -n "$long_functions" ]; then
  echo "$long_functions" | sed 's/^/check_lessons: /'
  problems=$((problems + $(echo "$long_functions" | wc -l)))
fi

if [ "$problems" -gt 0 ]; then
  echo "check_lessons: $problems problems" >&2
  exit 1
fi
echo "check_lessons: every chapter source file at most $max_file_lines lines," \
  "every function at most $max_function_lines"
