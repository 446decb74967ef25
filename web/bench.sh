#!/usr/bin/env bash
# Speed of the live figures (not a test): the pointer-move-to-redraw time of the cavity figure
# with 10^4 points, and 10^6 uniform points triangulated by dt::fastDelaunay in WebAssembly
# (headless Chromium, real time: virtual time would stop the clocks) and natively (web_native_cases --bench), same points, same function.
#
#   bash web/bench.sh BUILD_DIR [N]      prints "key value" lines (N = 1000000 by default)
set -euo pipefail
build=$1
n=${2:-1000000}
web=$build/web
profile=$(mktemp -d)
trap 'rm -rf "$profile"' EXIT
read -r native triangles < <("$web/web_native_cases" --bench "$n")
page=$(timeout 900 chromium --headless --no-sandbox --disable-gpu --disable-background-networking \
  --disable-component-update --disable-sync --no-first-run --user-data-dir="$profile" \
  --allow-file-access-from-files --window-size=1280,1000 --timeout=240000 \
  --dump-dom "file://$(cd "$web" && pwd)/bench.html?$n" 2> /dev/null)
values=$(printf '%s\n' "$page" | sed -n '/<pre id="bench">/,/<\/pre>/p' | sed 's/<[^>]*>//g')
printf '%s\n' "$values" | grep -q '^DONE' || { echo "bench.sh: the page did not finish: $values" >&2; exit 1; }
printf '%s\n' "$values" | grep '^web\.'
echo "web.native_seconds $native"
echo "web.native_triangles $triangles"
wasm=$(printf '%s\n' "$values" | awk '$1 == "web.wasm_seconds" { print $2 }')
awk -v w="$wasm" -v s="$native" 'BEGIN { printf "web.wasm_over_native %.2f\n", w / s }'
echo "web.points $n"
