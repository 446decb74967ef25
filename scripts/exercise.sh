#!/usr/bin/env bash
# shellcheck disable=SC2016,SC2128,SC2178  # literal backticks in sed patterns; 'sel' is a local string here and a local array elsewhere
# Classroom exercises (exercises/exercises.txt). Solutions sit in code/ between
# "BEGIN SOLUTION <id>" and "END SOLUTION <id>" comment lines, and in book/solutions.md between
# the same markers.
#
# The teacher:
#   scripts/exercise.sh list
#   scripts/exercise.sh release [--variant N] ID... DIR
#                                            a workspace for the class, outside this repository:
#                                            EVERY exercise's solution stripped (the markers stay,
#                                            around a stub), the IDs (and the variant N: the seed
#                                            its tests mix into their random inputs) stored in
#                                            DIR/.exercise, answers.md for prove and measure
#                                            exercises
#   scripts/exercise.sh release --roster FILE ID... DIR
#                                            one such workspace per student, DIR/NAME, the
#                                            roster's seed as its variant (the seed grade --roster
#                                            gives the judge)
#   scripts/exercise.sh grade [--format tsv|canvas|moodle|gradescope|junit] [--seed N]
#                             [--roster FILE] [--summary DIR] [--unsandboxed] ID STUDENT_DIR...
#                                            each student's solution region put into this tree's
#                                            files, checked by tokens and by the functions its
#                                            object calls, compiled, linked and run in bubblewrap
#                                            as nobody; the verdict is the judge's output compared
#                                            with the teacher's, outside the sandbox; one row per
#                                            student. Prove and measure: the answers are copied
#                                            to answers_ID/ beside the sheet
#   scripts/exercise.sh export FORMAT ID GRADES.TSV [ROSTER]
#                                            a saved table of grade in another format
#   scripts/exercise.sh summary ID GRADES.TSV OUTDIR
#                                            OUTDIR/summary.html: a histogram of each test's
#                                            passes (gnuplot), the failures, the slowest
#   scripts/exercise.sh similar [--threshold T] ID STUDENT_DIR...
#                                            pairs of students whose code has nearly the same
#                                            shape (a hint to talk about, not a verdict)
#   scripts/exercise.sh handout SECTION [OUT]  OUT/exercises_SECTION.md and OUT/solutions_SECTION.md
# The student, inside the workspace:
#   scripts/exercise.sh check [ID...]        build (dt_tests from the test files of ID...
#                                            only), run the tests (implement) or collect the
#                                            answer in answers.md (prove, measure)
#   scripts/exercise.sh hint [ID]            the next hint, one level per call
#   scripts/exercise.sh watch [ID...]        check again whenever a file of code/ or answers.md
#                                            is saved (Ctrl-C stops)
# The machinery's own tests:
#   scripts/exercise.sh selftest BUILD [ID...] each implement exercise: the stub compiles and
#                                            fails, the restored solution passes (also in a
#                                            variant); the judge of grade tells the stub from
#                                            the solution
#   scripts/exercise.sh lint BUILD           the list, the tests, the pages and regions agree
# Environment: DT_TEST_TIMEOUT (seconds per test: 60 in check, 10 in grade),
#   DT_EXERCISE_JOBS (parallel jobs), DT_VARIANT (set by check from the workspace's variant),
#   DT_SELFTEST_VARIANT (the variant selftest also runs the restored solutions in, default 7),
#   DT_GRADE_BUILD (the teacher's build, default build/),
#   DT_GRADE_NO_BUILD=1 (grade without bringing the build up to date first),
#   DT_GRADE_UNSANDBOXED=1 (as --unsandboxed), DT_GRADE_BWRAP (the bubblewrap program, default
#   bwrap), DT_GRADE_STATIC_CHECKS=0 (the token and symbol checks off: for the machinery's test
#   that the sandbox and the judge hold alone; every row says so),
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

