#!/usr/bin/env bash
# shellcheck disable=SC2016,SC2128,SC2178  # literal backticks in sed patterns; 'sel' is a local string here and a local array elsewhere
# Classroom exercises (exercises/exercises.txt). Solutions sit in code/ between
# "BEGIN SOLUTION <id>" and "END SOLUTION <id>" comment lines, and in book/solutions.md between
# the same markers.
#
# The teacher:
#   scripts/exercise.sh list
#   scripts/exercise.sh release ID... DIR    a workspace for the class, outside this repository:
#                                            EVERY exercise's solution stripped (the markers stay,
#                                            around a stub), the IDs stored in DIR/.exercise,
#                                            answers.md for prove and measure exercises
#   scripts/exercise.sh grade ID STUDENT_DIR... > grades.tsv
#                                            each student's solution region put into this tree's
#                                            build, this tree's tests run (a timeout per test);
#                                            one TSV row per student. Prove and measure: the
#                                            answers are copied to answers_ID/ beside the sheet
#   scripts/exercise.sh handout SECTION [OUT]  OUT/exercises_SECTION.md and OUT/solutions_SECTION.md
# The student, inside the workspace:
#   scripts/exercise.sh check [ID...]        build, run the tests (implement) or collect the
#                                            answer in answers.md (prove, measure)
#   scripts/exercise.sh hint [ID]            the next hint, one level per call
#   scripts/exercise.sh watch [ID...]        check again whenever a file of code/ or answers.md
#                                            is saved (Ctrl-C stops)
# The machinery's own tests:
#   scripts/exercise.sh selftest BUILD [ID...] each implement exercise: the stub compiles and
#                                            fails, the restored solution passes
#   scripts/exercise.sh lint BUILD           the list, the tests, the pages and regions agree
# Environment: DT_TEST_TIMEOUT (seconds per test: 60 in check, 10 in grade),
#   DT_EXERCISE_JOBS (parallel jobs), DT_GRADE_BUILD (the teacher's build, default build/),
#   DT_GRADE_NO_BUILD=1 (grade without bringing the build up to date first),
#   DT_GRADE_ANSWERS (where grade puts answers, default ./answers_ID), DT_WATCH_ROUNDS (watch
#   stops after so many checks; for tests), DT_HANDOUT_FIGURES (where handout takes the figures,
#   default build/output/ch2), DT_HANDOUT_BUILD_FIGURES=1 (handout builds a missing figure).
# Exit status: 0 pass, 1 fail, 2 bad usage.
set -euo pipefail

HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd -P)"
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
is_id() { ids | grep -qxF -- "$1"; }
exists() { is_id "$1" || die "no exercise '$1' (scripts/exercise.sh list)"; }
# The anchor of an exercise's entry in book/solutions.md: 2.3.4-1 -> sol_2_3_4_1.
anchor() { echo "sol_$(echo "$1" | tr '.-' '__')"; }

# ---- solution regions --------------------------------------------------------------------------
# The awk function shared by every reader of the markers: is `line` the BEGIN or END marker of
# exercise `id` (the id followed by the end of the line or a space)?
MARKS='function marks(line, word,    t, k, after) {
  t = word " SOLUTION " id; k = index(line, t)
  if (!k) return 0
  after = substr(line, k + length(t), 1)
  return after == "" || after == " "
}'

# strip_file ID FILE: FILE without ID's solutions. In C++ the markers stay (so that grade can
# cut the student's code out again) around one line throwing std::logic_error, or around
# nothing in a region marked "(remove)" (helpers, or a comment that states a proof). In Markdown
# the region disappears with its markers.
strip_file() {
  awk -v id="$1" -v md="$([[ $2 == *.md ]] && echo 1 || echo 0)" "$MARKS"'
    !inside && marks($0, "BEGIN") {
      inside = 1
      if (!md) {
        print
        if (index($0, "(remove)") == 0) {
          indent = $0; sub(/[^ \t].*/, "", indent)
          print indent "throw std::logic_error(\"exercise " id ": not implemented yet\");"
        }
      }
      next
    }
    inside && marks($0, "END") { inside = 0; if (!md) print; next }
    !inside { print }
    END { if (inside) { print "unterminated solution region " id > "/dev/stderr"; exit 1 } }
  ' "$2"
}

# regions ID FILE: the text inside ID's regions of FILE, each region followed by a line "\f".
regions() {
  awk -v id="$1" "$MARKS"'
    !inside && marks($0, "BEGIN") { inside = 1; next }
    inside && marks($0, "END") { inside = 0; print "\f"; next }
    inside { print }' "$2"
}

