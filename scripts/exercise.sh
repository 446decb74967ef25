#!/usr/bin/env bash
# Classroom exercises: list them, give a student a copy of the project without one exercise's
# solution, check an attempt, and write a teacher's handout. The exercises are described in
# exercises/exercises.txt; solutions sit in code/ between "BEGIN SOLUTION <id>" and
# "END SOLUTION <id>" comment lines, and in book/solutions.md between the same markers.
#
#   scripts/exercise.sh list
#   scripts/exercise.sh start ID DIR           a buildable copy of the project without ID's solution
#   scripts/exercise.sh check ID [DIR]         build DIR (default: this checkout), run ID's tests
#   scripts/exercise.sh handout SECTION [OUT]  OUT/exercises_SECTION.md and OUT/solutions_SECTION.md
#   scripts/exercise.sh selftest BUILD [ID...] for each implement exercise: the stub compiles and
#                                              fails, the restored solution passes (fast: reuses
#                                              BUILD's objects, recompiles only the stripped files)
#   scripts/exercise.sh lint BUILD             every test named exists in BUILD/dt_tests, every
#                                              region and solution entry is where it is declared
# Exit status: 0 pass, 1 fail, 2 bad usage.
set -euo pipefail

HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
DB="$HERE/exercises/exercises.txt"
JOBS="${DT_EXERCISE_JOBS:-$(nproc 2>/dev/null || echo 2)}"

die() { echo "exercise.sh: $*" >&2; exit 2; }

# ---- reading exercises/exercises.txt ----------------------------------------------------------
# Records are blocks of "key: value" lines separated by blank lines; '#' starts a comment line.
# field ID KEY: every value of KEY in ID's record, one per line.
field() {
  awk -v id="$1" -v key="$2" '
    /^#/ { next }
    /^[ \t]*$/ { rec = ""; next }
    {
      k = $0; sub(/:.*/, "", k); v = $0; sub(/^[^:]*:[ \t]*/, "", v)
      if (k == "id") rec = v
      else if (rec == id && k == key) print v
    }' "$DB"
}
ids() { awk '/^id:/ { sub(/^id:[ \t]*/, ""); print }' "$DB"; }
exists() { ids | grep -qxF -- "$1" || die "no exercise '$1' (scripts/exercise.sh list)"; }
# The anchor of an exercise's entry in book/solutions.md: 2.3.4-1 -> sol_2_3_4_1.
anchor() { echo "sol_$(echo "$1" | tr '.-' '__')"; }

# ---- stripping one exercise's solution regions -------------------------------------------------
# strip_file ID FILE: FILE without ID's regions. In C++ a region becomes one line throwing
# std::logic_error (a region marked "(remove)" becomes nothing: helpers the stub no longer needs);
# in Markdown it disappears.
strip_file() {
  awk -v id="$1" -v md="$([[ $2 == *.md ]] && echo 1 || echo 0)" '
    function marks(line, word,    t, k, after) {
      t = word " SOLUTION " id; k = index(line, t)
      if (!k) return 0
      after = substr(line, k + length(t), 1)
      return after == "" || after == " "
    }
    !inside && marks($0, "BEGIN") {
      inside = 1
      if (!md && index($0, "(remove)") == 0) {
        indent = $0; sub(/[^ \t].*/, "", indent)
        print indent "throw std::logic_error(\"exercise " id ": not implemented yet\");"
      }
      next
    }
    inside && marks($0, "END") { inside = 0; next }
    !inside { print }
    END { if (inside) { print "unterminated solution region " id > "/dev/stderr"; exit 1 } }
  ' "$2"
}

# region_files ID ROOT: the files (relative to ROOT) holding a region of ID.
region_files() {
  (cd "$2" && grep -rlE --include='*.cpp' --include='*.h' --include='*.md' \
     "(BEGIN|END) SOLUTION $(echo "$1" | sed 's/\./\\./g')( |$)" code book 2>/dev/null || true) | sort
}