# splice ID TEACHER STUDENT [MAP]: TEACHER's file with the k-th region of ID holding the k-th
# region of STUDENT's file. Exit status 3 (and a message) when the two files do not have as many
# regions or a region of STUDENT has no END line. MAP gets one line per output line: the
# STUDENT's line it came from, or 0 (a line of the teacher's), for compiler messages.
splice() {
  awk -v id="$1" -v student="$3" -v map="${4:-/dev/null}" "$MARKS"'
    BEGIN {
      k = 0; inside = 0; sl = 0
      while ((getline line < student) > 0) {
        sl++
        if (!inside && marks(line, "BEGIN")) { inside = 1; k++; body[k] = ""; nb[k] = 0; from = sl; continue }
        if (inside && marks(line, "END")) { inside = 0; continue }
        if (inside) { body[k] = body[k] line "\n"; at[k, ++nb[k]] = sl }
      }
      close(student)
      if (inside) { inside_left = 1; printf "the region of %s that starts on line %d has no END SOLUTION %s line\n", id, from, id > "/dev/stderr"; exit 3 }
      n = k; k = 0; inside = 0
    }
    !inside && marks($0, "BEGIN") {
      inside = 1; k++; print; print 0 > map
      printf "%s", body[k]; for (i = 1; i <= nb[k]; i++) print at[k, i] > map
      next
    }
    inside && marks($0, "END") { inside = 0; print; print 0 > map; next }
    !inside { print; print 0 > map }
    END {
      if (inside_left) exit 3
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
  if [ -n "${RUN_BOX:-}" ]; then
    # grade: in the sandbox, the report on stdout into a file of the grader.
    sandbox "$RUN_BOX" "$t" "$(dirname "$bin")" -- "$bin" --test-case="${name//,/?}" --no-version >"$rep" 2>&1
    rc=$?
    out=""
  else
    out="$(timeout -k 2 "$t" "$bin" --test-case="${name//,/?}" --no-version --out="$rep" 2>&1)"
    rc=$?
  fi
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

# The files a release leaves out: they state answers, and only the teacher's tree runs them
# (the judges of grade compute what the exercises ask, 2.3.2-2's in three lines).
RELEASE_LEAVE_OUT=(tests/test_exercises.cpp tests/test_exercises_class.cpp tests/test_book.cpp
                   tests/mutants.txt tests/mutants_selftest.txt exercises/judge.cpp
                   exercises/judge_2_1.h exercises/judge_2_2.h exercises/judge_2_3.h)

# answer_values: the values of the answers, one per line, from book/solutions.md.
answer_values() {
  sed -n 's/^<!-- values: \(.*\) -->$/\1/p' "$HERE/book/solutions.md" | tr '|' '\n' | sed 's/^ *//; s/ *$//; /^$/d'
}

cmd_release() {
  local variant="" roster=""
  while [ $# -gt 0 ]; do
    case "$1" in
      --variant) variant="${2:-}"; shift 2 || die "release: --variant wants a number" ;;
      --roster) roster="${2:-}"; shift 2 || die "release: --roster wants a file" ;;
      --*) die "release: unknown option '$1' (--variant N, --roster FILE)" ;;
      *) break ;;
    esac
  done
  [ $# -ge 2 ] || die "usage: release [--variant N | --roster FILE] ID... DIR"
  [ -z "$variant" ] || [[ $variant =~ ^[0-9]{1,18}$ ]] || die "release: --variant wants a number, not '$variant'"
  [ -z "$variant" ] || [ -z "$roster" ] || die "release: --variant and --roster exclude each other (the roster gives each student's variant)"
  if [ -n "$roster" ]; then
    # One workspace per student of the roster, DIR/NAME, each with its seed as the variant:
    # the seed that grade --roster then draws the judge's inputs from.
    [ -f "$roster" ] || die "release: no roster file '$roster'"
    local names=() name sd line=0
    while IFS=$'\t' read -r name sd _; do
      line=$((line + 1))
      case "$name" in ''|'#'*) continue ;; esac
      [[ $name =~ ^[A-Za-z0-9._-]+$ ]] && [ "$name" != . ] && [ "$name" != .. ] ||
        die "release: $roster, line $line: the workspace name '$name' is not letters, digits, '.', '_' or '-'"
      [[ $sd =~ ^[0-9]{1,18}$ ]] || die "release: $roster, line $line: the seed of $name is '$sd', not a number"
      names+=("$name:$sd")
    done <"$roster"
    [ ${#names[@]} -gt 0 ] || die "release: $roster names no student"
    local dir="${!#}" ns
    [ ! -e "$dir" ] || [ -z "$(ls -A "$dir" 2>/dev/null)" ] || die "$dir exists and is not empty"
    local out made=()
    for ns in "${names[@]}"; do
      if ! out="$(cmd_release --variant "${ns##*:}" "${@:1:$#-1}" "$dir/${ns%:*}")"; then
        # Nothing half-made: the workspaces of this command go with the one that failed.
        local m; for m in "${made[@]}"; do rm -rf "${dir:?}/$m"; done
        die "release: stopped at ${ns%:*}; none of the roster's workspaces was kept"
      fi
      made+=("${ns%:*}")
      echo "${out%%$'\n'*}"
    done
    echo "students check with: scripts/exercise.sh check   (inside their workspace)"
    return
  fi
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
  # Files that state answers (the machinery's tests and the class test hold whole solutions, the
  # mutants solution lines, the book tool's test the answers' values) are left out; the tests
  # of the workspace build without them.
  local f
  for f in "${RELEASE_LEAVE_OUT[@]}"; do rm -f "$abs/$f"; done
  # The tests and their hints of prove and measure exercises state the answers: the teacher's.
  awk '/^#/ || /^[ \t]*$/ { kind = ""; print; next }
       /^kind:/ { kind = $2 }
       (kind == "prove" || kind == "measure") && /^(test|hint):/ { next }
       { print }' "$HERE/exercises/exercises.txt" >"$abs/exercises/exercises.txt"
  # The values of the answers (book/solutions.md) in the library, tests, scripts and tools (the
  # chapter programs measure what measure exercises ask, and the book's pages have their own
  # edition check): a comment holding one goes; one in code stops the release, and the
  # half-made workspace goes.
  local values leaks=""; values="$(answer_values)"
  while IFS= read -r f; do
    [ -n "$f" ] || continue
    local tmp; tmp="$(mktemp)"
    if ! awk -v values="$values" -v mode=strip -f "$HERE/exercises/answer_values.awk" "$abs/$f" >"$tmp" 2>>"$abs/.leaks"; then
      leaks=1
    fi
    cat "$tmp" >"$abs/$f"; rm -f "$tmp"
  done < <(cd "$abs" && find code tests scripts exercises cli book -type f \( -name '*.cpp' -o -name '*.h' -o -name '*.sh' -o -name '*.txt' \) -print0 2>/dev/null |
           xargs -0 -r awk -v values="$values" -v mode=list -f "$HERE/exercises/answer_values.awk" | cut -d: -f1 | sort -u)
  if [ -n "$leaks" ]; then
    local why; why="$(sed "s#^$abs/##" "$abs/.leaks")"
    rm -rf "$abs"
    die "the release would show answers; nothing released:
$why"
  fi
  rm -f "$abs/.leaks"
  { echo "# Made by scripts/exercise.sh release: the exercises of this workspace."
    echo "ids: ${sel[*]}"
    [ -z "$variant" ] || echo "variant: $variant"; } >"$abs/.exercise"
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
  echo "released ${sel[*]} into $abs${variant:+ (variant $variant)} (every solution stripped; hand this directory out)"
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

# workspace_variant DIR: the variant stored by release --variant in DIR/.exercise (nothing when
# none, or when it is not a number: the tests then draw the inputs every workspace draws).
workspace_variant() {
  [ -f "$1/.exercise" ] || return 0
  awk '/^variant:[ \t]*[0-9]+[ \t]*$/ { sub(/^variant:[ \t]*/, ""); sub(/[ \t]*$/, ""); print; exit }' "$1/.exercise"
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

# test_files DIR ID...: the files of DIR/tests that hold the test cases of the implement
# exercises ID... (their names or doctest patterns: * any characters, case ignored), one per
# line, sorted; the check builds dt_tests from these alone (and main.cpp), not from the whole
# suite. Dies if a test names no file.
test_files() {
  local dir="$1" id name re found c k q='"'
  shift
  for id in "$@"; do
    [ "$(field "$id" kind)" = implement ] || continue
    while IFS= read -r name; do
      # The name as an extended regular expression: * for any characters, specials escaped.
      re="" k=0
      while [ "$k" -lt "${#name}" ]; do
        c="${name:k:1}"
        if [ "$c" = '*' ]; then re+='.*'
        elif [[ '[]\.^$+?(){}|' == *"$c"* ]]; then re+="\\$c"
        else re+="$c"
        fi
        k=$((k + 1))
      done
      re="TEST_CASE[(]$q$re$q"
      found="$(grep -liE -- "$re" "$dir"/tests/*.cpp || true)"
      [ -n "$found" ] || die "exercise $id: no file of $dir/tests holds the test '$name'"
      printf '%s\n' "$found"
    done < <(field "$id" test)
  done | xargs -r -n1 basename | sort -u
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
    local log files; log="$(mktemp)"
    files="$(test_files "$dir" "${SEL[@]}" | paste -sd';')"
    echo "building $build (target dt_tests, from tests/${files//;/, tests/}) ..."
    if ! { cmake -S "$dir" -B "$build" -DCMAKE_BUILD_TYPE=Release "-DDT_TEST_FILES=$files" >"$log" 2>&1 &&
           cmake --build "$build" --target dt_tests -j "$JOBS" >>"$log" 2>&1; }; then
      echo "FAIL: the project does not build; the first errors:"
      grep -E 'error|Error' "$log" | head -n 15 | sed 's/^/  /'
      echo "hint: fix the compile errors first (full log: $log)"
      return 1
    fi
    rm -f "$log"
  fi
  local variant; variant="$(workspace_variant "$dir")"
  if [ -n "$variant" ]; then
    echo "variant $variant: your tests draw their own random inputs"
    export DT_VARIANT="$variant"
  else
    unset DT_VARIANT
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
# Grading never trusts the student's process. Each student's code is compiled, linked and run in
# bubblewrap as nobody: no network, no view of the teacher's tree, of the other workspaces or of
# this grader's folder, limits on CPU, memory, processes and file size, and everything it started
# killed when it ends or times out. The verdict comes from outside: the judge (exercises/judge.cpp)
# linked with the student's code prints what the functions return; this script, which never runs
# student code, compares that with the judge linked with the teacher's solution. The teacher's
# doctest tests run in the sandbox too: their report names the first failing check, and since the
# student's process can write it, it can only lower a grade, never raise it.

# flags_of BUILD VAR: a variable of the library's flags.make (CXX_FLAGS, CXX_DEFINES,
# CXX_INCLUDES), one word per line. CMake quotes a word with a space or a quote in it
# (-I"/tmp/a b/c'd/code"); xargs reads those quotes as a shell would, and nothing is evaluated.
flags_of() { sed -n "s/^$2 = //p" "$1/CMakeFiles/dt.dir/flags.make" | xargs -r printf '%s\n'; }

# sandbox BOX SECONDS [DIR...] -- COMMAND...: COMMAND in bubblewrap as nobody, in BOX (seen as
# /box: with an empty private /tmp the only writable folder), the DIRs visible read-only at their
# own paths, no stdin. After SECONDS it is killed with every process it started (they live in
# its own PID namespace, which ends with it). Status: COMMAND's, 137 on the timeout.
# SANDBOX_CWD: its working directory (default /box).
sandbox() {
  local box="$1" t="$2"; shift 2
  local ro=() d
  while [ $# -gt 0 ] && [ "$1" != -- ]; do ro+=(--ro-bind "$1" "$1"); shift; done
  shift
  local limits=(prlimit --cpu="$t" --as=$((3 << 30)) --nproc=64 --fsize=$((128 << 20)) --nofile=256 --core=0)
  if [ "${GRADE_UNSANDBOXED:-0}" = 1 ]; then
    # /box at the start of an argument is BOX itself here.
    (cd "${SANDBOX_CWD:-$box}" && exec timeout -s KILL "$t" "${limits[@]}" "${@/#\/box/$box}") </dev/null
    return
  fi
  local sys=()
  for d in /usr /bin /sbin /lib /lib32 /lib64 /libx32 /etc/alternatives; do
    if [ -L "$d" ]; then sys+=(--symlink "$(readlink "$d")" "$d")
    elif [ -d "$d" ]; then sys+=(--ro-bind "$d" "$d"); fi
  done
  timeout -s KILL "$((t + 5))" setpriv --reuid=65534 --regid=65534 --clear-groups --inh-caps=-all \
    "${DT_GRADE_BWRAP:-bwrap}" --unshare-all --die-with-parent --new-session "${sys[@]}" --proc /proc --dev /dev \
      --size $((128 << 20)) --tmpfs /tmp --bind "$box" /box "${ro[@]}" --chdir "${SANDBOX_CWD:-/box}" \
      --clearenv --setenv PATH /usr/bin:/bin --setenv HOME /box --setenv TMPDIR /tmp \
      -- "${limits[@]}" timeout -s KILL "$t" "$@" </dev/null
}

# sandbox_refusal: why the sandbox cannot run here (nothing when it can).
sandbox_refusal() {
  local probe err
  probe="$(mktemp -d)"; chmod 711 "$probe"; mkdir "$probe/box"; chown 65534:65534 "$probe/box"
  command -v "${DT_GRADE_BWRAP:-bwrap}" >/dev/null || { echo "bwrap (Debian's bubblewrap) is not installed (scripts/deps.sh installs it)"; rm -rf "$probe"; return; }
  if ! err="$(sandbox "$probe/box" 10 -- sh -c 'echo ok >/box/probe' 2>&1)" || [ "$(cat "$probe/box/probe" 2>/dev/null)" != ok ]; then
    echo "bubblewrap cannot make a sandbox here (user namespaces off, or not root to drop to nobody): ${err:-no output}"
  fi
  rm -rf "$probe"
}

# undefined OBJECT: the symbols OBJECT uses and does not define, mangled, sorted.
undefined() { nm -u "$1" | awk '{ print $NF }' | sort -u; }

# symbols_refusal ID STUDENT_O STUB_O TEACHER_O: the first function the student's object calls
# that the exercise does not allow: a symbol the stub does not already use must be used by the
# teacher's solution or match exercises/allowed_symbols.txt or an allow: line of the exercise,
# and may not name a forbid: word. Nothing when all are allowed.
symbols_refusal() {
  local id="$1" new allowed words
  new="$(comm -23 <(undefined "$2") <(undefined "$3"))"
  [ -n "$new" ] || return 0
  allowed="$(grep -vE '^(#|[[:space:]]*$)' "$HERE/exercises/allowed_symbols.txt"; field "$id" allow)"
  words="$(field "$id" forbid | grep -E '^[A-Za-z_][A-Za-z0-9_:]*$' || true)"
  paste -d '\t' <(echo "$new") <(echo "$new" | c++filt) |
    awk -F '\t' -v teacher="$(undefined "$4")" -v allowed="$allowed" -v words="$words" '
      BEGIN { nt = split(teacher, t, "\n"); for (i = 1; i <= nt; i++) ok[t[i]] = 1
              na = split(allowed, a, "\n"); nw = split(words, w, "\n") }
      {
        for (i = 1; i <= nw; i++) {
          x = $2; gsub(/[^A-Za-z0-9_:]+/, " ", x)
          if ((" " x " ") ~ ("[ :]" w[i] "[ :]") || (" " x " ") ~ (" " w[i] " ")) { print "calls " $2 " (a forbidden word: " w[i] ")"; exit }
        }
        if ($1 in ok) next
        for (i = 1; i <= na; i++) if (a[i] != "" && $2 ~ a[i]) next
        print "calls " $2 ", which exercise " id " does not allow (the functions of its solution and exercises/allowed_symbols.txt)"; exit
      }' id="$id"
}

# map_lines MAP FILE SHOWN: compiler messages with SPLICED:LINE turned into the student's
# SHOWN:LINE (MAP: one line per line of the spliced file, the student's line or 0); a line
# outside the regions is named as the teacher's.
map_lines() {
  awk -v shown="$3" -v spliced="$2" '
    NR == FNR { m[FNR] = $1; next }
    {
      while ((k = index($0, spliced ":")) > 0) {
        rest = substr($0, k + length(spliced) + 1)
        if (!match(rest, /^[0-9]+/)) break
        l = substr(rest, 1, RLENGTH)
        to = m[l] > 0 ? shown ":" m[l] : shown " (the teacher'"'"'s line " l ")"
        $0 = substr($0, 1, k - 1) to substr(rest, RLENGTH + 1)
      }
      print
    }' "$1" -
}

# judge_differences REFERENCE GOT: for each test K whose lines ("tK ...") in the judge's output
# GOT are not those of REFERENCE, a line "K<TAB>the first difference"; K is 0 for a difference in
# lines of no test. Nothing when GOT is REFERENCE.
judge_differences() {
  cmp -s "$1" "$2" && return 0
  awk 'function key(l) { return match(l, /^t[0-9]+ /) ? substr(l, 2, RLENGTH - 2) : 0 }
       function cut(l) { return length(l) > 160 ? substr(l, 1, 160) "..." : l }
       NR == FNR { k = key($0); r[k, ++nr[k]] = $0; keys[k] = 1; next }
       { k = key($0); g[k, ++ng[k]] = $0; keys[k] = 1 }
       END {
         for (k in keys) {
           for (i = 1; i <= nr[k] && i <= ng[k]; i++)
             if (r[k, i] != g[k, i]) break
           if (i <= nr[k] && i <= ng[k])
             printf "%s\tthe judge printed \"%s\" where the solution prints \"%s\"\n", k, cut(g[k, i]), cut(r[k, i])
           else if (nr[k] > ng[k])
             printf "%s\tthe judge printed %d of the %d lines of the solution; the next: \"%s\"\n", k, ng[k] + 0, nr[k], cut(r[k, i])
           else if (ng[k] > nr[k])
             printf "%s\tthe judge printed more than the solution: \"%s\"\n", k, cut(g[k, i])
         }
       }' "$1" "$2" | sort -n
}

# grade_one ID WORK STUDENT_DIR NUMBER SEED: one student's row, into WORK/rows/NUMBER (a folder
# of this grader that no sandbox sees).
grade_one() {
  local id="$1" work="$2" sdir="$3" num="$4" seed="$5"
  local me="$work/s$num" start=$SECONDS student f
  student="$(basename "$sdir")"
  mkdir -p "$me/src" "$me/bin"
  chmod 755 "$me" "$me/src" "$me/bin"
  fresh_box "$me/box"
  local names; mapfile -t names < <(field "$id" test)
  local ntests=${#names[@]} cols=() i judge=-
  for ((i = 0; i < ntests; i++)); do cols+=("-"); done
  row() {  # result passed first_failure
    local detail
    detail="$(tr '\t\n' '  ' <<<"$3" | sed -E 's/ +/ /g; s/^ //; s/ $//' | cut -c 1-500)"
    [ "${GRADE_UNSANDBOXED:-0}" != 1 ] || detail="UNSANDBOXED (graded without bubblewrap): ${detail:--}"
    [ "${DT_GRADE_STATIC_CHECKS:-1}" != 0 ] || detail="STATIC CHECKS OFF: ${detail:--}"
    local IFS=$'\t'
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$student" "$1" "$2/$ntests" "${cols[*]}" "$judge" "${detail:--}" \
      "$((SECONDS - start))" "$seed" >"$work/rows/$num"
  }
  if [ ! -d "$sdir" ]; then row NO-WORKSPACE 0 "$sdir is not a directory"; return; fi
  # 1. The student's regions, spliced into the teacher's files; nothing else of theirs is used.
  local sfiles=() objs=() spliced
  for f in $GRADE_FILES; do
    if [ ! -f "$sdir/$f" ]; then row NO-REGION 0 "no $f in the workspace"; return; fi
    sfiles+=("$sdir/$f")
    spliced="$me/src/$(basename "$f")"
    if ! splice "$id" "$HERE/$f" "$sdir/$f" "$spliced.map" >"$spliced" 2>"$me/splice.log"; then
      row NO-REGION 0 "$f: $(cat "$me/splice.log") (the BEGIN/END SOLUTION $id lines must stay)"; return
    fi
    chmod 644 "$spliced"
  done
  # 2. Forbidden code, read as the compiler reads it. (DT_GRADE_STATIC_CHECKS=0 turns this and
  #    step 4 off, for the machinery's test that the sandbox and the judge hold alone.)
  local bad words; mapfile -t words < <(field "$id" forbid)
  for f in $GRADE_FILES; do
    [ "${DT_GRADE_STATIC_CHECKS:-1}" != 0 ] || break
    if ! bad="$("$work/forbidden" "$id" "$sdir/$f" "${words[@]}" 2>&1)"; then
      row FORBIDDEN 0 "${bad#"$sdir/"}"; return
    fi
  done
  # 3. Compiled in the sandbox, with the headers only (no solution) and the library's flags.
  for f in $GRADE_FILES; do
    spliced="$me/src/$(basename "$f")"
    local o; o="$(basename "$f" .cpp).o"
    if ! sandbox "$me/box" 120 "$work/inc" "$me/src" -- "$GRADE_CXX" "${GRADE_ARGS[@]}" \
           -c "$spliced" -o "/box/$o" >"$me/cc.log" 2>&1; then
      row COMPILE-ERROR 0 "$(grep -m 3 -E 'error' "$me/cc.log" | map_lines "$spliced.map" "$spliced" "$f")"; return
    fi
    mv "$me/box/$o" "$me/bin/$o"
    # 4. What the object calls: only what the exercise allows.
    bad=""
    [ "${DT_GRADE_STATIC_CHECKS:-1}" = 0 ] || bad="$(symbols_refusal "$id" "$me/bin/$o" "$work/stub_$o" "$work/teacher_$o")"
    if [ -n "$bad" ]; then row FORBIDDEN 0 "$f: $bad"; return; fi
    objs+=("$me/bin/$o")
  done
  # 5. Linked in the sandbox: the judge, and the teacher's tests, each before the library.
  if ! SANDBOX_CWD="$GRADE_BUILD" sandbox "$me/box" 120 "$GRADE_BUILD" "$work/judge" "$me/bin" -- \
         "$GRADE_CXX" "${GRADE_LINK_FLAGS[@]}" "${objs[@]}" "$work/judge/judge.o" libdt.a "${GRADE_LIBS[@]}" \
         -o /box/j >"$me/ld.log" 2>&1 ||
     ! SANDBOX_CWD="$GRADE_BUILD" sandbox "$me/box" 120 "$GRADE_BUILD" "$me/bin" -- \
         "$GRADE_CXX" "${GRADE_LINK_FLAGS[@]}" "${GRADE_TEST_OBJS[@]}" "${objs[@]}" libdt.a "${GRADE_LIBS[@]}" \
         -o /box/t >>"$me/ld.log" 2>&1; then
    row LINK-ERROR 0 "$(grep -m 3 -E 'undefined|multiple|error' "$me/ld.log" | sed "s#$me/bin/##")"; return
  fi
  mv "$me/box/j" "$me/box/t" "$me/bin/"
  fresh_box "$me/box"
  # 6. The judge in the sandbox; its output, in a file of the grader, compared outside.
  local rc verdict="" result=PASS first="" diffs=""
  set +e
  sandbox "$me/box" "$TEST_TIMEOUT" "$me/bin" -- "$me/bin/j" "$id" "$seed" >"$me/results" 2>"$me/judge.err"
  rc=$?
  set -e
  if [ $rc -eq 137 ]; then judge=timeout; result=TIMEOUT; verdict="the judge's run did not finish within $TEST_TIMEOUT s (an endless loop?)"
  elif [ $rc -gt 128 ]; then judge=crash; result=CRASH; verdict="the judge's run CRASHED: $(signal_name $((rc - 128)))"
  elif [ "$(tail -n 1 "$me/results")" != "end $id" ] || [ $rc -ne 0 ]; then
    judge=exited; result=EXITED
    verdict="the program ended (exit status $rc) before the judge was done: the code called exit or ended the process some other way"
  else
    diffs="$(judge_differences "$work/reference_$seed" "$me/results")"
    if [ -z "$diffs" ]; then judge=match; else judge=differ; result=FAIL; fi
  fi
  # 7. The teacher's tests, for the failure a student can act on; a run the judge already found
  #    endless, crashing or exiting is not repeated test by test. A test's column is a pass only
  #    when the judge's lines of that test match too.
  local passed=0 k
  if [ "$judge" = match ] || [ "$judge" = differ ]; then
    local RUN_BOX="$me/box"
    for ((i = 0; i < ntests; i++)); do
      run_one "$me/bin/t" "${names[$i]}"
      fresh_box "$me/box"
      [ "$R_STATUS" != missing ] || R_STATUS=exited
      k="$(awk -F '\t' -v k=$((i + 1)) '$1 == k || $1 == 0 { sub(/^[0-9]+\t/, ""); print; exit }' <<<"$diffs")"
      if [ "$R_STATUS" = pass ] && [ -n "$k" ]; then R_STATUS=fail; R_DETAIL="$k"; fi
      cols[$i]="$R_STATUS"
      if [ "$R_STATUS" = pass ]; then passed=$((passed + 1)); continue; fi
      if [ -z "$first" ]; then
        first="test '${names[$i]}': $R_DETAIL"
        [ "$R_STATUS" = timeout ] || [ "$R_STATUS" = crash ] && first="$R_DETAIL"
        case "$R_STATUS" in timeout) result=TIMEOUT ;; crash) result=CRASH ;; exited) result=EXITED ;; *) result=FAIL ;; esac
      fi
    done
    [ -n "$first" ] || [ -z "$diffs" ] || first="$(cut -f 2 <<<"$diffs" | head -n 1)"
  fi
  rm -rf "${me:?}/bin" "${me:?}/box"
  row "$result" "$passed" "${first:-$verdict}"
}

# fresh_box DIR: DIR empty, nobody's, for one run in the sandbox (what a run left there is gone).
fresh_box() {
  rm -rf "$1"; mkdir "$1"
  [ "${GRADE_UNSANDBOXED:-0}" = 1 ] || chown 65534:65534 "$1"
  chmod 700 "$1"
}

signal_name() {
  case $1 in 4) echo SIGILL ;; 6) echo SIGABRT ;; 7) echo SIGBUS ;; 8) echo SIGFPE ;; 9) echo SIGKILL ;;
    11) echo SIGSEGV ;; *) echo "signal $1" ;; esac
}

