#!/usr/bin/env bash
# The book's layout, measured in headless Chromium (book/layout_probe.js does the measuring):
# every page of the book (the pages with the book's previous/next bar; or the pages given) is
# rendered at each window width, and any table, image, code block, caption or live figure
# wider than the text column, any sideways scroll bar inside the text, and any page that
# scrolls sideways is printed, one line each, naming the page, the width and the element.
# Exit status: 0 when there is none, 1 when there is one, 2 on bad usage.
#
#   bash book/layout_check.sh [--widths 1024,1280] HTML_DIR [PAGE.html ...]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
# shellcheck source=SCRIPTDIR/headless.sh
. "$here/headless.sh"
widths=1024,1280
if [ "${1:-}" = --widths ]; then
  [ $# -ge 2 ] || { echo "layout_check: --widths needs a value, e.g. 1024,1280" >&2; exit 2; }
  widths=$2; shift 2
fi
[[ "$widths" =~ ^[0-9]+(,[0-9]+)*$ ]] || { echo "layout_check: bad --widths '$widths'" >&2; exit 2; }
[ $# -ge 1 ] || { echo "usage: layout_check.sh [--widths W1,W2] HTML_DIR [PAGE.html ...]" >&2; exit 2; }
dir=$(cd "$1" && pwd) || { echo "layout_check: no directory '$1'" >&2; exit 2; }
shift
pages=()
if [ $# -gt 0 ]; then
  pages=("$@")
else
  while IFS= read -r -d '' f; do
    grep -q 'class="booknav"' "$f" && pages+=("$(basename "$f")")
  done < <(find "$dir" -maxdepth 1 -name '*.html' -print0 | sort -z)
fi
[ ${#pages[@]} -gt 0 ] || { echo "layout_check: no book page in $dir" >&2; exit 2; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
list=""
for p in "${pages[@]}"; do
  [ -f "$dir/$p" ] || { echo "layout_check: no page '$p' in $dir" >&2; exit 2; }
  list+="${list:+,}$(js_string layout_check "$dir/$p")"
done
cp "$here/layout_probe.js" "$work/layout_probe.js"
{
  echo '<!DOCTYPE html><html><head><meta charset="utf-8"></head><body>'
  echo '<iframe id="layout-frame" style="border:0"></iframe><pre id="layout-result">pending</pre>'
  echo "<script>window.LAYOUT_CHECK = {pages: [$list].map(function (p) {"
  echo "  return 'file://' + p.split('/').map(encodeURIComponent).join('/'); }),"
  echo "  widths: [$widths], height: 900, timeoutMs: 60000};</script>"
  echo '<script src="layout_probe.js"></script></body></html>'
} > "$work/harness.html"

n=$(( ${#pages[@]} * $(tr ',' '\n' <<< "$widths" | wc -l) ))
budget=$(( n * 60000 + 10000 ))
result=$(headless_verdict "$work" "$budget" 1600,1000 layout-result)
last=$(tail -n 1 <<< "$result")
if [[ ! "$last" =~ ^LAYOUT\ ([0-9]+)\ defects ]]; then
  echo "layout_check: the browser gave no verdict (Chromium's log: $work/chromium.log):" >&2
  tail -n 5 "$work/chromium.log" >&2 || true
  exit 1
fi
defects=${BASH_REMATCH[1]}
if [ "$defects" -gt 0 ]; then
  head -n -1 <<< "$result" | sed 's/^/layout: /' >&2
  echo "layout_check: $defects layout defects in $n page loads (widths $widths px)" >&2
  exit 1
fi
echo "layout_check: ${#pages[@]} pages fit at $widths px ($n page loads)"
