# shellcheck shell=bash
# Sourced by the book's and the live figures' browser checks (book/axe_check.sh,
# book/layout_check.sh, web/axe_book.sh): one way to load a harness page in headless Chromium
# and read its verdict, so that a flag or a parsing fix is made once.

# A path as a JavaScript string literal; $1 names the calling tool in the error.
js_string() {
  local s=$2
  case $s in *$'\n'*|*$'\r'*) echo "$1: a path with a line break: '$s'" >&2; exit 2 ;; esac
  s=${s//\\/\\\\}; s=${s//\"/\\\"}
  printf '"%s"' "$s"
}

# headless_verdict WORK BUDGET_MS WINDOW PRE_ID: loads WORK/harness.html (the window
# W,H pixels, the virtual time budget in ms, a fresh profile in WORK) and prints the text of its
# <pre id="PRE_ID">, entities decoded; Chromium's messages go to WORK/chromium.log.
headless_verdict() {
  local work=$1 budget=$2 window=$3 id=$4
  chromium --headless --no-sandbox --disable-gpu --disable-background-networking \
    --disable-component-update --disable-sync --no-first-run --mute-audio \
    --user-data-dir="$work/profile" --allow-file-access-from-files --window-size="$window" \
    --virtual-time-budget="$budget" --dump-dom "file://$work/harness.html" \
    > "$work/dom.html" 2> "$work/chromium.log" || true
  awk -v open="<pre id=\"$id\">" '{ buf = buf $0 "\n" } END {
        i = index(buf, open); if (!i) exit
        buf = substr(buf, i + length(open)); j = index(buf, "</pre>"); printf "%s", substr(buf, 1, j - 1) }' \
      "$work/dom.html" | sed -e 's/<[^>]*>//g' -e 's/&lt;/</g' -e 's/&gt;/>/g' -e 's/&quot;/"/g' -e 's/&amp;/\&/g'
}