# teacher_cc DIR COMPILER ARGS...: a compile (-c) of the teacher's own code, never a student's,
# run in DIR. Through ccache when it is installed, with DIR as its base: the same sources
# compiled again by a later grade or selftest (into another temporary DIR) come from the cache.
teacher_cc() {
  local dir="$1"; shift
  if command -v ccache >/dev/null 2>&1; then
    (cd "$dir" && CCACHE_BASEDIR="$dir" ccache "$@")
  else
    "$@"
  fi
}

# grade_prepare ID BUILD WORK: what every student's grading shares, made once, by the teacher's
# code only: the headers (no solution), the forbidden check and the judge compiled, the judge
# linked with the teacher's solution and its output for SEED (the reference), the stub's and the
# solution's objects (their undefined symbols are the allow list).
grade_prepare() {
  local id="$1" build="$2" work="$3" f o
  GRADE_BUILD="$build"
  GRADE_CXX="$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$build/CMakeCache.txt")"
  mkdir -p "$work/inc" "$work/judge"
  # Includes are bare names: the headers of every room of code/ side by side.
  cp "$HERE"/code/*.h "$HERE"/code/*/*.h "$work/inc/"
  chmod 755 "$work" "$work/inc" "$work/judge"
  local defines flags
  mapfile -t defines < <(flags_of "$build" CXX_DEFINES)
  mapfile -t flags < <(flags_of "$build" CXX_FLAGS)
  GRADE_ARGS=("${defines[@]}" -I"$work/inc" "${flags[@]}")
  local link; read -r -a link <"$build/CMakeFiles/dt_tests.dir/link.txt"
  GRADE_LINK_FLAGS=() GRADE_TEST_OBJS=() GRADE_LIBS=()
  local w after=0 skip=0
  for w in "${link[@]:1}"; do
    if [ $skip = 1 ]; then skip=0; continue; fi
    case "$w" in
      -o) skip=1 ;;
      *.o) GRADE_TEST_OBJS+=("$w") ;;
      libdt.a) after=1 ;;
      *) if [ $after = 1 ]; then GRADE_LIBS+=("$w"); else GRADE_LINK_FLAGS+=("$w"); fi ;;
    esac
  done
  # The tests' objects: main's and those of the files defining the exercise's tests (a name is
  # looked up up to its first '*'), so each student's link is small.
  local keep=() t name
  for t in "${GRADE_TEST_OBJS[@]}"; do
    case "$t" in */main.cpp.o) keep+=("$t"); continue ;; esac
    local src; src="$HERE/tests/$(basename "$t" .o)"
    while IFS= read -r name; do
      if [ -f "$src" ] && grep -qF -- "TEST_CASE(\"${name%%\**}" "$src"; then keep+=("$t"); break; fi
    done < <(field "$id" test)
  done
  GRADE_TEST_OBJS=("${keep[@]}")
  # What the links read, copied where the sandbox's user can read it: the teacher's build may
  # sit below a directory only root can enter (a fresh clone made with mktemp -d is mode 700).
  mkdir -p "$work/link"
  cp "$build/libdt.a" "$work/link/"
  for t in "${GRADE_LIBS[@]}"; do  # the build's other libraries on dt_tests' link line
    case "$t" in /*|-*) continue ;; esac
    mkdir -p "$work/link/$(dirname "$t")"
    cp "$build/$t" "$work/link/$t"
  done
  for t in "${GRADE_TEST_OBJS[@]}"; do
    mkdir -p "$work/link/$(dirname "$t")"
    cp "$build/$t" "$work/link/$t"
  done
  chmod -R a+rX "$work/link"
  GRADE_BUILD="$work/link"
  { teacher_cc "$work" "$GRADE_CXX" -std=c++17 -O1 -c "$HERE/exercises/forbidden.cpp" -o "$work/forbidden.o" &&
    "$GRADE_CXX" -o "$work/forbidden" "$work/forbidden.o"; } ||
    die "exercises/forbidden.cpp does not compile"
  teacher_cc "$work" "$GRADE_CXX" "${GRADE_ARGS[@]}" -c "$HERE/exercises/judge.cpp" -o "$work/judge/judge.o" ||
    die "exercises/judge.cpp does not compile"
  chmod 644 "$work/judge/judge.o"
  (cd "$build" && "$GRADE_CXX" "${GRADE_LINK_FLAGS[@]}" "$work/judge/judge.o" libdt.a "${GRADE_LIBS[@]}" -o "$work/judge_ref") ||
    die "the judge does not link with the teacher's library"
  "$work/judge_ref" --list | grep -qxF -- "$id" ||
    die "exercise $id has no judge in exercises/judge.cpp: grading it would trust the student's process"
  GRADE_FILES="$(region_files "$id" "$HERE" | grep -E '^code/.*\.cpp$' || true)"
  [ -n "$GRADE_FILES" ] || die "exercise $id has no solution region in a .cpp of code/"
  for f in $GRADE_FILES; do
    o="$(basename "$f" .cpp).o"
    strip_file "$id" "$HERE/$f" >"$work/stub_$(basename "$f")"
    teacher_cc "$work" "$GRADE_CXX" "${GRADE_ARGS[@]}" -c "$work/stub_$(basename "$f")" -o "$work/stub_$o" 2>/dev/null &&
      teacher_cc "$work" "$GRADE_CXX" "${GRADE_ARGS[@]}" -c "$HERE/$f" -o "$work/teacher_$o" || die "$f does not compile"
  done
}

# reference WORK ID SEED: the teacher's judge output for SEED (made once per seed).
reference() {
  local ref="$1/reference_$3"
  [ -f "$ref" ] || { "$1/judge_ref" "$2" "$3" >"$ref.tmp" && mv "$ref.tmp" "$ref"; } ||
    die "the judge fails on the teacher's solution of $2 (seed $3)"
  echo "$ref"
}

# export_grades FORMAT ID TSV ROSTER: the grades of TSV (grade's own table) in FORMAT on stdout:
#   tsv         the table as it is
#   junit       JUnit XML: a testsuite per student, a testcase per test (a failure whose type
#               is the test's column, or the result when the test was not run), as CI servers
#               read doctest's --reporters=junit
#   gradescope  Gradescope's results.json of one submission: score, max_score, output, tests
#               (name, score, max_score, status, output, visibility)
#   canvas      Canvas' gradebook CSV: Student, ID, SIS User ID, SIS Login ID, Section, then the
#               exercise's column (tests passed), a "Points Possible" row first; the roster's
#               columns 3-7 fill the student's name and ids
#   moodle      Moodle's grade import CSV: Username (the roster's name, else the workspace),
#               the grade (tests passed) and a feedback column
export_grades() {
  local format="$1" id="$2" tsv="$3" roster="${4:-}"
  if [ "$format" = tsv ]; then cat "$tsv"; return; fi
  [ "$format" != gradescope ] || [ "$(awk 'END { print NR }' "$tsv")" = 2 ] ||
    die "the gradescope format holds one submission (Gradescope runs the autograder once per student)"
  awk -F '\t' -v format="$format" -v id="$id" -v roster="$roster" '
    function xml(s) { gsub(/&/, "\\&amp;", s); gsub(/</, "\\&lt;", s); gsub(/>/, "\\&gt;", s); gsub(/"/, "\\&quot;", s); return s }
    function json(s) { gsub(/\\/, "\\\\", s); gsub(/"/, "\\\"", s); gsub(/\t/, "\\t", s); gsub(/[\001-\037]/, " ", s); return "\"" s "\"" }
    function csv(s) { if (s ~ /[",\r\n]/) { gsub(/"/, "\"\"", s); s = "\"" s "\"" } return s }
    BEGIN {
      if (roster != "") while ((getline line < roster) > 0) {
        if (line ~ /^#/) continue
        nf = split(line, rf, "\t"); for (i = 3; i <= 7; i++) info[rf[1], i] = i <= nf ? rf[i] : ""
        known[rf[1]] = 1
      }
    }
    NR == 1 { n = NF - 7; for (i = 1; i <= n; i++) test[i] = $(i + 3); next }
    {
      s++; who[s] = $1; res[s] = $2; split($3, p, "/"); passed[s] = p[1]; judge[s] = $(n + 4)
      detail[s] = $(n + 5); secs[s] = $(n + 6)
      for (i = 1; i <= n; i++) col[s, i] = $(i + 3)
    }
    END {
      if (format == "junit") {
        # A test that was not run (the judge timed out, crashed or exited; the code was
        # refused) failed as much as one that ran: its failure says why.
        fails = 0; for (k = 1; k <= s; k++) for (i = 1; i <= n; i++) fails += col[k, i] != "pass"
        printf "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"exercise %s\" tests=\"%d\" failures=\"%d\">\n", xml(id), s * n, fails
        for (k = 1; k <= s; k++) {
          f = 0; for (i = 1; i <= n; i++) f += col[k, i] != "pass"
          printf "  <testsuite name=\"%s\" tests=\"%d\" failures=\"%d\" time=\"%s\">\n", xml(who[k]), n, f, secs[k]
          for (i = 1; i <= n; i++) {
            printf "    <testcase classname=\"%s\" name=\"%s\"", xml(who[k]), xml(test[i])
            if (col[k, i] == "pass") print "/>"
            else printf ">\n      <failure type=\"%s\" message=\"%s\"/>\n    </testcase>\n", xml(col[k, i] == "-" ? res[k] : col[k, i]), xml(res[k] ": " detail[k])
          }
          print "  </testsuite>"
        }
        print "</testsuites>"
      } else if (format == "gradescope") {
        printf "{\n  \"score\": %d,\n  \"max_score\": %d,\n  \"output\": %s,\n  \"tests\": [\n", passed[1], n, json(res[1] (detail[1] == "-" ? "" : ": " detail[1]))
        for (i = 1; i <= n; i++)
          printf "    {\"name\": %s, \"score\": %d, \"max_score\": 1, \"status\": %s, \"output\": %s, \"visibility\": \"visible\"}%s\n",
            json(test[i]), col[1, i] == "pass", json(col[1, i] == "pass" ? "passed" : "failed"),
            json(col[1, i] == "pass" ? "" : (col[1, i] == "-" ? "not run: " : col[1, i] ": ") detail[1]), i < n ? "," : ""
        print "  ]\n}"
      } else if (format == "canvas") {
        printf "Student,ID,SIS User ID,SIS Login ID,Section,%s\n", csv("Exercise " id)
        printf "Points Possible,,,,,%d\n", n
        for (k = 1; k <= s; k++)
          printf "%s,%s,%s,%s,%s,%d\n", csv(known[who[k]] && info[who[k], 3] != "" ? info[who[k], 3] : who[k]),
            csv(info[who[k], 4]), csv(info[who[k], 5]), csv(info[who[k], 6]), csv(info[who[k], 7]), passed[k]
      } else if (format == "moodle") {
        printf "Username,%s,%s\n", csv("Exercise " id), csv("Exercise " id " feedback")
        for (k = 1; k <= s; k++)
          printf "%s,%d,%s\n", csv(known[who[k]] && info[who[k], 3] != "" ? info[who[k], 3] : who[k]), passed[k],
            csv(res[k] " " passed[k] "/" n (detail[k] == "-" ? "" : ": " detail[k]))
      }
    }' "$tsv"
}

# roster_field FILE STUDENT N: column N of STUDENT's line of the roster (tab-separated:
# workspace name, seed, name, ID, SIS user ID, SIS login ID, section; '#' starts a comment).
roster_field() {
  [ -n "$1" ] || return 0
  awk -F '\t' -v s="$2" -v n="$3" '!/^#/ && $1 == s { print $n; exit }' "$1"
}

# export FORMAT ID TSV [ROSTER]: a table of grade (TSV) in another format.
cmd_export() {
  [ $# -ge 3 ] && [ $# -le 4 ] || die "usage: export tsv|canvas|moodle|gradescope|junit ID GRADES.TSV [ROSTER]"
  case "$1" in tsv|canvas|moodle|gradescope|junit) ;; *) die "export: no format '$1' (tsv, canvas, moodle, gradescope, junit)" ;; esac
  exists "$2"
  [ -f "$3" ] || die "export: no file '$3'"
  [ -z "${4:-}" ] || [ -f "$4" ] || die "export: no roster file '$4'"
  head -n 1 "$3" | grep -q $'^student\tresult\tpassed\t' || die "export: $3 is not a table of grade"
  export_grades "$1" "$2" "$3" "${4:-}"
}

cmd_grade() {
  local format=tsv seed=1 roster="" summary=""
  GRADE_UNSANDBOXED="${DT_GRADE_UNSANDBOXED:-0}"
  while [ $# -gt 0 ]; do
    case "$1" in
      --format) format="${2:-}"; shift 2 ;;
      --seed) seed="${2:-}"; shift 2 ;;
      --roster) roster="${2:-}"; shift 2 ;;
      --unsandboxed) GRADE_UNSANDBOXED=1; shift ;;
      --summary) summary="${2:-}"; shift 2 ;;
      --*) die "grade: unknown option '$1' (--format tsv|canvas|moodle|gradescope|junit, --seed N, --roster FILE, --summary DIR, --unsandboxed)" ;;
      *) break ;;
    esac
  done
  [ $# -ge 2 ] || die "usage: grade [--format F] [--seed N] [--roster FILE] [--unsandboxed] ID STUDENT_DIR... > grades.tsv"
  case "$format" in tsv|canvas|moodle|gradescope|junit) ;; *) die "grade: no format '$format' (tsv, canvas, moodle, gradescope, junit)" ;; esac
  [[ $seed =~ ^[0-9]{1,18}$ ]] || die "grade: --seed wants a number, not '$seed'"
  [ -z "$roster" ] || [ -f "$roster" ] || die "grade: no roster file '$roster'"
  local id="$1"; shift
  exists "$id"
  local kind; kind="$(field "$id" kind)"
  if [ "$kind" != implement ]; then grade_answers "$id" "$@"; return; fi
  [ "$format" != gradescope ] || [ $# -eq 1 ] || die "the gradescope format holds one submission (Gradescope runs the autograder once per student)"
  if [ "$GRADE_UNSANDBOXED" = 1 ]; then
    echo "grade: WARNING: student code runs WITHOUT the sandbox (--unsandboxed): it can read and change every file this user can" >&2
  else
    [ "$(id -u)" = 0 ] || die "grade runs student code as the user nobody in bubblewrap and must start as root (in CI it does); --unsandboxed grades without the sandbox"
    local why; why="$(sandbox_refusal)"
    [ -z "$why" ] || die "grade refuses to run student code: $why (--unsandboxed grades without the sandbox, with a warning on every row)"
  fi
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
  local work; work="$(mktemp -d)"
  # shellcheck disable=SC2064
  trap "rm -rf '$work'" EXIT
  grade_prepare "$id" "$build" "$work"
  mkdir -p "$work/rows"; chmod 700 "$work/rows"
  local names; mapfile -t names < <(field "$id" test)
  local n=0 running=0 s sd
  for s in "$@"; do
    sd="$(roster_field "$roster" "$(basename "$s")" 2)"
    [ -n "$sd" ] || sd="$seed"
    [[ $sd =~ ^[0-9]{1,18}$ ]] || die "grade: the roster gives $(basename "$s") the seed '$sd', not a number"
    reference "$work" "$id" "$sd" >/dev/null
  done
  for s in "$@"; do
    n=$((n + 1))
    sd="$(roster_field "$roster" "$(basename "$s")" 2)"
    ( set +e; grade_one "$id" "$work" "$s" "$(printf '%04d' $n)" "${sd:-$seed}" ) &
    running=$((running + 1))
    if [ $running -ge "$JOBS" ]; then wait -n || true; running=$((running - 1)); fi
  done
  wait
  local header
  header="$(IFS=$'\t'; printf 'student\tresult\tpassed\t%s\tjudge\tfirst_failure\tseconds\tseed' "${names[*]}")"
  { echo "$header"; cat "$work"/rows/*; } >"$work/grades.tsv"
  export_grades "$format" "$id" "$work/grades.tsv" "$roster"
  [ -z "$summary" ] || cmd_summary "$id" "$work/grades.tsv" "$summary" >&2
  echo "grade: $n student$([ "$n" = 1 ] || echo s) of $id graded ($(awk -F '\t' 'NR > 1 && $2 == "PASS"' "$work/grades.tsv" | wc -l) pass)" >&2
}

# similar [--threshold T] ID STUDENT_DIR...: the pairs of students whose code for ID has nearly
# the same shape: the regions read as tokens (exercises/forbidden.cpp --shape: names and literals
# blurred, so renaming changes nothing), cut into runs of 5 tokens; the share of runs two
# students have in common (those of the stub left aside) is at least T (default 0.8). A hint to
# talk about, never a verdict: short solutions look alike by nature, and two students may reach
# the same code honestly.
cmd_similar() {
  local threshold=0.8
  if [ "${1:-}" = --threshold ]; then threshold="${2:-}"; shift 2; fi
  [[ $threshold =~ ^(0(\.[0-9]+)?|1(\.0*)?)$ ]] || die "similar: --threshold wants a number from 0 to 1, not '$threshold'"
  [ $# -ge 3 ] || die "usage: similar [--threshold T] ID STUDENT_DIR STUDENT_DIR..."
  local id="$1"; shift
  exists "$id"
  [ "$(field "$id" kind)" = implement ] || die "similar compares code: $id is a $(field "$id" kind) exercise"
  local work; work="$(mktemp -d)"
  # shellcheck disable=SC2064
  trap "rm -rf '$work'" EXIT
  g++ -std=c++17 -O1 -o "$work/forbidden" "$HERE/exercises/forbidden.cpp" || die "exercises/forbidden.cpp does not compile"
  local files f s; files="$(region_files "$id" "$HERE" | grep -E '^code/.*\.cpp$' || true)"
  for f in $files; do
    strip_file "$id" "$HERE/$f" >"$work/stub.cpp"
    "$work/forbidden" --shape "$id" "$work/stub.cpp" >>"$work/stub.shape" || true
  done
  for s in "$@"; do
    : >"$work/$(basename "$s").shape"
    for f in $files; do
      [ -f "$s/$f" ] && "$work/forbidden" --shape "$id" "$s/$f" >>"$work/$(basename "$s").shape" 2>/dev/null || true
    done
  done
  local shapes=(); for s in "$@"; do shapes+=("$(basename "$s").shape"); done
  echo "# similar $id: pairs whose code shares at least $threshold of its runs of 5 tokens (names and literals blurred); a hint, not a verdict"
  printf 'share\tstudent\tstudent\truns\n'
  (cd "$work" && awk -v t="$threshold" '
      FNR == 1 { name = FILENAME; sub(/\.shape$/, "", name); k = 0 }
      { tok[name, ++k] = $0; len[name] = k }
      END {
        for (s in len) {
          n = 0
          for (i = 1; i + 4 <= len[s]; i++) {
            g = tok[s, i] " " tok[s, i + 1] " " tok[s, i + 2] " " tok[s, i + 3] " " tok[s, i + 4]
            if (s == "stub") stubgram[g] = 1
            else if (!((s, g) in has)) { has[s, g] = 1; gram[s, ++n] = g }
          }
          count[s] = n
        }
        m = 0
        for (s in count) if (s != "stub") who[++m] = s
        for (a = 1; a <= m; a++) for (b = a + 1; b <= m; b++) {
          x = who[a]; y = who[b]; both = 0; nx = 0; ny = 0
          for (i = 1; i <= count[x]; i++) if (!(gram[x, i] in stubgram)) { nx++; if ((y, gram[x, i]) in has) both++ }
          for (i = 1; i <= count[y]; i++) if (!(gram[y, i] in stubgram)) ny++
          union = nx + ny - both
          if (union > 0 && both / union >= t) printf "%.2f\t%s\t%s\t%d\n", both / union, x < y ? x : y, x < y ? y : x, both
        }
      }' stub.shape "${shapes[@]}") | sort -t "$(printf '\t')" -k1,1nr -k2,2
}

# summary ID GRADES.TSV OUT: OUT/summary.html, the class at a glance for the teacher: a gnuplot
# histogram of the passes of each test (OUT/passes.png, said in words too), the results by
# kind, the students that did not pass with their first failure, and the slowest students.
cmd_summary() {
  [ $# -eq 3 ] || die "usage: summary ID GRADES.TSV OUTDIR"
  local id="$1" tsv="$2" out="$3"
  exists "$id"
  [ -f "$tsv" ] || die "summary: no file '$tsv'"
  head -n 1 "$tsv" | grep -q $'^student\tresult\tpassed\t' || die "summary: $tsv is not a table of grade"
  mkdir -p "$out"
  local data="$out/passes.dat"
  # One line per test: its number, how many students passed it, how many were graded.
  awk -F '\t' 'NR == 1 { n = NF - 7; next }
               { s++; for (i = 1; i <= n; i++) p[i] += $(i + 3) == "pass" }
               END { for (i = 1; i <= n; i++) printf "%d %d %d\n", i, p[i], s }' "$tsv" >"$data"
  local students; students="$(awk 'END { print NR - 1 }' "$tsv")"
  gnuplot <<GP || die "summary: gnuplot could not draw $out/passes.png"
set terminal pngcairo size 800,420 enhanced font 'Sans,12' background rgb 'white'
set output '$out/passes.png'
set title 'Exercise $id: students passing each test (of $students)'
set xlabel 'test (numbered as in the table below)'
set ylabel 'students passing'
set yrange [0:$students + 0.5]
set ytics $(( (students + 9) / 10 ))
set xrange [0.4:$(wc -l <"$data") + 0.6]
set xtics 1
set grid ytics
set boxwidth 0.6
set style fill solid 0.6 border rgb 'black'
plot '$data' using 1:2 with boxes lc rgb '#1f5fa8' notitle, \
     '' using 1:2:(sprintf('%d', \$2)) with labels offset 0,0.8 notitle
GP
  awk -F '\t' -v id="$id" '
    function h(s) { gsub(/&/, "\\&amp;", s); gsub(/</, "\\&lt;", s); gsub(/>/, "\\&gt;", s); return s }
    NR == 1 { n = NF - 7; for (i = 1; i <= n; i++) test[i] = $(i + 3); next }
    {
      s++; who[s] = $1; res[s] = $2; got[s] = $3; first[s] = $(n + 5); secs[s] = $(n + 6) + 0
      kinds[$2]++; for (i = 1; i <= n; i++) p[i] += $(i + 3) == "pass"
    }
    END {
      print "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">"
      printf "<title>Exercise %s: the class at a glance</title>\n", h(id)
      print "<style>body { font-family: sans-serif; max-width: 60em; margin: 2em auto; color: #111; line-height: 1.4 }"
      print "table { border-collapse: collapse; margin: 1em 0 } th, td { border: 1px solid #666; padding: 0.3em 0.6em; text-align: left; vertical-align: top }"
      print "th { background: #e8eef6 } img { max-width: 100%; height: auto }</style>\n</head>\n<body>\n<main>"
      printf "<h1>Exercise %s: the class at a glance</h1>\n", h(id)
      line = ""
      split("PASS FAIL TIMEOUT CRASH EXITED FORBIDDEN COMPILE-ERROR LINK-ERROR NO-REGION NO-WORKSPACE", order, " ")
      for (r = 1; r in order; r++) if (order[r] in kinds) line = line (line == "" ? "" : ", ") kinds[order[r]] " " h(order[r])
      printf "<p>%d students graded: %s.</p>\n", s, line
      print "<h2>Passes of each test</h2>"
      alt = "Bar chart of the students passing each test:"
      for (i = 1; i <= n; i++) alt = alt sprintf(" test %d, %d of %d;", i, p[i], s)
      printf "<figure>\n<img src=\"passes.png\" width=\"800\" height=\"420\" alt=\"%s\">\n", h(alt)
      print "<figcaption>The number of students passing each test; the table below names the tests and gives the same numbers.</figcaption>\n</figure>"
      print "<table>\n<caption>The tests</caption>\n<thead><tr><th scope=\"col\">test</th><th scope=\"col\">name</th><th scope=\"col\">students passing</th></tr></thead>\n<tbody>"
      for (i = 1; i <= n; i++) printf "<tr><td>%d</td><td>%s</td><td>%d of %d</td></tr>\n", i, h(test[i]), p[i], s
      print "</tbody>\n</table>"
      print "<h2>Students who did not pass</h2>"
      bad = 0
      for (k = 1; k <= s; k++) if (res[k] != "PASS") bad++
      if (bad == 0) print "<p>Every student passed.</p>"
      else {
        print "<table>\n<caption>Each with the first failure the grading found</caption>\n<thead><tr><th scope=\"col\">student</th><th scope=\"col\">result</th><th scope=\"col\">tests passed</th><th scope=\"col\">first failure</th></tr></thead>\n<tbody>"
        for (k = 1; k <= s; k++) if (res[k] != "PASS")
          printf "<tr><td>%s</td><td>%s</td><td>%s</td><td>%s</td></tr>\n", h(who[k]), h(res[k]), h(got[k]), h(first[k])
        print "</tbody>\n</table>"
      }
      print "<h2>The slowest students to grade</h2>"
      print "<table>\n<caption>Up to five, with the seconds their grading took</caption>\n<thead><tr><th scope=\"col\">student</th><th scope=\"col\">seconds</th><th scope=\"col\">result</th></tr></thead>\n<tbody>"
      for (r = 1; r <= 5 && r <= s; r++) {
        best = 0
        for (k = 1; k <= s; k++) if (!(k in shown) && (best == 0 || secs[k] > secs[best])) best = k
        shown[best] = 1
        printf "<tr><td>%s</td><td>%d</td><td>%s</td></tr>\n", h(who[best]), secs[best], h(res[best])
      }
      print "</tbody>\n</table>\n</main>\n</body>\n</html>"
    }' "$tsv" >"$out/summary.html"
  rm -f "$data"
  echo "$out/summary.html"
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
  for h in "$HERE"/code/*.h "$HERE"/code/*/*.h; do
    awk -v fn="$1" -v file="${h#"$HERE"/}" '
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
            [ -n "$sig" ] || die "exercise $id: no declaration of $fn in a header of code/"
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
# BUILD's library, whose members for those files are then never pulled in; the restored
# solutions are BUILD's dt_tests itself.
cmd_selftest() {
  [ $# -ge 1 ] || die "usage: selftest BUILD [ID...]"
  local build; build="$(cd "$1" && pwd)"; shift
  local objs="$build/CMakeFiles/dt_tests.dir/tests"
  [ -f "$build/libdt.a" ] && [ -d "$objs" ] && [ -x "$build/dt_tests" ] || die "$build has no libdt.a, dt_tests or its objects (build dt_tests first)"
  TEST_TIMEOUT="${DT_TEST_TIMEOUT:-60}"
  SELFTEST_VARIANT="${DT_SELFTEST_VARIANT:-7}"
  [[ $SELFTEST_VARIANT =~ ^[1-9][0-9]{0,17}$ ]] || die "DT_SELFTEST_VARIANT wants a number from 1, not '$SELFTEST_VARIANT'"
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
  # What dt_tests links after its objects (the library, the book tool's, GMP, ...), as its
  # link line names them; a relative path is the build's.
  local test_libs=() w link
  read -r -a link <"$build/CMakeFiles/dt_tests.dir/link.txt"
  for w in "${link[@]}"; do
    case "$w" in
      *.a|*.so|-l*) if [[ $w = /* || $w = -l* ]]; then test_libs+=("$w"); else test_libs+=("$build/$w"); fi ;;
    esac
  done
  work="$(mktemp -d)"
  trap 'rm -rf "$work"' RETURN
  # The library's headers are found by bare name in code/ and each of its rooms.
  local code_inc=() d
  for d in "$HERE"/code "$HERE"/code/*/; do code_inc+=(-I"${d%/}"); done
  # The judges of grade (exercises/judge.cpp) and the library's output for each.
  teacher_cc "$work" g++ -std=c++17 -O1 -ffp-contract=off "${code_inc[@]}" -c "$HERE/exercises/judge.cpp" -o "$work/judge.o" &&
    g++ -o "$work/judge_ref" "$work/judge.o" "$build/libdt.a" -lmpfr -lgmp -pthread ||
    die "exercises/judge.cpp does not compile or link with $build/libdt.a"
  local judged; judged="$("$work/judge_ref" --list)"
  for id in $sel; do
    local files; files="$(region_files "$id" "$HERE" | grep '^code/.*\.cpp$' || true)"
    if [ -z "$files" ]; then echo "FAIL $id: no solution region in a .cpp of code/"; fail=1; continue; fi
    # The stub, compiled and linked before BUILD's library: its check must fail and say why.
    local o_list=() ok=1 res rc same f o
    for f in $files; do
      o="$work/$(basename "$f" .cpp).stub.o"
      strip_file "$id" "$HERE/$f" >"$work/$(basename "$f")"
      if ! teacher_cc "$work" g++ -std=c++17 -O1 -ffp-contract=off "${code_inc[@]}" -c "$work/$(basename "$f")" -o "$o" \
           2>"$work/cc.log"; then
        echo "FAIL $id: the stub copy of $f does not compile:"; head -n 20 "$work/cc.log"; ok=0
      fi
      o_list+=("$o")
    done
    [ $ok = 1 ] || { fail=1; continue; }
    if ! g++ -o "$work/t" "${o_list[@]}" "${test_objs[@]}" "${test_libs[@]}" -pthread 2>"$work/ld.log"; then
      echo "FAIL $id: the stub copy does not link:"; head -n 20 "$work/ld.log"; fail=1; continue
    fi
    set +e; res="$(run_tests "$id" "$work/t")"; rc=$?; set -e
    if [ $rc -eq 0 ]; then echo "FAIL $id: its tests pass on the stub"; fail=1
    elif ! grep -q "exercise $id: not implemented yet" <<<"$res"; then
      echo "FAIL $id: the failure of the stub does not say so:"; echo "$res"; fail=1
    else echo "ok   $id: the stub compiles and its check fails"; fi
    # The judge of grade, where the exercise has one, must not print the library's output on the stub.
    if grep -qxF -- "$id" <<<"$judged"; then
      if ! g++ -o "$work/j" "${o_list[@]}" "$work/judge.o" "$build/libdt.a" -lmpfr -lgmp -pthread 2>"$work/ld.log"; then
        echo "FAIL $id: the judge does not link with the stub copy:"; head -n 20 "$work/ld.log"; fail=1; continue
      fi
      "$work/judge_ref" "$id" 1 >"$work/ref_$id" || { echo "FAIL $id: the judge fails on the library"; fail=1; continue; }
      same=0; "$work/j" "$id" 1 >"$work/got_$id" 2>/dev/null && cmp -s "$work/ref_$id" "$work/got_$id" && same=1
      if [ $same = 1 ]; then echo "FAIL $id: the judge prints the solution's output on the stub"; fail=1
      else echo "ok   $id: the judge tells the stub from the solution"; fi
    fi
    # The restored solution is the library's own source, from which BUILD's dt_tests was linked
    # (and the judge's reference above): its tests run there, in the default variant and in
    # another, since a released workspace's variant draws other random inputs.
    set +e; res="$(run_tests "$id" "$build/dt_tests")"; rc=$?; set -e
    if [ $rc -ne 0 ]; then echo "FAIL $id: its tests fail on the restored solution:"; echo "$res"; fail=1
    else echo "ok   $id: the restored solution passes"; fi
    set +e; res="$(DT_VARIANT=$SELFTEST_VARIANT run_tests "$id" "$build/dt_tests")"; rc=$?; set -e
    if [ $rc -ne 0 ]; then echo "FAIL $id: its tests fail on the restored solution in variant $SELFTEST_VARIANT:"; echo "$res"; fail=1
    else echo "ok   $id: the restored solution passes in variant $SELFTEST_VARIANT"; fi
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
        signature "$fn" >/dev/null || { echo "$id: no declaration of $fn in a header of code/"; fail=1; }
      done
    fi
    grep -q "BEGIN SOLUTION $id " "$HERE/book/solutions.md" || { echo "$id: no entry in book/solutions.md"; fail=1; }
    grep -qF "\\ref $(anchor "$id") " "$HERE/book/$page.md" || { echo "$id: book/$page.md does not link its solution"; fail=1; }
  done
  [ $fail = 0 ] && echo "lint: $(ids | wc -l) exercises consistent"
  return $fail
}

[ $# -ge 1 ] || die "usage: exercise.sh COMMAND, one of: list, release ID... DIR, grade [OPTIONS] ID STUDENT_DIR..., export FORMAT ID TSV [ROSTER], similar [--threshold T] ID STUDENT_DIR..., summary ID TSV OUTDIR, handout SECTION [OUTDIR], check [ID...] [DIR], hint [ID] [DIR], watch [ID...] [DIR], selftest BUILD [ID...], lint BUILD"
[ -f "$DB" ] || die "no $DB"
cmd="$1"; shift
case "$cmd" in
  list) cmd_list ;;
  release) cmd_release "$@" ;;
  # start ID DIR: the former self-study command; now a release of one exercise.
  start) [ $# -eq 2 ] || die "usage: start ID DIR"; cmd_release "$@" ;;
  grade) cmd_grade "$@" ;;
  export) cmd_export "$@" ;;
  similar) cmd_similar "$@" ;;
  summary) cmd_summary "$@" ;;
  check) cmd_check "$@" ;;
  hint) cmd_hint "$@" ;;
  "watch") cmd_watch "$@" ;;
  handout) cmd_handout "$@" ;;
  selftest) cmd_selftest "$@" ;;
  lint) cmd_lint "$@" ;;
  *) die "unknown command '$cmd'" ;;
esac
