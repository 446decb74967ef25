#!/usr/bin/env bash
# Runs a test page of the live figures (web/test.js) in headless Chromium from file:// and
# reads the verdict the page wrote into its DOM (ctest web_browser, web_browser_planted).
#
#   bash web/run_browser_test.sh PAGE.html                       passes iff the page says PASS
#   bash web/run_browser_test.sh PAGE.html --expect-fail TEXT    passes iff the page says FAIL
#                                   and a comparison named TEXT failed on a difference it found
#                                   (not on an exception)
#   ... --reduced-motion            the page is told the reader prefers reduced motion
# The window is 1280 px wide; test_390.html runs test.html in a frame 390 px wide (a phone's:
# headless Chromium keeps its window at least 500 px wide).
set -euo pipefail
page=$1
shift
mode='' want='' motion=()
while [ $# -gt 0 ]; do
  case $1 in
    --expect-fail) mode=--expect-fail; want=${2:?--expect-fail needs a text}; shift 2 ;;
    --reduced-motion) motion=(--force-prefers-reduced-motion); shift ;;
    *) echo "run_browser_test.sh: unknown option $1" >&2; exit 2 ;;
  esac
done
[ -f "$page" ] || { echo "run_browser_test.sh: $page: no such page (build the target web)" >&2; exit 2; }
profile=$(mktemp -d)
out=$(mktemp)
trap 'rm -rf "$profile" "$out" "$out.err"' EXIT
# Virtual time lets the page's scripts run to the end; the budget is far more than they need.
timeout 600 chromium --headless --no-sandbox --disable-gpu --disable-background-networking \
  --disable-component-update --disable-sync --no-first-run --user-data-dir="$profile" \
  --allow-file-access-from-files --window-size=1280,2000 "${motion[@]}" --virtual-time-budget=600000 \
  --dump-dom "file://$(cd "$(dirname "$page")" && pwd)/$(basename "$page")" > "$out" 2> "$out.err" || {
  echo "run_browser_test.sh: chromium failed:" >&2
  tail -n 20 "$out.err" >&2
  exit 1
}
# The verdict block: <pre id="verdict">...</pre>
verdict=$(sed -n '/<pre id="verdict">/,/<\/pre>/p' "$out" | sed 's/<[^>]*>//g')
printf '%s\n' "$verdict" | grep -v '^PASS ' || true
echo "$(printf '%s\n' "$verdict" | grep -c '^PASS ') checks passed"
if [ "$mode" = --expect-fail ]; then
  if printf '%s\n' "$verdict" | grep -q '^RESULT: FAIL' &&
     printf '%s\n' "$verdict" | grep '^FAIL ' | grep -F -- "$want" | grep -q 'first difference'; then
    echo "the page failed on '$want', as it must with the planted defect"
    exit 0
  fi
  echo "run_browser_test.sh: expected a failed check naming '$want'" >&2
  exit 1
fi
printf '%s\n' "$verdict" | grep -q '^RESULT: PASS'
