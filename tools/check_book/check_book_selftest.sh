#!/usr/bin/env bash
# The browser check's test: check_book.sh on fixture/ (both beside this script) must exit 1 and report each defect of
# bad.html (a formula error, a raw formula command, a missing image, a figure too wide at both window widths, a
# table too wide at 800 px only, a link to a missing file, a link to a missing anchor, a backslash before '|', an
# en dash before a flag name, a raw \ref or \f$ in a listing, a character entity shown as its code) and nothing
# else; the good page (MathJax with its AMS extensions, a figure and table that fit, links that resolve, and the
# look-alikes of the markup defects that are not defects: a '|' in code, en dashes between numbers and names, \| in
# a formula) must pass.
#   tools/check_book/check_book_selftest.sh [MATHJAX_DIR]      (default /usr/share/javascript/mathjax)
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
mathjax=${1:-/usr/share/javascript/mathjax}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -r "$here/fixture" "$work/html"
ln -s "$mathjax" "$work/html/mathjax"

"$here/check_book.sh" "$work/html" > "$work/out.txt" 2>&1
status=$?
cat "$work/out.txt"
failed=0
if [ "$status" != 1 ]; then echo "selftest: expected exit status 1, got $status"; failed=1; fi
expect() {
  if ! grep -qE -- "$1" "$work/out.txt"; then echo "selftest: not reported: $1"; failed=1; fi
}
expect "^bad\.html: formula error 'Undefined control sequence \\\\tfrac'"
expect "^bad\.html: raw formula command in the text: .*\\\\f\\\$d \+ 1"
expect "^bad\.html: image 'missing\.png' is missing"
expect "^bad\.html: figure 'wide\.svg' is 2000 px wide, wider than the [0-9]+ px text column at a 1280 px window"
expect "^bad\.html: figure 'wide\.svg' is 2000 px wide, wider than the [0-9]+ px text column at a 800 px window"
expect "^bad\.html: table 'a table for wide windows only' is 1100 px wide, .* at a 800 px window"
expect "^bad\.html: link 'nowhere\.html': no such file"
expect "^bad\.html: link 'index\.html#no-such-anchor': index\.html has no anchor 'no-such-anchor'"
expect "^bad\.html: a backslash before '\|' .*: '.*elementary\\\\\|pi"
expect "^bad\.html: an en dash before a flag name .*quick for a short run"
expect "^bad\.html: raw \\\\ref markup: .*ref_dormand1980"
expect "^bad\.html: raw formula command in the text: '// the stage weights \\\\f\\\$b_i"
expect "^bad\.html: a character entity shown as its code: .*&#124;dv"
expect ": 13 problems$"
if [ "$failed" = 0 ]; then echo "selftest: every defect found, nothing else"; fi
exit "$failed"
