#!/usr/bin/env bash
# Mutation testing: does the test suite notice a bug? Applies each hand-written mutant of
# tests/mutants.txt, one at a time, to a temporary copy of the repository, rebuilds everything
# the suite runs (the target dt_suite: the tests, the triangulator that test_cli runs and the
# chapter programs that test_figures runs; not the WebAssembly build, which no test case of the
# suite runs), runs the suite, and reports each mutant as KILLED (a test failed, crashed or
# timed out), SURVIVED (every test passed: the suite misses that bug) or INVALID (the mutant
# does not apply exactly once, changes nothing, or does not compile: fix the list). Exit status
# 0 iff every mutant is killed; 2 if the unmutated tree does not build or its suite fails.
#
#   scripts/mutants.sh                 every mutant of tests/mutants.txt
#   scripts/mutants.sh NAME...         only these mutants (an unknown name is an error)
#   scripts/mutants.sh --list FILE     the mutants of another list (same format)
#   scripts/mutants.sh --check         no build: only check that every mutant of the list
#                                      applies exactly once and changes its file (a ctest entry)
#   scripts/mutants.sh --self-test     the tool on a planted list (tests/mutants_selftest.txt):
#                                      a real bug must be KILLED, a comment-only change
#                                      SURVIVED, a stale mutant INVALID (a ctest entry)
#   MUTANTS_JOBS=4 MUTANTS_TIMEOUT=600 MUTANTS_TEST_ARGS='...' MUTANTS_TARGETS='...' \
#     MUTANTS_CMAKE_ARGS='...' MUTANTS_WORK=DIR scripts/mutants.sh
#
# The copy lives in a mktemp directory, removed at the end, or in MUTANTS_WORK, kept so that
# the next run rebuilds only what changed (the copy keeps the repository's file times); the
# repository is never modified. Each mutant costs one incremental build and one run of the
# suite (build/dt_tests, stopping at the first failure, without test_progress.cpp, whose 30 s
# of terminal sessions test only the progress display; the files that run whole programs come
# last, so a mutant an ordinary case kills costs seconds), so the whole list is not part of
# scripts/test.sh. The first pass runs only the test files that can reach the mutant's file (a
# C++ file reached through the chain of #include "..." lines, each header leading to the code/
# files that implement it, i.e. include it first; a test file that starts programs reaches
# everything). Each pass of a mutant has a timeout of MUTANTS_TIMEOUT_FACTOR (default 3) times
# that pass's time on the unmutated tree, at least MUTANTS_TIMEOUT_MIN s (default 60); a mutant
# stopped by it is reported KILLED with the words "timed out". MUTANTS_TIMEOUT (default 3600 s)
# only bounds the unmutated run, whose timeout is named as such. MUTANTS_TEST_ARGS replaces the
# doctest options, MUTANTS_TARGETS the build targets (default: dt_suite), MUTANTS_CMAKE_ARGS adds
# configure options (e.g. -DDT_TEST_FILES=test_spine.cpp: a suite of one file). To reuse compiled objects
# between runs, export CMAKE_CXX_COMPILER_LAUNCHER (e.g. a compiler cache) yourself.
#
# A mutant of a file under web/ (the live figures) is judged by the browser test instead: the
# copy builds the WebAssembly module and the test page (target web_live) and runs
# web/run_browser_test.sh at 1280 and 390 px; the WebAssembly is built only when the selected
# mutants include such a one (GMP for it is copied from the repository's build/ when there).
set -euo pipefail

repo=$(cd "$(dirname "$0")/.." && pwd)
jobs=${MUTANTS_JOBS:-2}
timeout_s=${MUTANTS_TIMEOUT:-3600}
timeout_factor=${MUTANTS_TIMEOUT_FACTOR:-3}
timeout_min=${MUTANTS_TIMEOUT_MIN:-60}
test_args=${MUTANTS_TEST_ARGS:---source-file-exclude=*test_progress*}
slow_files='*test_exercises*,*test_figures*,*test_cli*,*test_bad_input*,*test_chapter_options*'
targets=${MUTANTS_TARGETS:-dt_suite}

