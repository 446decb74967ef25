#!/usr/bin/env bash
# The book's accessibility, checked by axe-core (node_modules/axe-core, pinned by
# package-lock.json) in headless Chromium with the WCAG 2.0 and 2.1 A and AA rules: every page
# of the book (the pages with the book's previous/next bar; or the pages given) is loaded at
# 1280 px, its formulas typeset, and every failing element printed, one line each, naming the
# page, the rule and the element (book/axe_probe.js does the running).
# What axe cannot judge (focus order, whether an alt text says what a figure shows) is checked
# by hand: book/ACCESSIBILITY.md.
# Exit status: 0 when there is none, 1 when there is one, 2 on bad usage.
#
#   bash book/axe_check.sh HTML_DIR [PAGE.html ...]
#   bash book/axe_check.sh --editions BOOK_DIR   both editions (BOOK_DIR/student, /teacher);
#                                                 exit 77 when the book is not built
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
# shellcheck source=SCRIPTDIR/headless.sh
. "$here/headless.sh"
if [ "${1:-}" = --editions ]; then
  [ $# -eq 2 ] || { echo "usage: axe_check.sh --editions BOOK_DIR" >&2; exit 2; }
  for e in student teacher; do
    [ -f "$2/$e/index.html" ] || { echo "axe_check: no book in $2/$e (bash scripts/main.sh builds it)"; exit 77; }
  done
  status=0
  for e in student teacher; do bash "$0" "$2/$e" || status=1; done
  exit $status
fi
axe="$here/../node_modules/axe-core/axe.min.js"
[ -f "$axe" ] || { echo "axe_check: no $axe (bash scripts/deps.sh installs it: npm ci)" >&2; exit 2; }
axe=$(cd "$(dirname "$axe")" && pwd)/axe.min.js
[ $# -ge 1 ] || { echo "usage: axe_check.sh HTML_DIR [PAGE.html ...]" >&2; exit 2; }
dir=$(cd "$1" && pwd) || { echo "axe_check: no directory '$1'" >&2; exit 2; }
shift
pages=()
if [ $# -gt 0 ]; then
  pages=("$@")
else
  while IFS= read -r -d '' f; do
    # print.html (the printed book) repeats the pages; it is checked as a PDF.
    [ "$(basename "$f")" != print.html ] && grep -q 'class="booknav"' "$f" && pages+=("$(basename "$f")")
  done < <(find "$dir" -maxdepth 1 -name '*.html' -print0 | sort -z)
fi
[ ${#pages[@]} -gt 0 ] || { echo "axe_check: no book page in $dir" >&2; exit 2; }

# A whole directory that passed is stamped (DIR/.axe_passed) with one hash over every file in it
# (pages, styles, images, scripts) and over this check's own files: the book's build checks each
# edition, and ctest's entry, given the same bytes, says so instead of spending two minutes of
# Chromium on them again. Any changed, added or removed file, or a new axe, misses the stamp.
# DT_AXE_FRESH=1 checks anyway.
stamp_file="$dir/.axe_passed"
stamp=""
if [ $# -eq 0 ]; then
  stamp=$( { (cd "$dir" && find . -type f ! -name .axe_passed -print0 | LC_ALL=C sort -z |
                xargs -0 -r sha256sum)
             sha256sum "$axe" "$here/axe_probe.js" "$here/axe_check.sh" "$here/headless.sh"; } |
           sha256sum | cut -d' ' -f1)
  if [ "${DT_AXE_FRESH:-0}" != 1 ] && [ -f "$stamp_file" ] && [ "$(cat "$stamp_file")" = "$stamp" ]; then
    echo "axe_check: ${#pages[@]} pages, no WCAG 2.1 A/AA violation (the same files passed before: $stamp_file)"
    exit 0
  fi
  rm -f "$stamp_file"
fi

url='function (p) { return "file://" + p.split("/").map(encodeURIComponent).join("/"); }'
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
list=""
for p in "${pages[@]}"; do
  [ -f "$dir/$p" ] || { echo "axe_check: no page '$p' in $dir" >&2; exit 2; }
  list+="${list:+,}$(js_string axe_check "$dir/$p")"
done
cp "$here/axe_probe.js" "$work/axe_probe.js"
{
  echo '<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"><title>axe</title></head><body>'
  echo '<iframe id="axe-frame" title="page under test" style="border:0"></iframe><pre id="axe-result">pending</pre>'
  echo "<script>var u = $url;"
  echo "window.AXE_CHECK = {pages: [$list].map(u), axe: u($(js_string axe_check "$axe")), width: 1280, timeoutMs: 90000};</script>"
  echo '<script src="axe_probe.js"></script></body></html>'
} > "$work/harness.html"

budget=$(( ${#pages[@]} * 90000 + 10000 ))
result=$(headless_verdict "$work" "$budget" 1600,1000 axe-result)
last=$(tail -n 1 <<< "$result")
if [[ ! "$last" =~ ^AXE\ ([0-9]+)\ violations\ in\ ([0-9]+)\ pages ]]; then
  echo "axe_check: the browser gave no verdict (Chromium's log):" >&2
  tail -n 5 "$work/chromium.log" >&2 || true
  exit 1
fi
n=${BASH_REMATCH[1]} checked=${BASH_REMATCH[2]}
if [ "$n" -gt 0 ] || [ "$checked" -ne ${#pages[@]} ]; then
  head -n -1 <<< "$result" | sed 's/^/axe: /' >&2
  echo "axe_check: $n violations (WCAG 2.1 A/AA) in $checked of ${#pages[@]} pages" >&2
  exit 1
fi
[ -z "$stamp" ] || echo "$stamp" > "$stamp_file"
echo "axe_check: ${#pages[@]} pages, no WCAG 2.1 A/AA violation"
