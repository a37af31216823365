#!/usr/bin/env bash
# The chapter programs' shape check: each chapter program is a lesson read top to bottom, so no chapter source file
# is longer than 250 lines and no function in one is longer than 80 (clang-tidy's readability-function-size, which
# counts a function's lines from its opening brace to its closing one). Data tables are arrays, not functions, and
# are not counted. The file lengths are checked in a blink; the function lengths need clang-tidy to parse every
# chapter file (about two minutes of two cores), so they are checked only when asked. Exit status 0 when every file
# passes, 1 when one does not, 2 when the check could not run.
#
#   tools/check_lessons.sh [--functions [BUILD_DIR]]     (BUILD_DIR holds compile_commands.json; default build)
set -euo pipefail
cd "$(dirname "$0")/.."
check_functions=no
if [ "${1:-}" = --functions ]; then check_functions=yes; shift; fi
build_dir=${1:-build}
max_file_lines=250
max_function_lines=80

if [ "$check_functions" = yes ] && [ ! -f "$build_dir/compile_commands.json" ]; then
  echo "check_lessons: no compile_commands.json in '$build_dir' (configure the build first)" >&2
  exit 2
fi

problems=0
for f in chapters/*/*.cpp chapters/*/*.hpp; do
  lines=$(wc -l < "$f")
  if [ "$lines" -gt "$max_file_lines" ]; then
    echo "check_lessons: $f has $lines lines (at most $max_file_lines)"
    problems=$((problems + 1))
  fi
done

# Only the .cpp files are compiled on their own; a header's functions are checked where a .cpp includes it.
long_functions=
if [ "$check_functions" = yes ]; then
config="{CheckOptions: [{key: readability-function-size.LineThreshold, value: $max_function_lines}]}"
long_functions=$(printf '%s\n' chapters/*/*.cpp |
  xargs -P 2 -n 4 clang-tidy -p "$build_dir" --quiet --checks='-*,readability-function-size' \
    --header-filter='chapters/.*' --config="$config" 2> /dev/null |
  grep 'exceeds recommended size' | sort -u || true)
fi
if [ -n "$long_functions" ]; then
  echo "$long_functions" | sed "s|^$PWD/||; s|warning: function \('[^']*'\).*|function \1 is longer than $max_function_lines lines|" |
    sed 's/^/check_lessons: /'
  problems=$((problems + $(echo "$long_functions" | wc -l)))
fi

if [ "$problems" -gt 0 ]; then
  echo "check_lessons: $problems problems" >&2
  exit 1
fi
if [ "$check_functions" = yes ]; then
  echo "check_lessons: every chapter source file at most $max_file_lines lines, every function at most $max_function_lines"
else
  echo "check_lessons: every chapter source file at most $max_file_lines lines (function lengths: --functions)"
fi