list_arg="$repo/tests/mutants.txt"
mode=run
names=()
while [ $# -gt 0 ]; do
  case $1 in
    --list)
      [ $# -ge 2 ] || { echo "mutants: --list needs a file" >&2; exit 2; }
      list_arg=$2; shift 2 ;;
    --check) mode=check; shift ;;
    --self-test) mode=selftest; shift ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d'; exit 0 ;;
    -*) echo "mutants: unknown option $1" >&2; exit 2 ;;
    *) names+=("$1"); shift ;;
  esac
done
[ -f "$list_arg" ] || { echo "mutants: no list $list_arg" >&2; exit 2; }
list_arg=$(cd "$(dirname "$list_arg")" && pwd)/$(basename "$list_arg")

# ---- --self-test: the tool must tell a real bug, a change of nothing and a stale mutant ----
if [ $mode = selftest ]; then
  planted="$repo/tests/mutants_selftest.txt"
  log=$(mktemp)
  trap 'rm -f "$log"' EXIT
  # 1. --check refuses a list with a mutant whose text is not in the tree (and names it).
  if bash "$0" --check --list "$planted" >"$log" 2>&1; then
    echo "mutants self-test: --check accepted a stale mutant"; cat "$log"; exit 1
  fi
  grep -q '^INVALID   selftest-stale: the original text occurs 0 times' "$log" ||
    { echo "mutants self-test: --check did not name the stale mutant"; cat "$log"; exit 1; }
  # 2. An unknown mutant name is an error, not an empty run.
  if bash "$0" --check --list "$planted" no-such-mutant >"$log" 2>&1; then
    echo "mutants self-test: an unknown mutant name was accepted"; cat "$log"; exit 1
  fi
  # 3. The real run: a real bug KILLED, a comment-only change SURVIVED, the stale one INVALID,
  # an endless loop KILLED as a timeout (a small multiple of the unmutated pass's time, not
  # MUTANTS_TIMEOUT), a bug in a file no test of the suite reaches SURVIVED without running a
  # test, and the exit status says the list is not clean. To stay cheap, the copy's suite is the
  # one file that kills the real bug (tests/test_2_3_6_flips.cpp), built without the others.
  status=0
  MUTANTS_CMAKE_ARGS=${MUTANTS_CMAKE_ARGS:--DDT_TEST_FILES=test_2_3_6_flips.cpp} \
    MUTANTS_TARGETS=${MUTANTS_TARGETS:-dt_tests} MUTANTS_TIMEOUT_MIN=${MUTANTS_TIMEOUT_MIN:-10} \
    bash "$0" --list "$planted" >"$log" 2>&1 || status=$?
  cat "$log"
  ok=1
  grep -q '^KILLED    selftest-real ' "$log" || { echo "mutants self-test: the real bug was not KILLED"; ok=0; }
  grep -q '^SURVIVED  selftest-comment ' "$log" ||
    { echo "mutants self-test: a comment-only change was not reported SURVIVED"; ok=0; }
  grep -Eq '^KILLED    selftest-hang .*timed out after [0-9]+ s \(' "$log" ||
    { echo "mutants self-test: the endless loop was not KILLED as a timeout"; ok=0; }
  grep -q '^SURVIVED  selftest-unreached .*no test file of the suite reaches code/io/writers.cpp' "$log" ||
    { echo "mutants self-test: a file no test reaches was not skipped"; ok=0; }
  grep -q '^INVALID   selftest-stale' "$log" || { echo "mutants self-test: the stale mutant was not INVALID"; ok=0; }
  [ "$status" = 1 ] || { echo "mutants self-test: exit status $status, not 1"; ok=0; }
  # 4. Test options that select no test case are refused (exit 2), not run into SURVIVED.
  status=0
  MUTANTS_CMAKE_ARGS=${MUTANTS_CMAKE_ARGS:--DDT_TEST_FILES=test_2_3_6_flips.cpp} \
    MUTANTS_TARGETS=${MUTANTS_TARGETS:-dt_tests} MUTANTS_TEST_ARGS='-tc=no?such?test?case' \
    bash "$0" --list "$planted" selftest-real >"$log" 2>&1 || status=$?
  if [ "$status" != 2 ] || ! grep -q 'select no test case' "$log"; then
    cat "$log"; echo "mutants self-test: a selection of no test case was not refused (exit $status)"; ok=0
  fi
  [ $ok = 1 ] && echo "mutants self-test: passed"
  [ $ok = 1 ]
  exit