# splice ID TEACHER STUDENT: TEACHER's file with the k-th region of ID holding the k-th region of
# STUDENT's file. Exit status 3 (and a message) when the two files do not have as many regions.
splice() {
  awk -v id="$1" -v student="$3" "$MARKS"'
    BEGIN {
      k = 0; inside = 0
      while ((getline line < student) > 0) {
        if (!inside && marks(line, "BEGIN")) { inside = 1; k++; body[k] = ""; continue }
        if (inside && marks(line, "END")) { inside = 0; continue }
        if (inside) body[k] = body[k] line "\n"
      }
      close(student); n = k; k = 0; inside = 0
    }
    !inside && marks($0, "BEGIN") { inside = 1; k++; print; printf "%s", body[k]; next }
    inside && marks($0, "END") { inside = 0; print; next }
    !inside { print }
    END {
      if (k != n) { printf "%d region(s) of %s, %d expected\n", n, id, k > "/dev/stderr"; exit 3 }
    }' "$2"
}

# region_files ID ROOT: the files (relative to ROOT) holding a region of ID.
region_files() {
  (cd "$2" && grep -rlE --include='*.cpp' --include='*.h' --include='*.md' \
     "(BEGIN|END) SOLUTION $(echo "$1" | sed 's/\./\\./g')( |$)" code book tests 2>/dev/null || true) | sort
}

# tainted_snippets ID FILE: the Doxygen snippet markers of FILE ("//! [name]") whose block
# overlaps a code region of ID: the book must not quote a stub in place of the listing. A region
# marked "(remove)" (a helper, a comment) leaves the quoted code meaningful and taints nothing.
tainted_snippets() {
  awk -v id="$1" "$MARKS"'
    marks($0, "BEGIN") && index($0, "(remove)") == 0 { inside = 1 }
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
        # "\snippet code/x.cpp name" -> a note; the quoted code would be the stub.
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

# ---- forbidden code ------------------------------------------------------------------------------
# forbidden ID FILE...: prints the first forbidden use in ID's regions of the files ("'WORD' in
# FILE"), or nothing. Comments are skipped. A word of letters, digits, _ and : matches only as a
# whole word (std::map, not std::unordered_map). Every region also may not use the preprocessor
# (# or %: at a line's start, a line ending in a backslash) or asm, which could rebuild a word.
forbidden() {
  local id="$1"; shift
  local words; words="$(field "$id" forbid)"
  local f
  for f in "$@"; do
    regions "$id" "$f" | awk -v words="$words" -v file="$f" '
      BEGIN { n = split(words, w, "\n") }
      function wordc(c) { return c ~ /[A-Za-z0-9_]/ }
      function found(line, t,    k, from, before, after) {
        from = 1
        while ((k = index(substr(line, from), t)) > 0) {
          k += from - 1
          before = k > 1 ? substr(line, k - 1, 1) : ""
          after = substr(line, k + length(t), 1)
          if (t !~ /^[A-Za-z0-9_:]+$/) return 1
          if (!(wordc(substr(t, 1, 1)) && wordc(before)) && !(wordc(substr(t, length(t), 1)) && wordc(after)))
            return 1
          from = k + 1
        }
        return 0
      }
      {
        line = $0
        if (incomment) { if ((e = index(line, "*/")) == 0) next; line = substr(line, e + 2); incomment = 0 }
        while ((b = index(line, "/*")) > 0) {
          rest = substr(line, b + 2)
          if ((e = index(rest, "*/")) == 0) { line = substr(line, 1, b - 1); incomment = 1; break }
          line = substr(line, 1, b - 1) " " substr(rest, e + 2)
        }
        sub(/\/\/.*/, "", line)
        if (line ~ /^[ \t]*(#|%:)/ || $0 ~ /\\$/) { print "the preprocessor in " file; exit }
        if (found(line, "asm") || found(line, "__asm__")) { print "asm in " file; exit }
        for (i = 1; i <= n; i++)
          if (w[i] != "" && found(line, w[i])) { q = sprintf("%c", 39); print q w[i] q " in " file; exit }
      }'
  done | head -n 1
}

# ---- running tests -------------------------------------------------------------------------------
# run_one BIN NAME: runs one doctest test case under a timeout. Sets R_STATUS (pass, fail,
# timeout, crash, missing) and R_DETAIL (the first failing check, several lines). The verdict is
# read from a report file whose name the code under test cannot guess (--out), and requires
# the exit status 0: printing doctest's summary line does not pass a test.
run_one() {
  local bin="$1" name="$2" t="${TEST_TIMEOUT}" rep out rc
  rep="$(mktemp -u "${TMPDIR:-/tmp}/dt_report.XXXXXXXXXX")"
  set +e
  # doctest splits filters at commas: a comma becomes the one-character wildcard.
  out="$(timeout -k 2 "$t" "$bin" --test-case="${name//,/?}" --no-version --out="$rep" 2>&1)"
  rc=$?
  set -e
  local report=""
  [ -f "$rep" ] && report="$(cat "$rep")"
  rm -f "$rep"
  R_DETAIL=""
  if [ $rc -eq 124 ] || [ $rc -eq 137 ]; then
    R_STATUS=timeout
    R_DETAIL="test '$name' did not finish within $t s (an endless loop?)"
    return
  fi
  if [ $rc -gt 128 ]; then
    R_STATUS=crash
    local sig
    case $((rc - 128)) in 4) sig=SIGILL ;; 6) sig=SIGABRT ;; 7) sig=SIGBUS ;; 8) sig=SIGFPE ;;
      11) sig=SIGSEGV ;; *) sig="signal $((rc - 128))" ;; esac
    R_DETAIL="test '$name' CRASHED: $sig"
    # What the report holds up to the crash: the last check reached.
    R_DETAIL="$R_DETAIL$(awk '/ERROR:|FATAL ERROR|CRASHED/ && !s { s = 1; p = 1 } p && /^$/ { exit } p { print "\n  " $0 }' <<<"$report" | head -n 8 | tr -d '\n' | sed 's/^/ /')"
    return
  fi
  if ! grep -qE 'test cases: *1 \|' <<<"$report"; then
    R_STATUS=missing
    R_DETAIL="'$name' does not name exactly one test case of $bin${out:+ ($(head -c 300 <<<"$out" | tr '\n' ' '))}"
    return
  fi
  if [ $rc -eq 0 ] && grep -qE 'test cases: *1 \| *1 passed' <<<"$report"; then
    R_STATUS=pass
    return
  fi
  R_STATUS=fail
  # The first failing check as doctest reports it (location, expression, values, logged input).
  R_DETAIL="$(awk '/ERROR:|FATAL ERROR|THREW|threw/ && !shown { shown = 1; p = 1 }
                   p && /^[=]+$/ { exit }
                   p && /^$/ { exit }
                   p { print "  " $0 }' <<<"$report" | head -n 12)"
  [ -n "$R_DETAIL" ] || R_DETAIL="  (exit status $rc)"
}

