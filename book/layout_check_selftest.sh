#!/usr/bin/env bash
# The layout check checked: pages with a planted defect each (a widened table, an over-wide
# image, a code block wider than the column, a cut-off caption, a page wider than the window)
# must each be named, and a page that fits must pass. The pages imitate Doxygen's structure
# (div#doc-content > div.contents, the book's previous/next bar) with the book's own CSS, in a
# directory whose name holds a space, a quote and a non-ASCII letter.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
dir="$work/book d'é"
mkdir -p "$dir"
cp "$here/book.css" "$dir/book.css"
page() {  # page NAME BODY
  cat > "$dir/$1" <<EOF
<!DOCTYPE html><html><head><meta charset="utf-8"><link rel="stylesheet" href="book.css">
<style>body{margin:0;font-family:sans-serif} #doc-content{margin-left:250px;overflow:auto}
div.contents{padding:0 20px}</style></head><body>
<div id="doc-content"><div class="contents"><div class="booknav">prev | next</div>
$2
</div></div></body></html>
EOF
}
# 64 px wide: an image the harness can load from file://.
echo '<svg xmlns="http://www.w3.org/2000/svg" width="64" height="8"><rect width="64" height="8" fill="#ccc"/></svg>' > "$dir/dot.svg"
row='<tr><td>1</td><td>2</td></tr>'
page good.html "<p>Text that wraps as it likes.</p><table class=\"markdownTable\"><tr><th>n</th><th>time</th></tr>$row</table><div class=\"image\"><img src=\"dot.svg\"></div><pre>short code</pre>"
page wide_table.html "<table class=\"markdownTable\"><tr><th>a_very_long_header_that_cannot_wrap_anywhere_at_all_because_it_is_one_word_of_many_many_letters_xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx</th><th>b</th></tr>$row</table>"
page wide_image.html '<div class="image"><img src="dot.svg" style="width:1400px;max-width:none"></div>'
page wide_code.html "<div class=\"fragment\" style=\"overflow:hidden\"><div class=\"line\" style=\"white-space:pre\">$(printf 'x%.0s' $(seq 1 400))</div></div>"
page cut_caption.html '<div class="caption" style="white-space:nowrap;overflow:hidden;width:200px">Figure 9: a caption much longer than the two hundred pixels it is given, so it is cut off</div>'
page wide_page.html '<div style="position:absolute;left:0;width:3000px;height:10px"></div><p>fits</p>'

fail=0
# The whole directory at once (the default page list): each planted defect named, with its
# page, width and element; the good page never.
status=0
out=$(bash "$here/layout_check.sh" --widths 1024,1280 "$dir" 2>&1) || status=$?
[ "$status" = 1 ] || { echo "FAIL: exit $status, expected 1" >&2; fail=1; }
for want in 'wide_table.html @1024px: table.markdownTable "a_very_long_header.* scrolls sideways' \
            'wide_image.html @1280px: img src=dot.svg is 1400 px wide, .* px past the text column' \
            'wide_code.html @1024px: div.fragment.* scrolls sideways' \
            'cut_caption.html @1024px: div.caption.* is cut off' \
            'wide_page.html @1280px: the page scrolls sideways' \
            'layout defects in 12 page loads'; do
  grep -q -- "$want" <<< "$out" || { echo "FAIL: no line matches '$want'" >&2; fail=1; }
done
if grep -q 'good.html' <<< "$out"; then echo "FAIL: the good page was blamed" >&2; fail=1; fi
# The good page alone passes.
if ! good=$(bash "$here/layout_check.sh" "$dir" good.html 2>&1); then
  echo "FAIL: the good page alone failed: $good" >&2; fail=1
fi
if [ $fail = 0 ]; then
  echo "layout check self-test: 5 planted defects found, the good page passes"
else
  echo "--- the check's output:" >&2; grep -v dbus <<< "$out" >&2
fi
exit $fail
