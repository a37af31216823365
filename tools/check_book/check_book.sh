#!/usr/bin/env bash
# The book's browser check: opens every page of the built book in headless Chromium (check_book.html and
# check_book.js beside this script), lets MathJax finish, and prints one line per problem a reader would see:
# a formula error or a raw formula command, a missing image, a link to a missing file or anchor, a figure, table or
# displayed formula wider than the text column at a 1280 or an 800 px window. Exit status 0 when there is none,
# 1 when there are problems, 2 when the check itself could not run.
#
#   tools/check_book/check_book.sh [HTML_DIR [PAGE.html ...]]
#
# HTML_DIR defaults to build/docs/html (`cmake --build build --target check_book` builds the book and runs this);
# PAGEs restrict the check to those pages (links into the other pages are checked against their HTML as written).
#
# CHROMIUM names the browser (default: chromium, Debian's package).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
html_dir=${1:-build/docs/html}
if [ ! -f "$html_dir/index.html" ]; then
  echo "check_book: no book in '$html_dir' (build it with: cmake --build build --target docs)" >&2
  exit 2
fi
html_dir=$(cd "$html_dir" && pwd)
chromium=${CHROMIUM:-chromium}
if ! command -v "$chromium" > /dev/null; then
  echo "check_book: '$chromium' not found: install the Debian package chromium" >&2
  exit 2
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$here/check_book.html" "$here/check_book.js" "$work/"
# The pages of the book: every HTML file at the top of the folder (search/ holds the search box's result frames,
# mathjax/ MathJax's own files).
{
  printf 'window.CHECK_BOOK = {root: "file://%s/", widths: [1280, 800], concurrency: 3, pages: [\n' "$html_dir"
  if [ $# -gt 1 ]; then
    printf '"%s",\n' "${@:2}"
  else
    (cd "$html_dir" && find . -maxdepth 1 -name '*.html' -printf '"%f",\n' | sort)
  fi
  printf ']};\n'
} > "$work/pages.js"

# Virtual time runs only while nothing is loading, so the budget bounds the pages' idle waits, not the real
# time; `timeout` bounds the real time. A profile of its own keeps the run apart from any other Chromium.
status=0
timeout 600 "$chromium" --headless --no-sandbox --disable-gpu --no-first-run --user-data-dir="$work/profile" \
  --allow-file-access-from-files --window-size=1400,1000 --virtual-time-budget=3600000 \
  --dump-dom "file://$work/check_book.html" > "$work/dom.html" 2> "$work/chromium.log" || status=$?
if [ "$status" != 0 ] || ! grep -q 'data-done="yes"' "$work/dom.html"; then
  echo "check_book: Chromium did not finish the check (status $status); its last messages:" >&2
  tail -n 5 "$work/chromium.log" >&2
  exit 2
fi
# The verdict, unescaped: the problems, then one summary line.
sed -n '/<pre id="verdict"/,/<\/pre>/p' "$work/dom.html" | sed -e 's/<[^>]*>//g' -e 's/&lt;/</g' -e 's/&gt;/>/g' \
  -e 's/&quot;/"/g' -e "s/&#39;/'/g" -e 's/&amp;/\&/g' | sed '/^$/d' > "$work/verdict.txt"
cat "$work/verdict.txt"
if tail -n 1 "$work/verdict.txt" | grep -q ': 0 problems$'; then exit 0; fi
exit 1