# run_tests ID BINARY: runs ID's tests one by one; prints PASS, or the first failing check and
# the hint of its test. Returns 0 or 1.
run_tests() {
  local id="$1" bin="$2" n=0 name hint
  local names hints
  mapfile -t names < <(field "$id" test)
  mapfile -t hints < <(field "$id" hint)
  [ "${#names[@]}" -gt 0 ] || die "exercise $id names no test"
  for name in "${names[@]}"; do
    hint="${hints[$n]:-}"
    n=$((n + 1))
    run_one "$bin" "$name"
    case "$R_STATUS" in
      pass) echo "ok   $name" ;;
      missing) echo "FAIL $id: $R_DETAIL"; return 1 ;;
      timeout|crash) echo "FAIL $id: $R_DETAIL"; [ -n "$hint" ] && echo "hint: $hint"; return 1 ;;
      *)
        echo "FAIL $id: test '$name'"
        echo "$R_DETAIL"
        [ -n "$hint" ] && echo "hint: $hint"
        return 1 ;;
    esac
  done
  echo "PASS $id ($n test$([ $n -gt 1 ] && echo s))"
}

# ---- the teacher: list, release ----------------------------------------------------------------
cmd_list() {
  printf '%-9s %-10s %-9s %s\n' ID KIND PAGE TITLE
  local id
  for id in $(ids); do
    printf '%-9s %-10s %-9s %s\n' "$id" "$(field "$id" kind)" "$(field "$id" page)" "$(field "$id" title)"
  done
}

# copy_project SRC DIR: the project's own files: those git tracks when SRC is a git work tree
# (so grade's answers_ID/SHEET.md, handout sheets and other outputs left in the tree stay out),
# every file but grade's answers_* folders otherwise; never the git history (it holds the solutions), build directories
# (build, build-*, any directory holding a CMakeCache.txt) or workspaces made inside the tree (a
# directory holding .exercise, or its own CMakeLists.txt and scripts/exercise.sh).
copy_project() {
  local src="$1" dst="$2" d
  local prune=(-name .git -o -name build -o -name 'build-*' -o -name 'answers_*') skip=()
  while IFS= read -r -d '' d; do
    if [ -e "$src/$d/.exercise" ] || [ -e "$src/$d/CMakeCache.txt" ] ||
       { [ -f "$src/$d/CMakeLists.txt" ] && [ -f "$src/$d/scripts/exercise.sh" ]; }; then
      prune+=(-o -path "$d"); skip+=("${d#./}/")
    fi
  done < <(cd "$src" && find . -mindepth 1 -type d \( -name .git -prune -o -print0 \))
  local top=""
  top="$(git -C "$src" rev-parse --show-toplevel 2>/dev/null || true)"
  if [ -n "$top" ] && [ "$(cd "$top" && pwd -P)" = "$src" ]; then
    (cd "$src" && git ls-files -z | while IFS= read -r -d '' d; do
       [ -f "$d" ] || continue
       case "$d" in build/*|build-*/*) continue ;; esac
       for p in "${skip[@]}"; do [[ $d == "$p"* ]] && continue 2; done
       printf '%s\0' "$d"
     done | xargs -0 -r cp --parents -t "$dst")
    return
  fi
  (cd "$src" && find . \( "${prune[@]}" \) -prune -o -type f -print0 | xargs -0 -r cp --parents -t "$dst")
}

# answers_section ID FILE: the student's answer to ID in answers.md: the lines after the heading
# "## Exercise ID" up to the next "## " heading, without the template's placeholder.
answers_section() {
  [ -f "$2" ] || return 0
  awk -v id="$1" '
    /^## / { p = ($0 ~ ("^## Exercise " id "([ :]|$)")) ? 1 : 0; next }
    p && !/^<!-- write your answer/' "$2"
}