fi

unescape() { local s=$1; printf '%s' "${s//\\n/$'\n'}"; }
trim() { local s=$1; s=${s#"${s%%[![:space:]]*}"}; printf '%s' "${s%"${s##*[![:space:]]}"}"; }

# The mutants of the list (filtered by name): names, files, originals, replacements, texts.
declare -a M_name=() M_file=() M_orig=() M_repl=() M_desc=()
declare -A seen_name=()
lineno=0
while IFS= read -r line || [ -n "$line" ]; do
  lineno=$((lineno + 1))
  [[ -z "$line" || "$line" == \#* ]] && continue
  IFS=$'\x1f' read -r name file orig repl desc <<<"${line// @@ /$'\x1f'}"
  name=$(trim "$name") file=$(trim "$file")
  if [ -z "$name" ] || [ -z "$file" ] || [ -z "$desc" ]; then
    echo "mutants: $list_arg:$lineno: not 'name @@ file @@ original @@ replacement @@ what'" >&2
    exit 2
  fi
  [ -z "${seen_name[$name]:-}" ] || { echo "mutants: $list_arg:$lineno: mutant $name listed twice" >&2; exit 2; }
  seen_name[$name]=1
  if [ ${#names[@]} -gt 0 ]; then
    wanted=0
    for w in "${names[@]}"; do [ "$w" = "$name" ] && wanted=1; done
    [ $wanted = 1 ] || continue
  fi
  M_name+=("$name") M_file+=("$file") M_orig+=("$(unescape "$orig")") M_repl+=("$(unescape "$repl")")
  M_desc+=("$desc")
done <"$list_arg"
for w in "${names[@]}"; do
  [ -n "${seen_name[$w]:-}" ] || { echo "mutants: no mutant named $w in $list_arg" >&2; exit 2; }
done
[ ${#M_name[@]} -gt 0 ] || { echo "mutants: no mutant in $list_arg" >&2; exit 2; }

# Applies mutant i to the tree under $1: prints why not and fails unless its original text
# occurs exactly once and the replacement changes the file.
apply() {
  local root=$1 i=$2 target content rest count
  target="$root/${M_file[$i]}"
  if [ ! -f "$target" ] || [ -z "${M_orig[$i]}" ]; then
    echo "no file ${M_file[$i]} or empty original"; return 1
  fi
  content=$(cat "$target"; printf x)  # the x keeps trailing newlines
  content=${content%x}
  rest=${content//"${M_orig[$i]}"/}
  count=$(( (${#content} - ${#rest}) / ${#M_orig[$i]} ))
  if [ "$count" -ne 1 ]; then
    echo "the original text occurs $count times in ${M_file[$i]}"; return 1
  fi
  if [ "${M_orig[$i]}" = "${M_repl[$i]}" ]; then
    echo "the replacement is the original text"; return 1
  fi
  [ "$root" = "$repo" ] && return 0  # --check: never write into the repository
  printf '%s' "${content/"${M_orig[$i]}"/"${M_repl[$i]}"}" >"$target"
}

if [ $mode = check ]; then
  bad=0
  for i in "${!M_name[@]}"; do
    if why=$(apply "$repo" "$i"); then
      echo "APPLIES   ${M_name[$i]}"
    else
      echo "INVALID   ${M_name[$i]}: $why"; bad=$((bad + 1))
    fi
  done
  echo "mutants --check: ${#M_name[@]} mutants, $bad do not apply"
  [ $bad -eq 0 ]
  exit
fi

if [ -n "${MUTANTS_WORK:-}" ]; then
  work=$MUTANTS_WORK
  mkdir -p "$work"
else
  work=$(mktemp -d "${TMPDIR:-/tmp}/dt_mutants.XXXXXX")
  # Readable by others, like a checkout: a CLI test runs the copy's delaunay2d as user nobody
  # (a file that user could not write must not be replaced), and mktemp's 0700 would stop it.
  chmod 755 "$work"
  trap 'rm -rf "$work"' EXIT
fi
src="$work/src"
# The build sits in the copy where a checkout has its own (build/): the compile commands are
# then a checkout's, and ccache (see CMakeLists.txt) serves every file the mutant did not touch.
build="$src/build"
mkdir -p "$src"
find "$src" -mindepth 1 -maxdepth 1 ! -name build -exec rm -rf {} +
# The repository as it is now (uncommitted edits included), without .git and build
# directories, with its file times: a kept build recompiles only what changed since.
(cd "$repo" && find . \( -path ./.git -o -path './build*' \) -prune -o -type f -print0 |
  xargs -0 cp -p --parents -t "$src")
# A run interrupted while a mutant was applied left objects compiled from it, newer than the
# restored file: make that file new so that it is compiled again. So did the last mutant of
# each file in a finished run (the fresh copy gives the file its older time back): those are
# listed in $work/restored.
if [ -f "$work/mutated" ]; then
  touch "$src/$(cat "$work/mutated")"
  rm -f "$work/mutated"
fi
if [ -f "$work/restored" ]; then
  while IFS= read -r f; do [ ! -f "$src/$f" ] || touch "$src/$f"; done <"$work/restored"
  rm -f "$work/restored"
fi

echo "mutants: copy in $work; configuring and building the unmutated tree"
# shellcheck disable=SC2086  # MUTANTS_CMAKE_ARGS is a list of options
cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release ${MUTANTS_CMAKE_ARGS:-} >"$work/configure.log" 2>&1 ||
  { cat "$work/configure.log"; exit 2; }
# ---- which test files can reach a file --------------------------------------------------------
# Edges of the include graph, read once: a file leads to the repository files it includes with
# "..." (looked up beside it, then in tests/, code/ and each room of code/), and a header to the code/, chapters/
# and book/ files that implement it (include it first). reached_by[F] lists the files with an edge to F.
declare -A reached_by=()
starts_programs=""  # test files that run programs: they reach every file
code_dirs=(code)
for d in "$src"/code/*/; do code_dirs+=("code/$(basename "$d")"); done
for f in "$src"/code/*.h "$src"/code/*.cpp "$src"/code/*/*.h "$src"/code/*/*.cpp "$src"/tests/*.h "$src"/tests/*.cpp "$src"/tests/fuzz/*.h \
         "$src"/book/*.h "$src"/book/*.cpp "$src"/chapters/*.h "$src"/chapters/*.cpp; do
  [ -f "$f" ] || continue
  rel=${f#"$src"/}
  dir=$(dirname "$rel")
  first=1
  while IFS= read -r inc; do
    for cand in "$dir/$inc" "tests/$inc" "${code_dirs[@]/%//$inc}"; do
      if [ -f "$src/$cand" ]; then
        cand=$(realpath -m --relative-to="$src" "$src/$cand")
        reached_by[$cand]+=" $rel"
        # An implementation includes its header first: the header leads to it.
        [ $first = 1 ] && [[ $rel == code/*.cpp || $rel == chapters/*.cpp || $rel == book/*.cpp ]] && reached_by[$rel]+=" $cand"
        break
      fi
    done
    first=0
  done < <(sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"\([^"]*\)".*/\1/p' "$f")
  [[ $rel == tests/*.cpp ]] && grep -Eq 'DT_CLI|runCli|std::system|popen|DT_BINARY_DIR|process\.h' "$f" &&
    starts_programs+=",*$(basename "$rel")"
done
# The first pass's --source-file value for a mutant of file $1: the test files that reach it
# ("*" for a file that is not C++ or that the graph does not know, and for the unmutated run);
# empty if none does.
fast_files() {
  local target=$1 f n list=""
  case $target in
    *.h | *.cpp) ;;
    *) echo "*"; return ;;
  esac
  local -A seen=([$target]=1)
  local -a todo=("$target")
  while [ ${#todo[@]} -gt 0 ]; do
    f=${todo[0]}; todo=("${todo[@]:1}")
    [[ $f == tests/*.cpp ]] && list+=",*$(basename "$f")"
    for n in ${reached_by[$f]:-}; do
      [ -n "${seen[$n]:-}" ] || { seen[$n]=1; todo+=("$n"); }
    done
  done
  list+=$starts_programs
  # Only the files the suite was built from (DT_TEST_FILES), when it names them.
  if [ -n "$suite_files" ]; then
    local kept="" item
    for item in ${list//,/ }; do
      [[ " $suite_files " == *" ${item#\*} "* ]] && [[ ,$kept, != *,$item,* ]] && kept+=",$item"
    done
    list=$kept
  fi
  echo "${list#,}"
}

build_tests() {
  # shellcheck disable=SC2086  # targets is a list
  cmake --build "$build" -j"$jobs" --target $targets >"$work/build.log" 2>&1
}
# run_pass N LIMIT ARGS...: one run of dt_tests (stopping at the first failing test case: a
# killed mutant costs seconds) under a timeout of LIMIT s, appended to the log; its time goes to
# pass_time[N]. Returns 124 on a timeout, dt_tests' status otherwise.
declare -a pass_time=(0 0)
timed_out=""
run_pass() {
  local n=$1 limit=$2 t0 status=0
  shift 2
  t0=$(date +%s%N)
  # shellcheck disable=SC2086  # the options are a list
  (set -f; cd "$build" && timeout "$limit" ./dt_tests --abort-after=1 --no-intro "$@") \
    >>"$work/test.log" 2>&1 || status=$?
  pass_time[n]=$(( ($(date +%s%N) - t0 + 999999999) / 1000000000 ))
  [ $status = 124 ] && timed_out="pass $((n + 1)) timed out after $limit s"
  return $status
}
# The timeout of pass N of a mutant: a multiple of the unmutated pass's time.
limit_of() {
  local l=$(( timeout_factor * base_time[$1] ))
  [ $l -ge "$timeout_min" ] || l=$timeout_min
  echo "$l"
}
# run_tests LIMIT0 LIMIT1 [TARGET]: the suite on the build, a crash or a timeout failing it too.
# Without MUTANTS_TEST_ARGS, in two passes: the files whose cases build and run whole programs
# (the exercise machinery, the chapter programs, the triangulator's command lines: minutes) come
# last, after the rest has passed; the first pass runs only the files that reach TARGET.
run_tests() {
  local files
  : >"$work/test.log"
  timed_out=""
  if [ -n "${MUTANTS_TEST_ARGS+set}" ]; then
    # shellcheck disable=SC2086  # test_args is a list of options
    run_pass 0 "$1" $test_args
    return
  fi
  files=$(fast_files "${3:-}")
  if [ -n "$files" ]; then
    run_pass 0 "$1" "--source-file=$files" "--source-file-exclude=*test_progress*,$slow_files" || return
  fi
  run_pass 1 "$2" "--source-file=$slow_files"
}
# The live figures' mutants: the WebAssembly module and the browser test page, and the test
# at a laptop's and a phone's width (the verdict lines of the first failing run in the log).
is_web() { case $1 in web/*) return 0 ;; *) return 1 ;; esac; }
build_web() {
  local gmp=web/work/deps/prefix
  if [ ! -f "$build/$gmp/lib/libgmp.a" ] && [ -f "$repo/build/$gmp/lib/libgmp.a" ]; then
    mkdir -p "$build/$gmp"
    cp -pr "$repo/build/$gmp/." "$build/$gmp/"
  fi
  cmake --build "$build" -j"$jobs" --target web_live >"$work/build.log" 2>&1
}
run_web() {
  timeout "$timeout_s" bash "$src/web/run_browser_test.sh" "$build/web/test.html" >"$work/test.log" 2>&1 &&
    timeout "$timeout_s" bash "$src/web/run_browser_test.sh" "$build/web/test_390.html" --reduced-motion >>"$work/test.log" 2>&1
}
# A mutant of the suite's sources: both passes under timeouts derived from the unmutated run.
# shellcheck disable=SC2317  # called through $do_run
run_suite_mutant() { run_tests "$(limit_of 0)" "$(limit_of 1)" "$file"; }
need_suite=0 need_web=0
for f in "${M_file[@]}"; do
  if is_web "$f"; then need_web=1; else need_suite=1; fi
done
if [ $need_suite = 1 ]; then
  echo "mutants: the suite ($targets)"
  build_tests || { echo "mutants: the unmutated code does not build"; tail -30 "$work/build.log"; exit 2; }
  # The test files the suite is built from, if the configuration names them (DT_TEST_FILES).
  suite_files=$(sed -n 's/^DT_TEST_FILES:[A-Z]*=//p' "$build/CMakeCache.txt" | tr ';,' '  ')
  if ! run_tests "$timeout_s" "$timeout_s"; then
    if [ -n "$timed_out" ]; then
      echo "mutants: the unmutated suite timed out ($timed_out; MUTANTS_TIMEOUT=$timeout_s): raise MUTANTS_TIMEOUT on a busy machine"
    else
      echo "mutants: the unmutated suite fails; fix it first"
    fi
    tail -30 "$work/test.log"; exit 2
  fi
  declare -a base_time=("${pass_time[0]}" "${pass_time[1]}")
  echo "mutants: the unmutated suite took ${base_time[0]} s and ${base_time[1]} s (its two passes): a mutant's passes time out after $(limit_of 0) s and $(limit_of 1) s"
  # A selection that runs no test case passes whatever the code does: every mutant would be
  # reported SURVIVED (doctest splits -tc on commas only, so '-tc=a b' selects "a", and "b" is
  # ignored). Refused, as is a suite that fails.
  grep -Eq 'test cases: *[1-9]' "$work/test.log" ||
    { echo "mutants: the test options (${test_args:-none}) select no test case; every mutant would survive"
      exit 2; }
fi
if [ $need_web = 1 ]; then
  echo "mutants: the live figures (web_live) and their browser test"
  build_web || { echo "mutants: the unmutated WebAssembly does not build"; tail -30 "$work/build.log"; exit 2; }
  run_web || { echo "mutants: the unmutated browser test fails; fix it first"; tail -30 "$work/test.log"; exit 2; }
fi

killed=0 survived=0 invalid=0
declare -a survivors=() invalids=()
run_start=$(date +%s)
for i in "${!M_name[@]}"; do
  name=${M_name[$i]} file=${M_file[$i]}
  target="$src/$file"
  cp -p "$target" "$work/saved" 2>/dev/null || true
  echo "$file" >"$work/mutated"
  start=$(date +%s)
  if ! why=$(apply "$src" "$i"); then
    rm -f "$work/mutated"
    echo "INVALID   $name: $why"; invalid=$((invalid + 1)); invalids+=("$name"); continue
  fi
  do_build=build_tests do_run=run_suite_mutant timed_out=""
  if is_web "$file"; then do_build=build_web do_run=run_web; fi
  if ! $do_build; then
    status="INVALID  "; invalid=$((invalid + 1)); invalids+=("$name")
    detail="does not compile: $(grep -m1 'error' "$work/build.log" || true)"
  elif $do_run; then
    status="SURVIVED "; survived=$((survived + 1)); survivors+=("$name")
    detail="every test passed"
    is_web "$file" || [ -n "${MUTANTS_TEST_ARGS+set}" ] || [ -n "$(fast_files "$file")" ] ||
      detail="$detail (no test file of the suite reaches $file; only the slow pass ran)"
  else
    status="KILLED   "; killed=$((killed + 1))
    # The test case whose block holds the first error (blocks of passing tests with a MESSAGE
    # also start with "TEST CASE:").
    failed=$(awk '/^TEST CASE:/ { tc = $0; sub(/^TEST CASE: */, "", tc) }
                  /ERROR|CRASHED/ { if (tc != "") { print tc; exit } }
                  /^FAIL / { print; exit }' "$work/test.log" || true)
    if [ -n "$timed_out" ]; then
      detail="$timed_out ($timeout_factor x the unmutated pass's time, at least $timeout_min s)${failed:+, in or after: $failed}"
    else
      [ -n "$failed" ] || failed="no test case named: a crash ($(tail -1 "$work/test.log"))"
      detail="first failing: $failed"
    fi
  fi
  # Restore the file; a plain cp gives it a new time, so the next build recompiles it.
  cp "$work/saved" "$target"
  echo "$file" >>"$work/restored"
  rm -f "$work/mutated"
  echo "$status $name ($file, $(( $(date +%s) - start )) s): ${M_desc[$i]}; $detail"
done

total=$((killed + survived + invalid))
echo
echo "mutants: $total run, $killed killed, $survived survived, $invalid invalid ($(( $(date +%s) - run_start )) s)"
[ $survived -eq 0 ] || echo "survived: ${survivors[*]}"
[ $invalid -eq 0 ] || echo "invalid: ${invalids[*]}"
[ $survived -eq 0 ] && [ $invalid -eq 0 ] && exit 0
exit 1
