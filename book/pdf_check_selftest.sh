#!/usr/bin/env bash
# The PDF check checked: printed books with one planted defect each (a page left half empty
# inside a chapter, a figure missing from the PDF, more pages than the bound) must each be
# named, and a well-printed book must pass. The books are small HTML files in the printed
# book's form (a contents list, then each chapter from a new sheet) printed by Chromium.
#
#   bash book/pdf_check_selftest.sh BOOK_TOOL
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
[ $# -eq 1 ] && [ -x "$1" ] || { echo "usage: pdf_check_selftest.sh BOOK_TOOL" >&2; exit 2; }
tool=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# A raster figure (Chromium prints an SVG as vector art, not as an image): an SVG page printed
# to PDF by the book's print script, then made a PNG by pdftoppm.
mkdir -p "$work/figsrc"
printf '<!DOCTYPE html><html lang="en"><head><title>f</title></head><body><svg xmlns="http://www.w3.org/2000/svg" width="400" height="300"><rect width="400" height="300" fill="#888"/><circle cx="200" cy="150" r="90" fill="#222"/></svg></body></html>' > "$work/figsrc/print.html"
bash "$here/print_book.sh" "$work/figsrc" "$work/figsrc/fig.pdf" > /dev/null
pdftoppm -png -r 30 -singlefile "$work/figsrc/fig.pdf" "$work/fig"
para='<p>Lorem text of a chapter that fills the page, line after line, as the real book does, so that the measured ink reaches the foot of the sheet. It goes on and on with ordinary words.</p>'
fill=""
for _ in $(seq 1 16); do fill+=$para; done
book() {  # book NAME BODY_OF_CHAPTER_1 [FIGURES]
  cat > "$work/$1.html" <<EOF
<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"><title>$1</title>
<link rel="stylesheet" href="$here/book.css"></head><body><div id="doc-content">
<nav class="printtoc" aria-label="Contents"><h1>Contents</h1><ol>
<li><a href="#print_a">Chapter one of the test</a></li><li><a href="#print_b">Chapter two of the test</a></li></ol></nav>
<section class="printpage" id="print_a"><div class="header"><div class="headertitle"><div class="title">Chapter one of the test</div></div></div>
<div class="contents">$2</div></section>
<section class="printpage" id="print_b"><div class="header"><div class="headertitle"><div class="title">Chapter two of the test</div></div></div>
<div class="contents">$fill<p>The end.</p></div></section>
</div></body></html>
EOF
}
figure='<figure class="image"><img src="fig.png" alt="a dark disc on grey"><figcaption class="caption">Figure one: a dark disc on a grey square.</figcaption></figure>'
book good "$fill$figure$fill"
book half "$para<div style=\"break-before: page\"></div>$fill$figure"
pdf() {  # pdf NAME: NAME.pdf from NAME.html, through the book's own print script
  mkdir -p "$work/$1.d"; cp "$work/$1.html" "$work/$1.d/print.html"; cp "$work/fig.png" "$work/$1.d/"
  bash "$here/print_book.sh" "$work/$1.d" "$work/$1.pdf" > /dev/null
}
pdf good; pdf half
# The figure missing: the good book's PDF against a page that holds one figure more.
sed "s|$figure|$figure${figure//Figure one/Figure two}|" "$work/good.html" > "$work/twofig.html"

fail=0
expect() {  # expect WANT STATUS ARGS...: the check's exit status and a line matching WANT
  local want=$1 status=$2 out s=0; shift 2
  out=$(bash "$here/pdf_check.sh" --book-tool "$tool" "$@" 2>&1) || s=$?
  [ "$s" = "$status" ] || { echo "FAIL: exit $s (expected $status) for $*: $out" >&2; fail=1; }
  grep -q -- "$want" <<< "$out" || { echo "FAIL: no line matches '$want' for $*: $out" >&2; fail=1; }
}
expect 'pdf_check: .*good.pdf: .* pages' 0 --max-pages 50 "$work/good.pdf" "$work/good.html"
expect 'page 2 is more than half empty' 1 --max-pages 50 "$work/half.pdf" "$work/half.html"
expect 'images for 2 figures' 1 --max-pages 50 "$work/good.pdf" "$work/twofig.html"
expect 'the caption "Figure two: a dark disc' 1 --max-pages 50 "$work/good.pdf" "$work/twofig.html"
expect 'pages, more than the bound of 1' 1 --max-pages 1 "$work/good.pdf" "$work/good.html"
[ $fail = 0 ] && echo "pdf check self-test: a half-empty page, a missing figure and a page bound found; the good book passes"
exit $fail
