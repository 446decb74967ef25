#!/usr/bin/env bash
# The printed book checked (poppler-utils): at most MAX pages; every figure of the printed HTML
# is in the PDF (as many images as figures, and each caption's first words in its text); no
# page is more than half empty unless the next page starts a chapter (a page of the book's
# reading order) or it is the last. One line per defect, naming the page.
# Exit status: 0 when there is none, 1 when there is one, 2 on bad usage.
#
#   bash book/pdf_check.sh --max-pages MAX --book-tool BOOK_TOOL OUT.pdf PRINT.html
set -euo pipefail
max="" tool=""
while [ $# -gt 0 ]; do
  case $1 in
    --max-pages) max=${2:-}; shift 2 ;;
    --book-tool) tool=${2:-}; shift 2 ;;
    *) break ;;
  esac
done
[ $# -eq 2 ] && [[ "$max" =~ ^[0-9]+$ ]] && [ -x "$tool" ] ||
  { echo "usage: pdf_check.sh --max-pages MAX --book-tool BOOK_TOOL OUT.pdf PRINT.html" >&2; exit 2; }
pdf=$1 html=$2
[ -f "$pdf" ] && [ -f "$html" ] || { echo "pdf_check: no '$pdf' or no '$html'" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
bad=0
defect() { echo "pdf: $*" >&2; bad=$((bad + 1)); }

pages=$(pdfinfo "$pdf" | awk '/^Pages:/ { print $2 }')
[ -n "$pages" ] || { echo "pdf_check: pdfinfo cannot read '$pdf'" >&2; exit 1; }
[ "$pages" -le "$max" ] || defect "$pages pages, more than the bound of $max"

# Figures: the printed HTML's <figure> elements against the PDF's images and text.
figures=$( (grep -o '<figure class="image"' "$html" || true) | wc -l)
images=$(pdfimages -list "$pdf" | awk 'NR > 2 && $3 == "image"' | wc -l)
[ "$images" -ge "$figures" ] || defect "$images images for $figures figures"
pdftotext -enc UTF-8 "$pdf" - | tr -s ' \n\t' '   ' > "$work/text"
# Each caption's first five words (when they are plain words: no formula) must be printed.
tr '\n' ' ' < "$html" | { grep -o '<figcaption[^>]*>[^<]*' || true; } | sed 's/<figcaption[^>]*>//' |
  while IFS= read -r cap; do
    words=$(tr -s ' \t' '  ' <<< "$cap" | sed 's/^ //' | cut -d' ' -f1-5)
    case $words in *\\*|*\$*|*\&*|'') continue ;; esac
    grep -qF -- "$words" "$work/text" || echo "pdf: the caption \"$words ...\" is not in the PDF"
  done > "$work/captions" 2>&1
if [ -s "$work/captions" ]; then cat "$work/captions" >&2; bad=$((bad + $(wc -l < "$work/captions"))); fi

# Half-empty pages. The first line of the next page tells whether a chapter starts there: the
# titles are the contents list's entries.
tr '\n' ' ' < "$html" | { grep -o '<nav class="printtoc".*</nav>' || true; } | { grep -o '<li><a [^>]*>[^<]*' || true; } |
  sed 's/<li><a [^>]*>//' | tr -s ' ' ' ' > "$work/titles"
pdftoppm -gray -r 12 "$pdf" "$work/page"
"$tool" pagefill "$work"/page-*.pgm | sort -t- -k2 -n > "$work/fill"
k=0
while read -r file share; do
  k=$((k + 1))
  [ "$k" -lt "$pages" ] || continue
  awk -v s="$share" 'BEGIN { exit !(s < 0.5) }' || continue
  # (awk stops reading at the first line: pdftotext may then die of SIGPIPE, which is fine.)
  first=$( { pdftotext -enc UTF-8 -f $((k + 1)) -l $((k + 1)) "$pdf" - || true; } | awk 'NF { print; exit }' | tr -s ' ' ' ')
  chapter=0
  while IFS= read -r t; do
    [ -n "$first" ] && [ "${t#"$first"}" != "$t" ] && chapter=1 && break
    [ -n "$first" ] && [ "${first#"$t"}" != "$first" ] && chapter=1 && break
  done < "$work/titles"
  [ $chapter = 1 ] || defect "page $k is more than half empty (ink down to $share of its height) and no chapter starts after it (${file##*/})"
done < "$work/fill"

if [ $bad -gt 0 ]; then
  echo "pdf_check: $bad defects in $pdf ($pages pages)" >&2
  exit 1
fi
echo "pdf_check: $pdf: $pages pages (bound $max), $figures figures with their captions, no half-empty page inside a chapter"
