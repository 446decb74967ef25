#!/usr/bin/env bash
# The main job: installs what is missing, builds everything (Release), runs every chapter
# program (regenerating all figures and tables into build/output/ch2) and builds the book.
# Options are passed to every chapter program, e.g. "--quick" for a smaller run.
# It ends with a summary a teacher can use (each program's wall time, the figures and tables
# it wrote, where the book is), also written to build/output/ch2/run_summary.md, and as
# run.<program>.seconds / .figures / .tables values (values_run.txt) that the book cites.
set -euo pipefail
cd "$(dirname "$0")/.."
now() { date +%s%N; }
seconds_since() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.1f", (b - a) / 1e9 }'; }
t_start=$(now)
DT_WITH_OPTIONAL=1 bash scripts/deps.sh  # optional: CGAL for bench_kernels
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build build -j"$(nproc)"
t_built=$(now)

out=build/output/ch2
args=("$@")
for ((i = 0; i < ${#args[@]}; ++i)); do
  [ "${args[i]}" = --out ] && [ $((i + 1)) -lt ${#args[@]} ] && out=${args[i + 1]}
done
mkdir -p "$out"
stamp=$(mktemp)
trap 'rm -f "$stamp"' EXIT
rows=()
values=()
for src in chapters/ch2/*.cpp; do
  [ -e "$src" ] || continue
  name=$(basename "$src" .cpp)
  prog=build/$name
  echo "=== $prog $*"
  touch "$stamp"
  t0=$(now)
  "$prog" "$@"
  secs=$(seconds_since "$t0")
  figures=$(find "$out" -maxdepth 1 -type f -newer "$stamp" \( -name '*.png' -o -name '*.svg' -o -name '*.gif' \) | wc -l)
  tables=$(find "$out" -maxdepth 1 -type f -newer "$stamp" -name 'table*.md' | wc -l)
  rows+=("| \`$name\` | $secs | $figures | $tables |")
  values+=("run.$name.seconds $secs" "run.$name.figures $figures" "run.$name.tables $tables")
done
programs_secs=$(seconds_since "$t_built")
{
  echo "| program | wall time (s) | figures | tables |"
  echo "|---|---:|---:|---:|"
  printf '%s\n' "${rows[@]}"
  echo
  echo "Chapter programs: $programs_secs s in all (options: ${*:-none}); build and setup before them: $(awk -v a="$t_start" -v b="$t_built" 'BEGIN { printf "%.1f", (b - a) / 1e9 }') s; $(nproc) cores."
} > "$out/run_summary.md"
# What the tables cover, for the book's first page: a smaller run says so.
scope="full run, at the sizes of the notes' tables"
bt='`'  # a code span in the page: Doxygen would set "--" as a dash
for a in "$@"; do
  case $a in
    --quick) scope="quick run (${bt}--quick${bt}), whose tables stop at smaller sizes than the notes' tables" ;;
    --max-n | --max-n=*) scope="run limited by ${bt}--max-n${bt}, whose tables stop at that size" ;;
  esac
done
printf '%s\n' "${values[@]}" "run.programs_seconds $programs_secs" "run.options ${*:-none}" "run.scope $scope" \
  "run.cores $(nproc)" > "$out/values_run.txt"

book="(not built: Doxygen or MathJax missing)"
if [ -f book/CMakeLists.txt ]; then
  t0=$(now)
  cmake --build build --target book
  book_secs=$(seconds_since "$t0")
  book="build/book/student/index.html (students), build/book/teacher/index.html (teachers) ($book_secs s)"
fi
echo
echo "=== summary ($out/run_summary.md)"
cat "$out/run_summary.md"
echo "Book: $book"
echo "Total: $(seconds_since "$t_start") s"
