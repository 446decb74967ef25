# The answer values of book/solutions.md ("<!-- values: a | b -->", passed as -v values, one per
# line) in the lines of the files given, found as the book's edition check finds them: white
# space squeezed (kept only between two letters or digits), adjacent string literals joined,
# "\n" in a literal read as a line break, and a value only as a whole (4k is not in 4kB).
# -v mode=list prints FILE:LINE:VALUE for every line holding one; -v mode=strip prints the file
# (one file only) with such a line left out when it is a comment line, its trailing // comment
# cut when the code before it holds no value, and lists on stderr the lines it cannot clean.
function squeeze(s,    o, i, c, prev, next_) {
  gsub(/"[ \t]*"/, "", s)          # adjacent string literals are one literal
  gsub(/\\n/, " ", s)
  gsub(/[ \t\r]+/, " ", s)
  o = ""
  for (i = 1; i <= length(s); i++) {
    c = substr(s, i, 1)
    if (c == " ") {
      prev = substr(s, i - 1, 1); next_ = substr(s, i + 1, 1)
      if (prev ~ /[A-Za-z0-9_]/ && next_ ~ /[A-Za-z0-9_]/) o = o " "
      continue
    }
    o = o c
  }
  return o
}
function holds(line, v,    k, from, b, a) {
  from = 1
  while ((k = index(substr(line, from), v)) > 0) {
    k += from - 1
    b = substr(line, k - 1, 1); a = substr(line, k + length(v), 1)
    if (!(substr(v, 1, 1) ~ /[A-Za-z0-9_]/ && b ~ /[A-Za-z0-9_]/) && !(substr(v, length(v), 1) ~ /[A-Za-z0-9_]/ && a ~ /[A-Za-z0-9_]/)) return 1
    from = k + 1
  }
  return 0
}
BEGIN { n = split(values, raw, "\n"); for (i = 1; i <= n; i++) val[i] = squeeze(raw[i]) }
function found(text,    i) {
  text = squeeze(text)
  for (i = 1; i <= n; i++) if (val[i] != "" && holds(text, val[i])) return raw[i]
  return ""
}
{
  v = found($0)
  if (mode == "list") { if (v != "") print FILENAME ":" FNR ":" v; next }
  if (v == "") { print; next }
  if ($0 ~ /^[ \t]*(\/\/|\/\*|\*|#)/) next
  code = $0; sub(/[ \t]*\/\/.*$/, "", code)
  if (code != $0 && found(code) == "") { print code; next }
  print FILENAME ":" FNR ": holds the answer " v > "/dev/stderr"
  print
  bad = 1
}
END { exit bad }
