#!/usr/bin/env bash
# Mutation testing: does the test suite notice a bug? Applies each hand-written mutant of
# tests/mutants.txt, one at a time, to a temporary copy of the repository, rebuilds the tests,
# runs them, and reports each mutant as KILLED (a test failed, crashed or timed out), SURVIVED
# (every test passed: the suite misses that bug) or INVALID (the mutant does not apply or does
# not compile: fix the list). Exit status 0 iff every mutant is killed.
#
#   scripts/mutants.sh                 every mutant of tests/mutants.txt
#   scripts/mutants.sh NAME...         only these mutants
#   MUTANTS_JOBS=4 MUTANTS_TIMEOUT=600 scripts/mutants.sh
#
# The copy lives in a mktemp directory and is removed at the end; the repository is never
# modified. Each mutant costs one incremental build and one run of the suite (build/dt_tests,
# stopping at the first failure, without test_progress.cpp, whose 30 s of terminal sessions
# test only the progress display): about a minute per mutant on two cores, 45 minutes for the
# whole list, so this is not part of scripts/test.sh. MUTANTS_TEST_ARGS replaces the doctest
# options. To reuse compiled objects between runs, export CMAKE_CXX_COMPILER_LAUNCHER (e.g. a
# compiler cache) yourself.
set -euo pipefail

repo=$(cd "$(dirname "$0")/.." && pwd)
jobs=${MUTANTS_JOBS:-2}
timeout_s=${MUTANTS_TIMEOUT:-300}
test_args=${MUTANTS_TEST_ARGS:---source-file-exclude=*test_progress*}

work=$(mktemp -d "${TMPDIR:-/tmp}/dt_mutants.XXXXXX")
trap 'rm -rf "$work"' EXIT
src="$work/src"
build="$work/build"
mkdir -p "$src"
# The repository as it is now (uncommitted edits included), without .git and build directories.
(cd "$repo" && find . \( -path ./.git -o -path './build*' \) -prune -o -type f -print0 |
  xargs -0 cp --parents -t "$src")
list="$src/tests/mutants.txt"  # the copy's: editing the repository's list cannot disturb a run

# MUTANTS_CHECK_ONLY=1: only check that every mutant applies (its text occurs exactly once).
check_only=${MUTANTS_CHECK_ONLY:-0}
if [ "$check_only" != 1 ]; then
echo "mutants: copy in $work; configuring and building the unmutated suite"
cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release >"$work/configure.log" 2>&1 ||
  { cat "$work/configure.log"; exit 2; }
build_tests() { cmake --build "$build" -j"$jobs" --target dt_tests delaunay2d >"$work/build.log" 2>&1; }
run_tests() {
  # One process, stopping at the first failing test case: a killed mutant costs seconds. A
  # crash or a hang (timeout) fails the run too.
  # shellcheck disable=SC2086  # test_args is a list of options
  (set -f; cd "$build" && timeout "$timeout_s" ./dt_tests --abort-after=1 --no-intro $test_args) \
    >"$work/test.log" 2>&1
}
build_tests || { echo "mutants: the unmutated code does not build"; tail -30 "$work/build.log"; exit 2; }
run_tests || { echo "mutants: the unmutated suite fails; fix it first"; tail -30 "$work/test.log"; exit 2; }
fi

unescape() { local s=$1; printf '%s' "${s//\\n/$'\n'}"; }
trim() { local s=$1; s=${s#"${s%%[![:space:]]*}"}; printf '%s' "${s%"${s##*[![:space:]]}"}"; }

killed=0 survived=0 invalid=0
declare -a survivors=() invalids=()
while IFS= read -r line || [ -n "$line" ]; do
  [[ -z "$line" || "$line" == \#* ]] && continue
  IFS=$'\x1f' read -r name file orig repl desc <<<"${line// @@ /$'\x1f'}"
  name=$(trim "$name") file=$(trim "$file")
  if [ $# -gt 0 ]; then
    wanted=0
    for w in "$@"; do [ "$w" = "$name" ] && wanted=1; done
    [ $wanted = 1 ] || continue
  fi
  orig=$(unescape "$orig") repl=$(unescape "$repl")
  target="$src/$file"
  if [ ! -f "$target" ] || [ -z "$orig" ]; then
    echo "INVALID   $name: no file $file or empty original"; invalid=$((invalid + 1)); invalids+=("$name"); continue
  fi
  content=$(cat "$target"; printf x)  # the x keeps trailing newlines
  content=${content%x}
  rest=${content//"$orig"/}
  count=$(( (${#content} - ${#rest}) / ${#orig} ))
  if [ "$count" -ne 1 ]; then
    echo "INVALID   $name: the original text occurs $count times in $file"
    invalid=$((invalid + 1)); invalids+=("$name"); continue
  fi
  if [ "$check_only" = 1 ]; then
    echo "APPLIES   $name"; continue
  fi
  cp "$target" "$work/saved"
  printf '%s' "${content/"$orig"/"$repl"}" >"$target"
  start=$(date +%s)
  if ! build_tests; then
    status="INVALID  "; invalid=$((invalid + 1)); invalids+=("$name")
    detail="does not compile: $(grep -m1 'error' "$work/build.log" || true)"
  elif run_tests; then
    status="SURVIVED "; survived=$((survived + 1)); survivors+=("$name")
    detail="every test passed"
  else
    status="KILLED   "; killed=$((killed + 1))
    # The test case whose block holds the first error (blocks of passing tests with a MESSAGE
    # also start with "TEST CASE:").
    failed=$(awk '/^TEST CASE:/ { tc = $0; sub(/^TEST CASE: */, "", tc) }
                  /ERROR|CRASHED/ { if (tc != "") { print tc; exit } }' "$work/test.log" || true)
    [ -n "$failed" ] || failed="no test case named: crash or timeout ($(tail -1 "$work/test.log"))"
    detail="first failing: $failed"
  fi
  # Restore the file; a plain cp gives it a new time, so the next build recompiles it.
  cp "$work/saved" "$target"
  echo "$status $name ($file, $(( $(date +%s) - start )) s): $desc; $detail"
done <"$list"

total=$((killed + survived + invalid))
echo
echo "mutants: $total run, $killed killed, $survived survived, $invalid invalid"
[ $survived -eq 0 ] || echo "survived: ${survivors[*]}"
[ $invalid -eq 0 ] || echo "invalid: ${invalids[*]}"
[ $survived -eq 0 ] && [ $invalid -eq 0 ]