cmd_release() {
  [ $# -ge 2 ] || die "usage: release ID... DIR"
  local dir="${!#}" sel=("${@:1:$#-1}") id
  for id in "${sel[@]}"; do exists "$id"; done
  local abs; abs="$(readlink -m -- "$dir")"
  case "$abs/" in
    "$HERE"/*) die "$dir is inside the repository $HERE: a workspace there would be copied into the next one, and a student working there has every solution; choose a directory outside it" ;;
  esac
  case "$HERE/" in "$abs"/*) die "$dir contains the repository; choose an empty directory outside it" ;; esac
  if [ -e "$abs" ] && [ -n "$(ls -A "$abs" 2>/dev/null)" ]; then die "$dir exists and is not empty"; fi
  mkdir -p "$abs"
  copy_project "$HERE" "$abs"
  # Every exercise's solution goes, not only the released ones: the others would otherwise be
  # one directory away.
  for id in $(ids); do strip_tree "$id" "$abs"; done
  # The tests and their hints of prove and measure exercises state the answers: the teacher's.
  awk '/^#/ || /^[ \t]*$/ { kind = ""; print; next }
       /^kind:/ { kind = $2 }
       (kind == "prove" || kind == "measure") && /^(test|hint):/ { next }
       { print }' "$HERE/exercises/exercises.txt" >"$abs/exercises/exercises.txt"
  { echo "# Made by scripts/exercise.sh release: the exercises of this workspace."
    echo "ids: ${sel[*]}"; } >"$abs/.exercise"
  local written=0
  for id in "${sel[@]}"; do
    case "$(field "$id" kind)" in
      prove|measure)
        if [ $written = 0 ]; then
          { echo "# Answers"
            echo
            echo "Write each answer under its heading; \`scripts/exercise.sh check\` collects them and"
            echo "the teacher marks them."; } >"$abs/answers.md"
          written=1
        fi
        { echo
          echo "## Exercise $id: $(field "$id" title) ($(field "$id" kind))"
          echo
          echo "<!-- write your answer below this line -->"; } >>"$abs/answers.md" ;;
    esac
  done
  echo "released ${sel[*]} into $abs (every solution stripped; hand this directory out)"
  for id in "${sel[@]}"; do
    echo "exercise $id ($(field "$id" kind)): $(field "$id" title)"
    if [ "$(field "$id" kind)" = implement ]; then
      echo "  code goes between the BEGIN/END SOLUTION $id lines of:" \
           "$(region_files "$id" "$HERE" | grep '^code/' | tr '\n' ' ')"
    else
      echo "  the answer goes under '## Exercise $id' in answers.md"
    fi
  done
  echo "students check with: scripts/exercise.sh check   (inside the workspace)"
}

# ---- the student: check, hint, watch -------------------------------------------------------------
# workspace_ids DIR: the IDs stored by release in DIR/.exercise.
workspace_ids() {
  [ -f "$1/.exercise" ] || return 0
  awk '/^ids:/ { sub(/^ids:[ \t]*/, ""); print }' "$1/.exercise" | tr ' ' '\n' | sed '/^$/d'
}

