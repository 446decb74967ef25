#!/usr/bin/env bash
# Builds the live figures' WebAssembly module with Debian's emscripten (called by web/CMakeLists.txt):
#
#   bash web/build_wasm.sh SOURCE_DIR WORK_DIR OUTPUT.js [--planted]
#
# 1. GMP for wasm, once per build directory (WORK_DIR/deps/prefix), from Debian's own source
#    package (scripts/deps.sh enables deb-src and fetches it with `apt-get source gmp` into
#    /var/cache/dt-wasm-src). Never emscripten's ports (they download).
# 2. The library code/*.cpp and code/*/*.cpp (but the command line's file code, see below), each object rebuilt only when its sources are newer.
# 3. web/dt_web.cpp linked into one JavaScript file with the wasm embedded (-sSINGLE_FILE=1),
#    so that the book works from file:// with no server. --planted compiles the binding with
#    DT_WEB_PLANTED_DEFECT (the browser test's self-check, ctest web_browser_planted).
set -euo pipefail
src=$(cd "$1" && pwd)
work=$2
out=$3
planted=${4:-}
mkdir -p "$work"
work=$(cd "$work" && pwd)
# emscripten's optimiser needs Debian's JavaScript modules (acorn) even under another node.
export NODE_PATH=/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}
jobs=$(nproc)
srcdir=${DT_WASM_SRC:-/var/cache/dt-wasm-src}
deps=$work/deps
prefix=$deps/prefix

# Unpacks the Debian source package $1 (version files from apt-get source) into $2/$1.
unpack() {
  local pkg=$1 dest=$2 dsc
  dsc=$(find "$srcdir" -maxdepth 1 -name "${pkg}_*.dsc" 2>/dev/null | sort | head -n 1)
  if [ -z "$dsc" ]; then
    echo "build_wasm.sh: no Debian source of $pkg in $srcdir (run scripts/deps.sh as root)" >&2
    exit 1
  fi
  rm -rf "${dest:?}/$pkg"
  dpkg-source --no-check -x "$dsc" "$dest/$pkg" > /dev/null
}

if [ ! -f "$prefix/lib/libgmp.a" ]; then
  echo "-- wasm: building GMP from Debian's source (once per build directory)"
  mkdir -p "$deps"
  # GMP's configure refuses a working directory whose name holds a space, a quote or a $
  # ("unsafe absolute working directory name"), and make cannot install into one: GMP is built
  # and installed in a fresh directory of mktemp (a safe name), and its library and headers are
  # then copied into $prefix, whatever the build directory is called.
  gmpwork=$(mktemp -d)
  trap 'rm -rf "$gmpwork"' EXIT
  unpack gmp "$gmpwork"
  (
    cd "$gmpwork/gmp"
    # Debian's source has no doc/ (removed for licence reasons): drop it from the build.
    sed -i 's| doc/Makefile||' configure  # the list of outputs (and a case arm, left inert)
    sed -i 's|^\(SUBDIRS = .*\) doc$|\1|' Makefile.in
    emconfigure ./configure --host=none --disable-assembly --enable-cxx --disable-shared \
      --enable-static --prefix="$gmpwork/prefix" > "$deps/gmp-configure.log" 2>&1
    emmake make -j"$jobs" > "$deps/gmp-make.log" 2>&1
    emmake make install > "$deps/gmp-install.log" 2>&1
  ) || { echo "build_wasm.sh: GMP build failed, see $deps/gmp-*.log" >&2; exit 1; }
  mkdir -p "$prefix/lib" "$prefix/include"
  cp "$gmpwork"/prefix/include/*.h "$prefix/include/"
  cp "$gmpwork/prefix/lib/libgmp.a" "$prefix/lib/libgmp.a.part"
  mv "$prefix/lib/libgmp.a.part" "$prefix/lib/libgmp.a"  # the marker of a finished build, last
  rm -rf "$gmpwork"
  trap - EXIT
fi
# MPFR is left out: only the notes' 200-bit scheme (dt::orient2dNotes, dt::*MPFR*) uses it, and
# no live figure calls those. predicates.cpp still compiles against Debian's mpfr.h (its
# types are GMP's); the mpfr_* symbols stay undefined and are checked to be the only ones.
if [ ! -f "$prefix/include/mpfr.h" ]; then
  cp /usr/include/mpfr.h "$prefix/include/mpfr.h"
fi

# The same options as the native build where they matter: C++17, no contraction (section
# 2.3.1's naive predicates must compute what the source spells), exceptions caught (the
# library reports bad input by throwing).
flags=(-O2 -std=c++17 -fexceptions -ffp-contract=off -I"$src/code" -I"$prefix/include")
# The library's includes are bare names, found in code/ and in each of its rooms.
for d in "$src"/code/*/; do flags+=(-I"${d%/}"); done
objdir=$work/obj
mkdir -p "$objdir"
objs=()
pids=()
for f in "$src"/code/*.cpp "$src"/code/*/*.cpp; do
  # The command line's files: io.cpp (parsing: its std::from_chars for doubles is missing from
  # emscripten 3.1.6's libc++), writers.cpp (std::to_chars likewise), output_files.cpp (locks,
  # signals, renames) and peak_memory.cpp (/proc). No live figure reads or writes a file.
  case "$(basename "$f")" in io.cpp|writers.cpp|output_files.cpp|peak_memory.cpp) continue ;; esac
  o=$objdir/$(basename "$f" .cpp).o
  objs+=("$o")
  # Rebuilt when the source or any header of code/ is newer than the object.
  if [ ! -f "$o" ] || [ "$f" -nt "$o" ] ||
     [ -n "$(find "$src/code" -name '*.h' -newer "$o" -print -quit)" ]; then
    em++ "${flags[@]}" -c "$f" -o "$o" &
    pids+=($!)
    if [ ${#pids[@]} -ge "$jobs" ]; then wait "${pids[0]}"; pids=("${pids[@]:1}"); fi
  fi
done
for p in "${pids[@]}"; do wait "$p"; done

defs=()
[ "$planted" = --planted ] && defs=(-DDT_WEB_PLANTED_DEFECT)
em++ "${flags[@]}" "${defs[@]}" -c "$src/web/dt_web.cpp" -o "$work/dt_web$planted.o"
em++ -O2 -fexceptions "$work/dt_web$planted.o" "${objs[@]}" "$prefix/lib/libgmp.a" \
  -o "$out.tmp.js" -sERROR_ON_UNDEFINED_SYMBOLS=0 \
  -sSINGLE_FILE=1 -sMODULARIZE=1 -sEXPORT_NAME=DTModule -sALLOW_MEMORY_GROWTH=1 \
  -sMAXIMUM_MEMORY=4GB -sENVIRONMENT=web,node \
  -sEXPORTED_FUNCTIONS=_malloc,_free \
  -sEXPORTED_RUNTIME_METHODS=UTF8ToString 2> "$work/link$planted.log" ||
  { cat "$work/link$planted.log" >&2; exit 1; }
# Undefined symbols become stubs that abort when called: only MPFR's are allowed.
if grep -i "undefined symbol" "$work/link$planted.log" | grep -v "undefined symbol: mpfr_" | grep -q .; then
  echo "build_wasm.sh: undefined symbols other than MPFR's:" >&2
  grep -i "undefined symbol" "$work/link$planted.log" | grep -v "mpfr_" >&2
  rm -f "$out.tmp.js"
  exit 1
fi
mv "$out.tmp.js" "$out"
echo "-- wasm: $out"
