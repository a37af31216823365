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
# CHROMIUM names the browser (default: chromium, Debian's package); CHECK_BOOK_JOBS the number of Chromium
# processes that share the pages (default 2).
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
if [ $# -gt 1 ]; then
  printf '%s\n' "${@:2}" > "$work/pages.txt"
else
  (cd "$html_dir" && find . -maxdepth 1 -name '*.html' -printf '%f\n' | LC_ALL=C sort) > "$work/pages.txt"
fi
page_count=$(wc -l < "$work/pages.txt")
widths="1280 800"

# One Chromium runs the pages of its share on about one core (its iframes share one renderer), so the pages are
# shared among CHECK_BOOK_JOBS Chromium processes (default 2, CI's cores): largest first, each to the share with
# the fewest bytes so far, so that the shares take about as long. Each process checks its share and writes its
# findings (check_book.js explains them); the merge below matches the links between shares and writes the verdict.
jobs=${CHECK_BOOK_JOBS:-2}
if [ "$jobs" -gt "$page_count" ]; then jobs=$page_count; fi
if [ "$jobs" -lt 1 ]; then jobs=1; fi
while read -r page; do printf '%s\t%s\n' "$(stat -c %s "$html_dir/$page" 2> /dev/null || echo 0)" "$page"; done \
  < "$work/pages.txt" | sort -t "$(printf '\t')" -k1,1nr -k2 |
  awk -F '\t' -v jobs="$jobs" -v work="$work" '{
    k = 0
    for (j = 1; j < jobs; ++j) if (bytes[j] < bytes[k]) k = j
    bytes[k] += $1
    print $2 > (work "/share" k ".txt")
  }'
json_list() { sed -e 's/\\/\\\\/g' -e 's/"/\\"/g' -e 's/^/"/' -e 's/$/",/' "$1"; }
for ((k = 0; k < jobs; ++k)); do
  mkdir "$work/$k"
  cp "$work/check_book.html" "$work/check_book.js" "$work/$k/"
  {
    printf 'window.CHECK_BOOK = {root: "file://%s/", widths: [%s], concurrency: 3,\n' "$html_dir" "${widths// /, }"
    printf 'pages: [\n'; json_list "$work/share$k.txt"; printf '],\n'
    printf 'allPages: [\n'; json_list "$work/pages.txt"; printf ']};\n'
  } > "$work/$k/pages.js"
done

# Virtual time runs only while nothing is loading, so the budget bounds the pages' idle waits, not the real
# time; `timeout` bounds the real time. A profile of its own keeps each run apart from any other Chromium.
for ((k = 0; k < jobs; ++k)); do
  timeout 600 "$chromium" --headless --no-sandbox --disable-gpu --no-first-run --user-data-dir="$work/$k/profile" \
    --allow-file-access-from-files --window-size=1400,1000 --virtual-time-budget=3600000 \
    --dump-dom "file://$work/$k/check_book.html" > "$work/$k/dom.html" 2> "$work/$k/chromium.log" &
  pids[k]=$!
done
failed=no
for ((k = 0; k < jobs; ++k)); do
  status=0
  wait "${pids[k]}" || status=$?
  if [ "$status" != 0 ] || ! grep -q 'data-done="yes"' "$work/$k/dom.html"; then
    echo "check_book: Chromium did not finish the check (status $status); its last messages:" >&2
    tail -n 5 "$work/$k/chromium.log" >&2
    failed=yes
  fi
done
if [ "$failed" = yes ]; then exit 2; fi
# The findings, unescaped.
for ((k = 0; k < jobs; ++k)); do
  sed -n '/<pre id="verdict"/,/<\/pre>/p' "$work/$k/dom.html" | sed -e 's/<[^>]*>//g' -e 's/&lt;/</g' -e 's/&gt;/>/g' \
    -e 's/&quot;/"/g' -e "s/&#39;/'/g" -e 's/&amp;/\&/g' | sed '/^$/d'
done > "$work/findings.txt"
if grep '^X' "$work/findings.txt" | cut -f 2- | grep . >&2; then exit 2; fi
# The verdict: the problems, sorted, then one summary line. A link to a page with an anchor is a problem when no
# share saw the page (no G line) or the page does not define the anchor.
LC_ALL=C awk -F '\t' -v q="'" '
  $1 == "P" { problems[$2] = 1 }
  $1 == "G" { seen[$2] = 1 }
  $1 == "A" { defined[$2, $3] = 1 }
  $1 == "L" { page[++n] = $2; file[n] = $3; anchor[n] = $4; href[n] = $5 }
  $1 == "N" { links += $2 }
  END {
    for (i = 1; i <= n; ++i) {
      if (!(file[i] in seen)) problems[page[i] ": link " q href[i] q ": no such file"] = 1
      else if (!((file[i], anchor[i]) in defined))
        problems[page[i] ": link " q href[i] q ": " file[i] " has no anchor " q anchor[i] q] = 1
    }
    for (p in problems) { print p; ++count }
    print "~" links " " count + 0
  }' "$work/findings.txt" | LC_ALL=C sort > "$work/merged.txt"
summary=$(grep '^~' "$work/merged.txt" | tail -n 1)
read -r link_count problem_count <<< "${summary#\~}"
grep -v '^~' "$work/merged.txt" || true
echo "checked $page_count pages at ${widths// / and } px windows, $link_count links: $problem_count problems"
if [ "$problem_count" = 0 ]; then exit 0; fi
exit 1