# parse_ids_dir ARGS...: sets SEL (the IDs) and DIR (a directory argument, default the current
# one); without an ID, the workspace's own.
parse_ids_dir() {
  SEL=(); DIR="$PWD"
  local a
  for a in "$@"; do
    if is_id "$a"; then SEL+=("$a")
    elif [ -d "$a" ]; then DIR="$(cd "$a" && pwd -P)"
    else die "'$a' is neither an exercise (scripts/exercise.sh list) nor a directory"
    fi
  done
  if [ ${#SEL[@]} -eq 0 ]; then
    mapfile -t SEL < <(workspace_ids "$DIR")
    [ ${#SEL[@]} -gt 0 ] || die "no exercise given and $DIR/.exercise names none (a workspace made by release stores its exercises there)"
  fi
}

cmd_check() {
  parse_ids_dir "$@"
  local dir="$DIR" id
  TEST_TIMEOUT="${DT_TEST_TIMEOUT:-60}"
  local need_build=0 status=0
  for id in "${SEL[@]}"; do [ "$(field "$id" kind)" = implement ] && need_build=1; done
  local build="${DT_EXERCISE_BUILD:-$dir/build}"
  if [ $need_build = 1 ]; then
    [ -f "$dir/CMakeLists.txt" ] || die "$dir is not a copy of the project (no CMakeLists.txt)"
    local log; log="$(mktemp)"
    echo "building $build (target dt_tests) ..."
    if ! { cmake -S "$dir" -B "$build" -DCMAKE_BUILD_TYPE=Release >"$log" 2>&1 &&
           cmake --build "$build" --target dt_tests -j "$JOBS" >>"$log" 2>&1; }; then
      echo "FAIL: the project does not build; the first errors:"
      grep -E 'error|Error' "$log" | head -n 15 | sed 's/^/  /'
      echo "hint: fix the compile errors first (full log: $log)"
      return 1
    fi
    rm -f "$log"
  fi
  for id in "${SEL[@]}"; do
    case "$(field "$id" kind)" in
      implement) run_tests "$id" "$build/dt_tests" || status=1 ;;
      *)
        local words
        words="$(answers_section "$id" "$dir/answers.md" | wc -w)"
        if [ "$words" -gt 0 ]; then
          echo "collected $id: answers.md, section 'Exercise $id', $words words (the teacher marks it; no automatic verdict)"
        else
          echo "MISSING $id: write your answer under '## Exercise $id' in $dir/answers.md"
          status=1
        fi ;;
    esac
  done
  return $status
}

# hint_levels ID: the hints of ID from the least to the most specific: the exercise's "step:"
# lines, then the hint of each test.
hint_levels() {
  field "$1" step
  # The hints of a prove or measure exercise's tests are the teacher's: they state the claim.
  [ "$(field "$1" kind)" != implement ] || field "$1" hint
}

cmd_hint() {
  parse_ids_dir "$@"
  local id="${SEL[0]}" state="$DIR/.exercise_hints" levels shown
  mapfile -t levels < <(hint_levels "$id")
  shown="$(awk -v id="$id" '$1 == id { n = $2 } END { print n + 0 }' "$state" 2>/dev/null || echo 0)"
  if [ "$shown" -ge "${#levels[@]}" ]; then
    echo "no more hints for $id (${#levels[@]} shown); the failure of check names the input that fails"
    return 0
  fi
  echo "hint $((shown + 1)) of ${#levels[@]} for $id: ${levels[$shown]}"
  { grep -v "^$id " "$state" 2>/dev/null || true; echo "$id $((shown + 1))"; } >"$state.tmp"
  mv "$state.tmp" "$state"
}

# watch: polls the modification times (find -newer against a stamp file: no inotify needed).
cmd_watch() {
  parse_ids_dir "$@"
  local stamp; stamp="$(mktemp)"
  # shellcheck disable=SC2064  # the name now: the local is gone when the trap runs
  trap "rm -f '$stamp'" EXIT
  local rounds="${DT_WATCH_ROUNDS:-0}" done_rounds=0 args=("${SEL[@]}" "$DIR")
  while :; do
    touch "$stamp"
    cmd_check "${args[@]}" || true
    done_rounds=$((done_rounds + 1))
    if [ "$rounds" -gt 0 ] && [ $done_rounds -ge "$rounds" ]; then return 0; fi
    echo "watching $DIR/code and answers.md (Ctrl-C stops) ..."
    until [ -n "$(find "$DIR/code" "$DIR/answers.md" -newer "$stamp" -type f 2>/dev/null | head -n 1)" ]; do
      sleep "${DT_WATCH_INTERVAL:-1}"
    done
  done
}

# ---- the teacher: grade --------------------------------------------------------------------------
# flags_of BUILD VAR: a variable of the library's flags.make (CXX_FLAGS, CXX_DEFINES,
# CXX_INCLUDES), one word per line. CMake quotes a word with a space or a quote in it
# (-I"/tmp/a b/c'd/code"); xargs reads those quotes as a shell would, and nothing is evaluated.
flags_of() { sed -n "s/^$2 = //p" "$1/CMakeFiles/dt.dir/flags.make" | xargs -r printf '%s\n'; }

# grade_one ID BUILD WORK STUDENT_DIR NUMBER: one student's row, into WORK/rows/NUMBER.
grade_one() {
  local id="$1" build="$2" work="$3" sdir="$4" num="$5"
  local me="$work/s$num" start=$SECONDS student f
  student="$(basename "$sdir")"
  mkdir -p "$me"
  local names; mapfile -t names < <(field "$id" test)
  local ntests=${#names[@]} cols=() i
  for ((i = 0; i < ntests; i++)); do cols+=("-"); done
  row() {  # result passed first_failure
    local detail
    detail="$(tr '\t\n' '  ' <<<"$3" | sed -E 's/ +/ /g; s/^ //; s/ $//' | cut -c 1-500)"
    local IFS=$'\t'
    printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$student" "$1" "$2/$ntests" "${cols[*]}" "${detail:--}" \
      "$((SECONDS - start))" >"$work/rows/$num"
  }
  if [ ! -d "$sdir" ]; then row NO-WORKSPACE 0 "$sdir is not a directory"; return; fi
  # 1. The student's regions, spliced into the teacher's files; nothing else of theirs is used.
  local files; files="$(region_files "$id" "$HERE" | grep -E '^code/.*\.cpp$' || true)"
  local sfiles=() objs=()
  for f in $files; do
    if [ ! -f "$sdir/$f" ]; then row NO-REGION 0 "no $f in the workspace"; return; fi
    sfiles+=("$sdir/$f")
    if ! splice "$id" "$HERE/$f" "$sdir/$f" >"$me/$(basename "$f")" 2>"$me/splice.log"; then
      row NO-REGION 0 "$f: $(cat "$me/splice.log") (the BEGIN/END SOLUTION $id lines must stay)"; return
    fi
  done
  # 2. Forbidden code.
  local bad; bad="$(forbidden "$id" "${sfiles[@]}")"
  if [ -n "$bad" ]; then row FORBIDDEN 0 "uses $bad (exercise $id forbids: $(field "$id" forbid | tr '\n' ' ')and the preprocessor)"; return; fi
  # 3. Compile the spliced files with the library's own flags; link before the teacher's
  #    library and test objects (dt_tests' own link line, with the student's objects first).
  for f in $files; do
    local o; o="$me/$(basename "$f" .cpp).o"
    if ! (cd "$build" && "$GRADE_CXX" "${GRADE_ARGS[@]}" \
            -c "$me/$(basename "$f")" -o "$o") >"$me/cc.log" 2>&1; then
      row COMPILE-ERROR 0 "$(grep -m 3 -E 'error' "$me/cc.log" | sed "s#$me/##")"; return
    fi
    objs+=("$o")
  done
  local link; link="$(cat "$build/CMakeFiles/dt_tests.dir/link.txt")"
  link="${link/ -o dt_tests / -o $me/t ${objs[*]} }"
  if ! (cd "$build" && bash -c "$link") >"$me/ld.log" 2>&1; then
    row LINK-ERROR 0 "$(grep -m 3 -E 'undefined|multiple|error' "$me/ld.log" | sed "s#$me/##")"; return
  fi
  # 4. The teacher's tests, each under its timeout.
  local passed=0 first="" result=PASS
  for ((i = 0; i < ntests; i++)); do
    run_one "$me/t" "${names[$i]}"
    cols[$i]="$R_STATUS"
    if [ "$R_STATUS" = pass ]; then passed=$((passed + 1)); continue; fi
    if [ -z "$first" ]; then
      first="test '${names[$i]}': $R_DETAIL"
      [ "$R_STATUS" = timeout ] || [ "$R_STATUS" = crash ] && first="$R_DETAIL"
      case "$R_STATUS" in timeout) result=TIMEOUT ;; crash) result=CRASH ;; *) result=FAIL ;; esac
    fi
  done
  rm -f "$me/t" "$me"/*.o
  row "$result" "$passed" "$first"
}

cmd_grade() {
  [ $# -ge 2 ] || die "usage: grade ID STUDENT_DIR... > grades.tsv"
  local id="$1"; shift
  exists "$id"
  local kind; kind="$(field "$id" kind)"
  if [ "$kind" != implement ]; then grade_answers "$id" "$@"; return; fi
  local build="${DT_GRADE_BUILD:-$HERE/build}"
  TEST_TIMEOUT="${DT_TEST_TIMEOUT:-10}"
  if [ "${DT_GRADE_NO_BUILD:-0}" != 1 ]; then
    echo "grade: bringing $build up to date (target dt_tests) ..." >&2
    { cmake -S "$HERE" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null &&
      cmake --build "$build" --target dt_tests -j "$JOBS" >/dev/null; } ||
      die "the tree of the teacher does not build ($build)"
  fi
  [ -f "$build/CMakeFiles/dt.dir/flags.make" ] && [ -f "$build/CMakeFiles/dt_tests.dir/link.txt" ] ||
    die "$build is not a build of this tree with dt_tests (cmake --build $build --target dt_tests)"
  build="$(cd "$build" && pwd -P)"
  GRADE_CXX="$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$build/CMakeCache.txt")"
  local defines includes flags
  mapfile -t defines < <(flags_of "$build" CXX_DEFINES)
  mapfile -t includes < <(flags_of "$build" CXX_INCLUDES)
  mapfile -t flags < <(flags_of "$build" CXX_FLAGS)
  GRADE_ARGS=("${defines[@]}" -I"$HERE/code" "${includes[@]}" "${flags[@]}")
  local work; work="$(mktemp -d)"
  mkdir -p "$work/rows"
  # shellcheck disable=SC2064
  trap "rm -rf '$work'" EXIT
  local names; mapfile -t names < <(field "$id" test)
  ( IFS=$'\t'; printf 'student\tresult\tpassed\t%s\tfirst_failure\tseconds\n' "${names[*]}" )
  local n=0 running=0 s
  for s in "$@"; do
    n=$((n + 1))
    ( set +e; grade_one "$id" "$build" "$work" "$s" "$(printf '%04d' $n)" ) &
    running=$((running + 1))
    if [ $running -ge "$JOBS" ]; then wait -n || true; running=$((running - 1)); fi
  done
  wait
  cat "$work"/rows/*
  echo "grade: $n students of $id graded ($(grep -c $'\tPASS\t' "$work"/rows/* | awk -F: '{ s += $2 } END { print s + 0 }') pass)" >&2
}

# grade_answers ID STUDENT_DIR...: a prove or measure exercise: each answer is copied to
# ANSWERS/<student>.md, the teacher's sheet to ANSWERS/SHEET.md; one row per student.
grade_answers() {
  local id="$1"; shift
  local out="${DT_GRADE_ANSWERS:-$PWD/answers_$id}" s student words
  mkdir -p "$out"
  solution_sheet "$id" >"$out/SHEET.md"
  printf 'student\tresult\twords\tfile\n'
  for s in "$@"; do
    student="$(basename "$s")"
    { echo "# $student: exercise $id"; echo; answers_section "$id" "$s/answers.md"; } >"$out/$student.md"
    words="$(answers_section "$id" "$s/answers.md" | wc -w)"
    printf '%s\t%s\t%s\t%s\n' "$student" "$([ "$words" -gt 0 ] && echo collected || echo missing)" \
      "$words" "$out/$student.md"
  done
  echo "grade: the answers to $id are in $out, beside SHEET.md, the sheet of the teacher" >&2
}

# ---- handouts --------------------------------------------------------------------------------------
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

# signature FUNCTION: "FILE" on the first line, then the Doxygen comment and the declaration of
# FUNCTION in the first header of code/ that declares it.
signature() {
  local h
  for h in "$HERE"/code/*.h; do
    awk -v fn="$1" -v file="code/$(basename "$h")" '
      /^[ \t]*\/\/\// { doc = doc $0 "\n"; next }
      !decl && $0 ~ ("(^|[ *&:])" fn "\\(") && $0 !~ /^[ \t]*\/\// { decl = 1 }
      decl { text = text $0 "\n"; if (index($0, ";") || index($0, "{")) { printf "%s\n%s%s", file, doc, text; exit 1 } next }
      { doc = "" }' "$h" || return 0
  done
  return 1
}

# solution_sheet ID: the teacher's sheet of one exercise: the entry of book/solutions.md, the
# measured tables that answer it, and its tests.
solution_sheet() {
  local id="$1" tab figdir="$HERE/build/output/ch2"
  echo "## Exercise $id: $(field "$id" title)"
  echo
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
}

cmd_handout() {
  [ $# -ge 1 ] && [ $# -le 2 ] || die "usage: handout SECTION [OUTDIR]"
  local sec="$1" out="${2:-$PWD}" id fig fn figdir="${DT_HANDOUT_FIGURES:-$HERE/build/output/ch2}"
  local sel; sel="$(ids | awk -v s="$sec" 'index($0, s "-") == 1')"
  [ -n "$sel" ] || die "no exercise in section $sec (scripts/exercise.sh list)"
  # Every figure first: a sheet that says "not built yet" is no handout.
  for id in $sel; do
    for fig in $(field "$id" figures); do
      [ -f "$figdir/$fig" ] && continue
      local prog; prog="$(field "$id" program)"
      if [ "${DT_HANDOUT_BUILD_FIGURES:-0}" = 1 ]; then
        echo "handout: $fig is missing; building and running $prog ..." >&2
        { cmake -S "$HERE" -B "$HERE/build" -DCMAKE_BUILD_TYPE=Release >/dev/null &&
          cmake --build "$HERE/build" --target "$prog" -j "$JOBS" >/dev/null &&
          (cd "$HERE" && "build/$prog" >/dev/null); } || die "could not make $fig with $prog"
        [ -f "$figdir/$fig" ] || die "$prog did not write $figdir/$fig"
      else
        die "the figure $fig of exercise $id is missing: make it with 'cmake --build build --target $prog && build/$prog' (or DT_HANDOUT_BUILD_FIGURES=1)"
      fi
    done
  done
  mkdir -p "$out"
  local sheet="$out/exercises_$sec.md" sols="$out/solutions_$sec.md"
  {
    echo "# Exercises of section $sec"
    echo
    echo "From the companion to \"Construction of 2D Delaunay Triangulations\". Work in the workspace"
    echo "your teacher handed out (made by \`scripts/exercise.sh release\`; it holds no solution)."
    echo "Inside it, \`scripts/exercise.sh check\` checks your work, \`scripts/exercise.sh hint\` gives"
    echo "one hint at a time and \`scripts/exercise.sh watch\` checks again whenever you save."
    for id in $sel; do
      local kind; kind="$(field "$id" kind)"
      echo
      echo "## Exercise $id: $(field "$id" title) ($kind)"
      echo
      # The page's bold label repeats the heading; its links to the book's solutions are dropped.
      statement "$id" | to_markdown "$HERE" | sed -E '1s/^\*\*Exercise [^*]*\*\* \([a-z]*\)\. //' |
        sed -E 's/ *Solution: exercise [0-9.-]+\.?//; s/ *Check: `scripts\/exercise.sh check [0-9.-]+`\.?//'
      for fig in $(field "$id" figures); do
        cp "$figdir/$fig" "$out/"
        echo
        echo "![$fig]($fig)"
      done
      echo
      case "$kind" in
        implement)
          echo "**Where:** between the lines \`// BEGIN SOLUTION $id\` and \`// END SOLUTION $id\` of" \
               "$(region_files "$id" "$HERE" | grep '^code/.*\.cpp$' | sed 's/.*/`&`/' | tr '\n' ' ' | sed 's/ $//')" \
               "(keep those lines: the grading cuts your code out between them)."
          for fn in $(field "$id" functions); do
            local sig; sig="$(signature "$fn" || true)"
            [ -n "$sig" ] || die "exercise $id: no declaration of $fn in code/*.h"
            echo
            echo "**Signature and contract** (\`$(head -n 1 <<<"$sig")\`):"
            echo
            echo '```cpp'
            tail -n +2 <<<"$sig" | sed -E 's/^[ \t]*\/\/\/ ?/\/\/ /'
            echo '```'
          done
          echo
          echo "**A pass:** \`scripts/exercise.sh check\` prints \`ok   <test>\` for each of these tests, then \`PASS $id\`:"
          field "$id" test | sed 's/^/- `/; s/$/`/'
          local words; words="$(field "$id" forbid | tr '\n' ' ' | sed 's/ $//')"
          [ -z "$words" ] || echo "
**Not allowed:** $(sed 's/\([^ ]*\)/`\1`/g; s/ /, /g' <<<"$words") (the grading rejects code that uses them)." ;;
        measure)
          echo "**Build and run:** \`cmake -S . -B build -DCMAKE_BUILD_TYPE=Release && cmake --build build --target $(field "$id" program) && build/$(field "$id" program)\`" \
               "(figures and tables in \`build/output/ch2/\`)."
          echo
          echo "**Answer:** under \`## Exercise $id\` in \`answers.md\`; \`scripts/exercise.sh check\` prints \`collected $id\` and your teacher marks it." ;;
        prove)
          echo "**Answer:** under \`## Exercise $id\` in \`answers.md\`; \`scripts/exercise.sh check\` prints \`collected $id\` and your teacher marks it." ;;
      esac
    done
  } >"$sheet"
  {
    echo "# Solutions of section $sec"
    for id in $sel; do echo; solution_sheet "$id"; done
  } >"$sols"
  echo "$sheet"
  echo "$sols"
}

