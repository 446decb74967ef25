#!/usr/bin/env bash
# The main job: installs what is missing, builds everything (Release), runs every chapter
# program (regenerating all figures and tables into build/output) and builds the book.
# Options are passed to every chapter program, e.g. "--quick" for a smaller run.
set -euo pipefail
cd "$(dirname "$0")/.."
DT_WITH_OPTIONAL=1 bash scripts/deps.sh  # optional: CGAL for bench_kernels
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build build -j"$(nproc)"
for src in chapters/ch2/*.cpp; do
  [ -e "$src" ] || continue
  prog=build/$(basename "$src" .cpp)
  echo "=== $prog $*"
  "$prog" "$@"
done
if [ -f book/CMakeLists.txt ]; then
  cmake --build build --target book
  # The live figures (web/): copied into the book's html/live when emscripten built them.
  if [ -f build/web/dt_wasm.js ]; then
    cmake --build build --target web_book > /dev/null
    echo "live figures: build/book/html/live"
  fi
  echo "book: build/book/html/index.html"
fi
