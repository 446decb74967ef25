#!/usr/bin/env bash
# The accessibility check checked: pages with one planted violation each (no lang on <html>,
# a figure without alt text, orange text too pale to read, a search box without a label, a
# link with nothing to read) must each be named with its rule, and a page without any must
# pass. The pages sit in a directory whose name holds a space, a quote and a non-ASCII letter.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
dir="$work/book d'é"
mkdir -p "$dir"
page() {  # page NAME LANG BODY
  cat > "$dir/$1" <<EOF
<!DOCTYPE html><html$2><head><meta charset="utf-8"><title>$1</title></head><body><main>
<div class="booknav">previous | next</div><h1>A page</h1>
$3
</main></body></html>
EOF
}
echo '<svg xmlns="http://www.w3.org/2000/svg" width="64" height="8"><rect width="64" height="8" fill="#ccc"/></svg>' > "$dir/dot.svg"
good='<p>Plain text.</p><figure><img src="dot.svg" alt="a grey bar"><figcaption>A bar.</figcaption></figure>'
page good.html ' lang="en"' "$good"
page no_lang.html '' "$good"
page no_alt.html ' lang="en"' '<figure><img src="dot.svg"><figcaption>A bar.</figcaption></figure>'
page pale.html ' lang="en"' '<p style="color:#e08000">code keyword orange on white</p>'
page search.html ' lang="en"' '<input type="text" id="MSearchField" value="Search">'
page empty_link.html ' lang="en"' '<p>See <a href="good.html"><img src="dot.svg" alt=""></a>.</p>'

fail=0
status=0
out=$(bash "$here/axe_check.sh" "$dir" 2>&1) || status=$?
[ "$status" = 1 ] || { echo "FAIL: exit $status, expected 1" >&2; fail=1; }
for want in 'no_lang.html: html-has-lang' 'no_alt.html: image-alt' 'pale.html: color-contrast' \
            'search.html: label' 'empty_link.html: link-name' \
            'axe_check: 5 violations .* in 6 of 6 pages'; do
  grep -q -- "$want" <<< "$out" || { echo "FAIL: no line matches '$want'" >&2; fail=1; }
done
if grep -q 'good.html' <<< "$out"; then echo "FAIL: the good page was blamed" >&2; fail=1; fi
if ! g=$(bash "$here/axe_check.sh" "$dir" good.html 2>&1); then
  echo "FAIL: the good page alone failed: $g" >&2; fail=1
fi
# The stamp of a directory that passed: the same files again are not checked again, but a page
# changed after the stamp (here a violation planted in it) or any other file changed is.
clean="$work/clean"
mkdir -p "$clean"
cp "$dir/good.html" "$dir/dot.svg" "$clean/"
if ! c1=$(bash "$here/axe_check.sh" "$clean" 2>&1) || [ ! -f "$clean/.axe_passed" ]; then
  echo "FAIL: a clean directory failed or got no stamp: $c1" >&2; fail=1
fi
c2=$(bash "$here/axe_check.sh" "$clean" 2>&1) || { echo "FAIL: the stamped directory failed: $c2" >&2; fail=1; }
grep -q 'the same files passed before' <<< "$c2" || { echo "FAIL: the stamp was not used: $c2" >&2; fail=1; }
echo '<svg xmlns="http://www.w3.org/2000/svg" width="64" height="8"/>' > "$clean/dot.svg"
c3=$(bash "$here/axe_check.sh" "$clean" 2>&1) || { echo "FAIL: after a new image: $c3" >&2; fail=1; }
if grep -q 'the same files passed before' <<< "$c3"; then echo "FAIL: a changed image kept the stamp" >&2; fail=1; fi
sed -i 's/<html lang="en">/<html>/' "$clean/good.html"
status=0
c4=$(bash "$here/axe_check.sh" "$clean" 2>&1) || status=$?
if [ "$status" != 1 ] || ! grep -q 'good.html: html-has-lang' <<< "$c4"; then
  echo "FAIL: a violation planted after the stamp was not found (exit $status): $c4" >&2; fail=1
fi
if [ $fail = 0 ]; then
  echo "axe check self-test: 5 planted violations found, the good page passes, a stamp hides no change"
else
  echo "--- the check's output:" >&2; cat <<< "$out" >&2
fi
exit $fail