# ---- the machinery's own tests ---------------------------------------------------------------------
# The fast path of the machinery tests: compile the stripped files alone and link them before
# BUILD's library, whose members for those files are then never pulled in.
cmd_selftest() {
  [ $# -ge 1 ] || die "usage: selftest BUILD [ID...]"
  local build; build="$(cd "$1" && pwd)"; shift
  local objs="$build/CMakeFiles/dt_tests.dir/tests"
  [ -f "$build/libdt.a" ] && [ -d "$objs" ] || die "$build has no libdt.a or dt_tests objects (build dt_tests first)"
  TEST_TIMEOUT="${DT_TEST_TIMEOUT:-60}"
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
      if ! g++ -o "$work/t" "${o_list[@]}" "${test_objs[@]}" "$build/libdt.a" -lmpfr -lgmp -pthread 2>"$work/ld.log"; then
        echo "FAIL $id: the $variant copy does not link:"; head -n 20 "$work/ld.log"; fail=1; continue
      fi
      local res; set +e; res="$(run_tests "$id" "$work/t")"; local rc=$?; set -e
      if [ $variant = stub ]; then
        if [ $rc -eq 0 ]; then echo "FAIL $id: its tests pass on the stub"; fail=1
        elif ! grep -q "exercise $id: not implemented yet" <<<"$res"; then
          echo "FAIL $id: the failure of the stub does not say so:"; echo "$res"; fail=1
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
  local bin="$1/dt_tests" id name fail=0 list kind page fn
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
      [ -n "$(field "$id" functions)" ] || { echo "$id: no 'functions:' (the handout quotes their contract)"; fail=1; }
      for fn in $(field "$id" functions); do
        signature "$fn" >/dev/null || { echo "$id: no declaration of $fn in code/*.h"; fail=1; }
      done
    fi
    grep -q "BEGIN SOLUTION $id " "$HERE/book/solutions.md" || { echo "$id: no entry in book/solutions.md"; fail=1; }
    grep -qF "\\ref $(anchor "$id") " "$HERE/book/$page.md" || { echo "$id: book/$page.md does not link its solution"; fail=1; }
  done
  [ $fail = 0 ] && echo "lint: $(ids | wc -l) exercises consistent"
  return $fail
}

[ $# -ge 1 ] || die "usage: exercise.sh COMMAND, one of: list, release ID... DIR, grade ID STUDENT_DIR..., handout SECTION [OUTDIR], check [ID...] [DIR], hint [ID] [DIR], watch [ID...] [DIR], selftest BUILD [ID...], lint BUILD"
[ -f "$DB" ] || die "no $DB"
cmd="$1"; shift
case "$cmd" in
  list) cmd_list ;;
  release) cmd_release "$@" ;;
  # start ID DIR: the former self-study command; now a release of one exercise.
  start) [ $# -eq 2 ] || die "usage: start ID DIR"; cmd_release "$@" ;;
  grade) cmd_grade "$@" ;;
  check) cmd_check "$@" ;;
  hint) cmd_hint "$@" ;;
  "watch") cmd_watch "$@" ;;
  handout) cmd_handout "$@" ;;
  selftest) cmd_selftest "$@" ;;
  lint) cmd_lint "$@" ;;
  *) die "unknown command '$cmd'" ;;
esac
