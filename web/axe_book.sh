#!/usr/bin/env bash
# axe-core on every page of a built book that holds a live figure, after driving each figure with
# keys (focus, arrows, Shift+arrow, Enter, Space): no WCAG 2.1 A/AA violation may be found.
#
#   bash web/axe_book.sh HTML_DIR AXE.js     e.g. build/book/student node_modules/axe-core/axe.min.js
#
# Each page is loaded in a frame of a harness page (as book/layout_check.sh does), axe-core is
# put into the frame, and one line per violation names the page, the rule and the elements.
# Exit 0 iff none; 1 on a violation or no verdict; 2 on bad arguments; 77 (a skipped ctest
# entry) when the directory holds no page with a live figure (the book was not built).
set -euo pipefail
# shellcheck source=SCRIPTDIR/../book/headless.sh
. "$(cd "$(dirname "$0")/../book" && pwd)/headless.sh"
[ $# -eq 2 ] || { echo "usage: axe_book.sh HTML_DIR AXE.js" >&2; exit 2; }
dir=$(cd "$1" 2>/dev/null && pwd) || { echo "axe_book: no directory '$1'" >&2; exit 77; }
axe=$(cd "$(dirname "$2")" && pwd)/$(basename "$2")
[ -f "$axe" ] || { echo "axe_book: no axe-core at $2 (scripts/deps.sh installs it)" >&2; exit 2; }
pages=()
while IFS= read -r -d '' f; do
  # The printed book shows each live figure's static figure: nothing there loads or is driven
  # (book/axe_check.sh checks it as a page).
  [ "$(basename "$f")" = print.html ] && continue
  grep -q 'class="dt-live"' "$f" && pages+=("$f")
done < <(find "$dir" -maxdepth 1 -name '*.html' -print0 | sort -z)
[ ${#pages[@]} -gt 0 ] || { echo "axe_book: no page with a live figure in $dir"; exit 77; }
for p in "${pages[@]}" "$axe"; do
  case $p in *[\"\\$'\n']*) echo "axe_book: a path this script cannot quote: $p" >&2; exit 2 ;; esac
done

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
list=""
for p in "${pages[@]}"; do list+="${list:+,}\"file://$p\""; done
cat > "$work/harness.html" <<EOF
<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"><title>axe on the book</title></head><body>
<iframe id="frame" width="1280" height="1000" title="a page of the book"></iframe><pre id="result">pending</pre>
<script>
var pages = [$list], lines = [], frame = document.getElementById("frame");
function key(doc, node, k, shift) {
  node.focus();
  doc.activeElement.dispatchEvent(new KeyboardEvent("keydown", { key: k, shiftKey: !!shift, bubbles: true, cancelable: true }));
}
function next(i) {
  if (i === pages.length) {
    document.getElementById("result").textContent = lines.join("\\n") + "\\nAXE " +
      lines.filter(function (l) { return l.indexOf("VIOLATION") === 0; }).length + " violations in " + pages.length + " pages";
    return;
  }
  var name = pages[i].replace(/.*\\//, ""), waited = 0;
  frame.onload = function () {
    var w = frame.contentWindow, doc = frame.contentDocument;
    (function poll() {
      // Built: every live element holds a figure (or the loader's message that it could not be).
      var live = doc.querySelectorAll(".dt-live"), built = doc.querySelectorAll(".dt-live-figure");
      if (built.length < live.length && (waited += 100) < 60000) return setTimeout(poll, 100);
      if (built.length < live.length) lines.push("VIOLATION " + name + ": the live figure did not load");
      doc.querySelectorAll(".dt-live [tabindex='0']").forEach(function (node) {
        ["ArrowRight", "ArrowUp", "Enter", " "].forEach(function (k) { key(doc, node, k); });
        key(doc, node, "ArrowLeft", true);
      });
      var s = doc.createElement("script");
      s.src = "file://$axe";
      s.onload = function () {
        w.axe.run(doc, { runOnly: { type: "tag", values: ["wcag2a", "wcag2aa", "wcag21a", "wcag21aa"] } }).then(function (r) {
          r.violations.forEach(function (v) {
            lines.push("VIOLATION " + name + ": " + v.id + " (" + v.help + "): " +
              v.nodes.slice(0, 3).map(function (n) { return n.target.join(" "); }).join(", "));
          });
          lines.push("checked " + name + ": " + built.length + " live figure(s), " + r.passes.length + " rules passed");
          next(i + 1);
        }, function (e) { lines.push("VIOLATION " + name + ": axe failed: " + e); next(i + 1); });
      };
      s.onerror = function () { lines.push("VIOLATION " + name + ": axe-core did not load"); next(i + 1); };
      doc.head.appendChild(s);
    })();
  };
  frame.src = pages[i];
}
next(0);
</script></body></html>
EOF
budget=$(( ${#pages[@]} * 120000 + 10000 ))
result=$(headless_verdict "$work" "$budget" 1300,1100 result)
printf '%s\n' "$result"
last=$(tail -n 1 <<< "$result")
[[ "$last" =~ ^AXE\ ([0-9]+)\ violations ]] || { echo "axe_book: the browser gave no verdict" >&2; exit 1; }
[ "${BASH_REMATCH[1]}" = 0 ]