# tainted_snippets ID FILE: the Doxygen snippet markers of FILE ("//! [name]") whose block
# overlaps a region of ID: the book must not quote them once the region is gone.
tainted_snippets() {
  awk -v id="$1" '
    function marks(line, word,    t, k, after) {
      t = word " SOLUTION " id; k = index(line, t)
      if (!k) return 0
      after = substr(line, k + length(t), 1)
      return after == "" || after == " "
    }
    marks($0, "BEGIN") { inside = 1 }
    match($0, /\/\/! \[[^]]*\]/) {
      name = substr($0, RSTART + 5, RLENGTH - 6)
      if (name in open) { if (hit[name] || inside) print name; delete open[name]; delete hit[name] }
      else { open[name] = 1; hit[name] = inside }
    }
    inside { for (n in open) hit[n] = 1 }
    marks($0, "END") { inside = 0 }
  ' "$2" | sort -u
}

# strip_tree ID ROOT: strips ID in the copy ROOT (in place), and removes from its book every
# quotation of the stripped code and the link to the removed solution.
strip_tree() {
  local id="$1" root="$2" f tmp name
  local files; files="$(region_files "$id" "$root")"
  [ -n "$files" ] || return 0
  for f in $files; do
    if [[ $f == code/* ]]; then
      for name in $(tainted_snippets "$id" "$root/$f"); do
        # "\snippet code/x.cpp name" -> a note; the quoted code would be the solution.
        sed -i "s#^\\\\snippet $f $name\$#(The code of exercise $id is not shown in this workspace.)#" \
          "$root"/book/*.md
      done
    fi
    tmp="$(mktemp)"
    strip_file "$id" "$root/$f" >"$tmp"
    cat "$tmp" >"$root/$f"
    rm -f "$tmp"
  done
  # Links to the removed entry of book/solutions.md.
  sed -i -E "s#\\\\ref $(anchor "$id") \"[^\"]*\"#(solution not in this workspace)#g" "$root"/book/*.md
}

# ---- running an exercise's tests ---------------------------------------------------------------
# run_tests ID BINARY: runs ID's tests one by one; prints PASS, or the first failing check and
# the hint of its test. Returns 0 or 1.
run_tests() {
  local id="$1" bin="$2" n=0 out name hint
  local names hints
  mapfile -t names < <(field "$id" test)
  mapfile -t hints < <(field "$id" hint)
  [ "${#names[@]}" -gt 0 ] || die "exercise $id names no test"
  for name in "${names[@]}"; do
    hint="${hints[$n]:-}"
    n=$((n + 1))
    set +e
    # doctest splits filters at commas: a comma becomes the one-character wildcard.
    out="$("$bin" --test-case="${name//,/?}" --no-version 2>&1)"
    local rc=$?
    set -e
    if ! grep -qE 'test cases: *1 \| *1 passed' <<<"$out" || [ $rc -ne 0 ]; then
      if ! grep -qE 'test cases: *1 \|' <<<"$out"; then
        echo "FAIL $id: '$name' does not name exactly one test case of $bin"
        return 1
      fi
      echo "FAIL $id: test '$(sed -n 's/^TEST CASE: *//p' <<<"$out" | head -n 1)'"
      # The first failing check as doctest reports it (location, expression, values).
      awk '/ERROR:|FATAL ERROR|THREW|threw/ && !shown { shown = 1; p = 1 }
           p && /^[=]+$/ { exit }
           p && /^$/ { exit }
           p { print "  " $0 }' <<<"$out" | head -n 12
      [ -n "$hint" ] && echo "hint: $hint"
      return 1
    fi
    echo "ok   $name"
  done
  echo "PASS $id ($n test$([ $n -gt 1 ] && echo s))"
}

# ---- commands ------------------------------------------------------------------------------------
cmd_list() {
  printf '%-9s %-10s %-9s %s\n' ID KIND PAGE TITLE
  local id
  for id in $(ids); do
    printf '%-9s %-10s %-9s %s\n' "$id" "$(field "$id" kind)" "$(field "$id" page)" "$(field "$id" title)"
  done
}

# copy_project SRC DIR: the project's own files, without build directories and without the git
# history (the history holds the solutions).
copy_project() {
  (cd "$1" && find . \( -path './build*' -o -path './.git' \) -prune -o -type f -print0 |
     xargs -0 cp --parents -t "$2")
}

cmd_start() {
  [ $# -eq 2 ] || die "usage: start ID DIR"
  local id="$1" dir="$2"
  exists "$id"
  if [ -e "$dir" ] && [ -n "$(ls -A "$dir" 2>/dev/null)" ]; then die "$dir exists and is not empty"; fi
  mkdir -p "$dir"
  dir="$(cd "$dir" && pwd)"
  copy_project "$HERE" "$dir"
  strip_tree "$id" "$dir"
  local kind; kind="$(field "$id" kind)"
  echo "exercise $id ($kind): $(field "$id" title)"
  echo "statement: book page $(field "$id" page) (book/$(field "$id" page).md, section Exercises)"
  if [ "$kind" = implement ]; then
    echo "your code goes where $(region_files "$id" "$HERE" | grep '^code/' | sed "s#^#$dir/#" | tr '\n' ' ')throws \"exercise $id: not implemented yet\""
  fi
  echo "check it with: scripts/exercise.sh check $id   (from $dir)"
}

cmd_check() {
  [ $# -ge 1 ] && [ $# -le 2 ] || die "usage: check ID [DIR]"
  local id="$1" dir="${2:-$PWD}"
  exists "$id"
  [ -f "$dir/CMakeLists.txt" ] || die "$dir is not a copy of the project (no CMakeLists.txt)"
  dir="$(cd "$dir" && pwd)"
  local build="${DT_EXERCISE_BUILD:-$dir/build}" log
  log="$(mktemp)"
  echo "building $build (target dt_tests) ..."
  if ! { cmake -S "$dir" -B "$build" -DCMAKE_BUILD_TYPE=Release >"$log" 2>&1 &&
         cmake --build "$build" --target dt_tests -j "$JOBS" >>"$log" 2>&1; }; then
    echo "FAIL $id: the project does not build; the first errors:"
    grep -E 'error|Error' "$log" | head -n 15 | sed 's/^/  /'
    echo "hint: fix the compile errors first (full log: $log)"
    return 1
  fi
  rm -f "$log"
  case "$(field "$id" kind)" in
    prove) echo "exercise $id asks for a proof: compare yours with its entry of book/solutions.md;" \
                "the tests below check the claim on examples." ;;
    measure) echo "exercise $id asks for a measurement: the tests below check the claim the" \
                  "measurement answers." ;;
  esac
  run_tests "$id" "$build/dt_tests"
}

# Doxygen markup to plain Markdown (for the sheets): formulas, references, snippets quoted.
to_markdown() {
  local root="$1"
  awk -v root="$root" '
    /^\\snippet / {
      file = root "/" $2; name = $3; inside = 0
      print "```cpp"
      while ((getline line < file) > 0) {
        if (index(line, "//! [" name "]")) { if (inside) break; inside = 1; continue }
        if (inside && line !~ /(BEGIN|END) SOLUTION/) print line
      }
      close(file)
      print "```"
      next
    }
    /^\\(anchor|image)/ { next }
    {
      gsub(/\\f\$/, "$"); gsub(/\\f\[/, "$$"); gsub(/\\f\]/, "$$")
      while (match($0, /\\ref [A-Za-z0-9_.]+ "[^"]*"/)) {
        t = substr($0, RSTART, RLENGTH); sub(/^[^"]*"/, "", t); sub(/"$/, "", t)
        $0 = substr($0, 1, RSTART - 1) t substr($0, RSTART + RLENGTH)
      }
      gsub(/\\ref /, "")
      print
    }'
}

# statement ID: the exercise's text from its book page, between "<!-- EXERCISE ID -->" and the
# next blank line.
statement() {
  local page; page="$(field "$1" page)"
  awk -v id="$1" 'index($0, "<!-- EXERCISE " id " -->") { p = 1; next } p && /^$/ { exit } p' \
    "$HERE/book/$page.md"
}

cmd_handout() {
  [ $# -ge 1 ] && [ $# -le 2 ] || die "usage: handout SECTION [OUTDIR]"
  local sec="$1" out="${2:-$PWD}" id fig figdir="$HERE/build/output/ch2"
  local sel; sel="$(ids | awk -v s="$sec" 'index($0, s "-") == 1')"
  [ -n "$sel" ] || die "no exercise in section $sec (scripts/exercise.sh list)"
  mkdir -p "$out"
  local sheet="$out/exercises_$sec.md" sols="$out/solutions_$sec.md"
  {
    echo "# Exercises of section $sec"
    echo
    echo "From the companion to \"Construction of 2D Delaunay Triangulations\". Each exercise says how"
    echo "to check an answer: \`scripts/exercise.sh start ID DIR\` makes a copy of the project without"
    echo "the solution; \`scripts/exercise.sh check ID\` inside it builds and runs the exercise's tests."
    for id in $sel; do
      echo
      echo "## Exercise $id: $(field "$id" title) ($(field "$id" kind))"
      echo
      # The page's bold label repeats the heading.
      statement "$id" | to_markdown "$HERE" | sed -E '1s/^\*\*Exercise [^*]*\*\* \([a-z]*\)\. //'
      echo
      echo "(Book page \`$(field "$id" page)\`, section Exercises.)"
      for fig in $(field "$id" figures); do
        if [ -f "$figdir/$fig" ]; then
          cp "$figdir/$fig" "$out/"
          echo
          echo "![$fig]($fig)"
        else
          echo
          echo "(Figure \`$fig\`: run \`build/$(field "$id" program)\` first; it is not built yet.)"
        fi
      done
      echo
      case "$(field "$id" kind)" in
        implement) echo "**Check:** \`scripts/exercise.sh start $id mywork && cd mywork && scripts/exercise.sh check $id\`." ;;
        measure) echo "**Check:** run \`build/$(field "$id" program)\`, then \`scripts/exercise.sh check $id\` (the tests check the claim)." ;;
        prove) echo "**Check:** compare with the solutions sheet; \`scripts/exercise.sh check $id\` runs the tests of the claim." ;;
      esac
    done
  } >"$sheet"
  {
    echo "# Solutions of section $sec"
    for id in $sel; do
      echo
      echo "## Exercise $id: $(field "$id" title)"
      echo
      # The entry without its own heading, then the measured tables that answer it.
      awk -v id="$id" 'index($0, "BEGIN SOLUTION " id " ") { p = 1; next }
                       index($0, "END SOLUTION " id " ") { p = 0 } p && !/^## /' \
        "$HERE/book/solutions.md" | to_markdown "$HERE"
      for tab in $(field "$id" tables); do
        echo
        if [ -f "$figdir/$tab" ]; then cat "$figdir/$tab"
        else echo "(Table \`$tab\`: run \`build/$(field "$id" program)\` first; it is not built yet.)"; fi
      done
      echo
      echo "Tests (doctest names or patterns, \`build/dt_tests -tc='...'\`):"
      field "$id" test | sed 's/^/- /'
    done
  } >"$sols"
  echo "$sheet"
  echo "$sols"
}

# The fast path of the machinery tests: compile the stripped files alone and link them before
# BUILD's library, whose members for those files are then never pulled in.
cmd_selftest() {
  [ $# -ge 1 ] || die "usage: selftest BUILD [ID...]"
  local build; build="$(cd "$1" && pwd)"; shift
  local objs="$build/CMakeFiles/dt_tests.dir/tests"
  [ -f "$build/libdt.a" ] && [ -d "$objs" ] || die "$build has no libdt.a or dt_tests objects (build dt_tests first)"
  local sel="$*" id fail=0 work f o
  if [ -z "$sel" ]; then
    for id in $(ids); do
      if [ "$(field "$id" kind)" = implement ]; then sel="$sel $id"; fi
    done
  fi
  # The objects of the current test sources only: a renamed test file leaves its old object behind.
  local test_objs=() t
  for t in "$HERE"/tests/*.cpp; do
    [ -f "$objs/$(basename "$t").o" ] || die "$build has no object for tests/$(basename "$t") (build dt_tests first)"
    test_objs+=("$objs/$(basename "$t").o")
  done
  work="$(mktemp -d)"
  trap 'rm -rf "$work"' RETURN
  for id in $sel; do
    local files; files="$(region_files "$id" "$HERE" | grep '^code/.*\.cpp$' || true)"
    if [ -z "$files" ]; then echo "FAIL $id: no solution region in code/*.cpp"; fail=1; continue; fi
    for variant in stub restored; do
      local o_list=() ok=1
      for f in $files; do
        o="$work/$(basename "$f" .cpp).$variant.o"
        if [ $variant = stub ]; then strip_file "$id" "$HERE/$f" >"$work/$(basename "$f")"
        else cp "$HERE/$f" "$work/$(basename "$f")"; fi
        if ! g++ -std=c++17 -O1 -ffp-contract=off -I"$HERE/code" -c "$work/$(basename "$f")" -o "$o" \
             2>"$work/cc.log"; then
          echo "FAIL $id: the $variant copy of $f does not compile:"; head -n 20 "$work/cc.log"; ok=0
        fi
        o_list+=("$o")
      done
      [ $ok = 1 ] || { fail=1; continue; }
      if ! g++ -o "$work/t" "${o_list[@]}" "${test_objs[@]}" "$build/libdt.a" -lmpfr -lgmp 2>"$work/ld.log"; then
        echo "FAIL $id: the $variant copy does not link:"; head -n 20 "$work/ld.log"; fail=1; continue
      fi
      local res; set +e; res="$(run_tests "$id" "$work/t")"; local rc=$?; set -e
      if [ $variant = stub ]; then
        if [ $rc -eq 0 ]; then echo "FAIL $id: its tests pass on the stub"; fail=1
        elif ! grep -q "exercise $id: not implemented yet" <<<"$res"; then
          echo "FAIL $id: the stub's failure does not say so:"; echo "$res"; fail=1
        else echo "ok   $id: the stub compiles and its check fails"; fi
      else
        if [ $rc -ne 0 ]; then echo "FAIL $id: its tests fail on the restored solution:"; echo "$res"; fail=1
        else echo "ok   $id: the restored solution passes"; fi
      fi
    done
  done
  return $fail
}

cmd_lint() {
  [ $# -eq 1 ] || die "usage: lint BUILD"
  local bin="$1/dt_tests" id name fail=0 list kind page
  [ -x "$bin" ] || die "no $bin"
  for id in $(ids); do
    kind="$(field "$id" kind)"; page="$(field "$id" page)"
    case "$kind" in implement|measure|prove) ;; *) echo "$id: unknown kind '$kind'"; fail=1 ;; esac
    [ -f "$HERE/book/$page.md" ] || { echo "$id: no page book/$page.md"; fail=1; continue; }
    [ -n "$(statement "$id")" ] || { echo "$id: no '<!-- EXERCISE $id -->' statement on book/$page.md"; fail=1; }
    [ "$(field "$id" test | wc -l)" = "$(field "$id" hint | wc -l)" ] || { echo "$id: not one hint per test"; fail=1; }
    while IFS= read -r name; do
      list="$("$bin" --list-test-cases --test-case="${name//,/?}" --no-version 2>&1)"
      grep -q 'passing the current filters: 1$' <<<"$list" ||
        { echo "$id: '$name' does not name exactly one test case"; fail=1; }
    done < <(field "$id" test)
    if [ "$kind" = implement ]; then
      region_files "$id" "$HERE" | grep -q '^code/' || { echo "$id: no solution region in code/"; fail=1; }
    fi
    grep -q "BEGIN SOLUTION $id " "$HERE/book/solutions.md" || { echo "$id: no entry in book/solutions.md"; fail=1; }
    grep -qF "\\ref $(anchor "$id") " "$HERE/book/$page.md" || { echo "$id: book/$page.md does not link its solution"; fail=1; }
  done
  [ $fail = 0 ] && echo "lint: $(ids | wc -l) exercises consistent"
  return $fail
}

[ $# -ge 1 ] || die "usage: list | start ID DIR | check ID [DIR] | handout SECTION [OUTDIR] | selftest BUILD [ID...] | lint BUILD"
[ -f "$DB" ] || die "no $DB"
cmd="$1"; shift
case "$cmd" in
  list) cmd_list ;;
  start) cmd_start "$@" ;;
  check) cmd_check "$@" ;;
  handout) cmd_handout "$@" ;;
  selftest) cmd_selftest "$@" ;;
  lint) cmd_lint "$@" ;;
  *) die "unknown command '$cmd'" ;;
esac
