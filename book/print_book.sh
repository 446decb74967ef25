#!/usr/bin/env bash
# The printed edition: HTML_DIR/print.html (book_tool printbook: a contents list, then every
# page of the reading order, each from a new sheet) printed to PDF by headless Chromium, with
# the book's print styles (book/book.css, @media print: page numbers, no heading alone at a
# page foot, figures kept with their captions, listings wrapped, link targets printed).
#
#   bash book/print_book.sh HTML_DIR OUT.pdf
set -euo pipefail
[ $# -eq 2 ] || { echo "usage: print_book.sh HTML_DIR OUT.pdf" >&2; exit 2; }
dir=$(cd "$1" && pwd) || { echo "print_book: no directory '$1'" >&2; exit 2; }
[ -f "$dir/print.html" ] || { echo "print_book: no $dir/print.html (book_tool printbook writes it)" >&2; exit 2; }
out=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
rm -f "$out"
# The virtual time lets MathJax typeset every formula before the page is printed.
chromium --headless --no-sandbox --disable-gpu --disable-background-networking \
  --disable-component-update --disable-sync --no-first-run --mute-audio \
  --user-data-dir="$work/profile" --allow-file-access-from-files --no-pdf-header-footer \
  --run-all-compositor-stages-before-draw --virtual-time-budget=120000 \
  --print-to-pdf="$out" "file://$(sed -e 's/%/%25/g' -e 's/ /%20/g' -e 's/#/%23/g' -e 's/?/%3F/g' <<< "$dir")/print.html" > "$work/log" 2>&1 || true
if [ ! -s "$out" ]; then
  echo "print_book: Chromium wrote no $out:" >&2; tail -n 5 "$work/log" >&2; exit 1
fi
echo "print_book: $out"
