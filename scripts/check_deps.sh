#!/usr/bin/env bash
# Checks that every external program the repository calls comes from a Debian package that
# scripts/deps.sh installs, so that a well-stocked machine cannot hide a missing install step.
#
#   bash scripts/check_deps.sh              the check (run by scripts/test.sh through ctest)
#   bash scripts/check_deps.sh --self-test  removes each package of the table below from a copy
#                                           of deps.sh in turn and requires the check to fail,
#                                           naming the command that package provides
#   DT_DEPS_FILE=FILE                       check against FILE instead of scripts/deps.sh
#
# Two checks:
#  1. Each command of the table is installed, and the file it resolves to belongs to the package
#     the table names (or to a package that package depends on), and that package is listed in
#     deps.sh; commands marked "base" must come from an Essential or Priority: required package
#     (present on every Debian system, even a minimal container, before deps.sh runs).
#  2. The sources are scanned for invoked commands (shell scripts, std::system/popen strings,
#     gnuplot system() calls, CMake find_program/COMMAND): each must be in the table, so a new
#     popen("foo ...") fails here until someone decides which package brings foo.
set -euo pipefail
cd "$(dirname "$0")/.."
deps_file=${DT_DEPS_FILE:-scripts/deps.sh}

# command   package (in deps.sh) or "base"   where it is called
TABLE='
g++          g++                cmake (the compiler of every target)
c++          g++                cmake (the compiler of every target)
cmake        cmake              scripts/main.sh scripts/test.sh scripts/fuzz.sh
ctest        cmake              scripts/test.sh
make         make               cmake (the generator)
ccache       ccache             CMakeLists.txt (compiles a file once for every copy of the tree)
gnuplot      gnuplot-nox        chapters/common.cpp runGnuplot (runProgram)
doxygen      doxygen            book/CMakeLists.txt
clang++      clang              scripts/fuzz.sh
chromium     chromium           book/layout_check.sh (the book layout, measured) and tests of the book
em++         emscripten         web/build_wasm.sh web/CMakeLists.txt (the live figures in WebAssembly)
emconfigure  emscripten         web/build_wasm.sh (GMP and MPFR for WebAssembly)
emmake       emscripten         web/build_wasm.sh
dpkg-source  dpkg-dev           web/build_wasm.sh (unpacks the Debian source of gmp)
chown        base               scripts/deps.sh
perf         optional:linux-perf  chapters/ch2/sec2_3_4_algorithms.cpp (the profile table; optional)
apt-get      base               scripts/deps.sh
dpkg-query   base               scripts/deps.sh scripts/check_deps.sh
dpkg         base               scripts/check_deps.sh
awk          base               scripts/test.sh
sed          base               figures/ch2/*.gp system(), scripts
cat          base               figures/ch2/*.gp system()
grep         base               scripts
script       base               tests/test_progress.cpp (a terminal for the progress display)
mkdir        base               scripts
mktemp       base               scripts
rm           base               scripts
tee          base               scripts/test.sh
nproc        base               scripts
dirname      base               scripts
basename     base               scripts/main.sh
readlink     base               scripts/check_deps.sh
apt-cache    base               scripts/check_deps.sh
sort         base               scripts/check_deps.sh
head         base               scripts
tail         base               scripts
ls           base               scripts/fuzz.sh
cp           base               scripts
node         nodejs             book and web checks (axe-core in Chromium, package.json)
npm          nodejs             scripts/deps.sh (npm ci: axe-core, pinned by package-lock.json)
bwrap        bubblewrap         scripts/exercise.sh (the sandbox of grading)
realpath     base               scripts/mutants.sh (paths relative to the tree)
setpriv      base               scripts/exercise.sh tests/test_cli.cpp (runs as the user nobody)
prlimit      base               scripts/exercise.sh tests/test_cli.cpp (process limits)
nm           binutils           scripts/exercise.sh (the functions the object of a student calls)
c++filt      binutils           scripts/exercise.sh (their names, demangled)
comm         base               scripts/exercise.sh
paste        base               scripts/exercise.sh
id           base               scripts/exercise.sh
cmp          base               scripts/deps.sh
git          git                scripts/mutants.sh (a temporary copy of the tree)
shellcheck   shellcheck         CMakeLists.txt (the ctest entry shellcheck: every script of scripts/)
tar          base               scripts/mutants.sh
touch        base               scripts/mutants.sh
mv           base               scripts
pdfinfo      poppler-utils      book/pdf_check.sh (the printed book: its pages)
pdfimages    poppler-utils      book/pdf_check.sh (the printed book: its figures)
pdftotext    poppler-utils      book/pdf_check.sh (the printed book: captions, chapter starts)
pdftoppm     poppler-utils      book/pdf_check.sh (the printed book: how full each page is)
date         base               scripts
sleep        base               scripts
timeout      base               scripts
find         base               scripts
xargs        base               scripts
wc           base               scripts
tr           base               scripts
cut          base               scripts
sha256sum    base               book/axe_check.sh (the stamp of a checked directory)
chmod        base               scripts/mutants.sh (the copy readable by others)
seq          base               book/layout_check_selftest.sh
diff         base               tests
env          base               scripts (#!/usr/bin/env bash)
bash         base               scripts
perl         base               scripts/check_deps.sh (perl-base)
sh           base               tests/support.h (runCli) tests/test_cli.cpp tests/test_bad_input.cpp (a signal during the writes, a pipe)
ln           base               tests/test_cli.cpp (a hard link to the input)
mkfifo       base               tests/test_bad_input.cpp (a named pipe as input)
'
# Shell words that are not programs (keywords and builtins) are skipped by the scan.
BUILTINS=" if then else elif fi for while until do done case esac in function return local export
 set unset shift exit echo printf read cd pwd test [ [[ ]] true false command type source . eval
 exec trap wait declare readonly let break continue shopt getopts mapfile time { } ! "

fail=0
say() { echo "check_deps: $*" >&2; fail=1; }

listed_packages() {  # the packages deps.sh installs (DT_PACKAGES and DT_OPTIONAL_PACKAGES)
  awk '/^[[:space:]]*DT_(OPTIONAL_)?PACKAGES=\(/ { on = 1 }
       on { line = $0; sub(/#.*/, "", line); gsub(/DT_(OPTIONAL_)?PACKAGES=\(|\)/, " ", line); print line }
       on && /\)/ { on = 0 }' "$1" | tr -s ' \t' '\n' | sed '/^$/d' | sort -u
}

declare -A owner_map=()
load_owners() {  # one dpkg -S call for every candidate path of every command (it is slow)
  local cmd path f paths=() line pkg
  while read -r cmd _; do
    [ -n "$cmd" ] || continue
    path=$(command -v "$cmd" 2>/dev/null) || continue
    for f in "$path" "$(readlink -f "$path")"; do paths+=("$f" "${f#/usr}"); done
  done <<< "$TABLE"
  while IFS= read -r line; do
    case $line in diversion*) continue ;; esac
    pkg=${line%%: *}; pkg=${pkg%%,*}
    owner_map[${line#*: }]=$pkg
  done < <(dpkg -S "${paths[@]}" 2>/dev/null)
}

owner_of() {  # the package owning a file: tries the path, its resolved target, and both
  local f g      # without the /usr prefix (dpkg may still register /bin/sed as /bin/sed)
  for f in "$1" "$(readlink -f "$1")"; do
    for g in "$f" "${f#/usr}"; do
      [ -n "${owner_map[$g]:-}" ] && { echo "${owner_map[$g]}"; return 0; }
    done
  done
  return 1
}

declare -A closure_of=()
depends_closure() {  # the installed packages $1 pulls in through Depends/Pre-Depends (cached)
  if [ -z "${closure_of[$1]+set}" ]; then
    closure_of[$1]=$(apt-cache depends --installed --recurse --no-recommends --no-suggests \
      --no-conflicts --no-breaks --no-replaces --no-enhances "$1" 2>/dev/null |
      sed -n 's/^\([a-z0-9][a-z0-9.+-]*\)\(:[a-z0-9]*\)\{0,1\}$/\1/p' | sort -u)
  fi
  echo "${closure_of[$1]}"
}

is_base_package() {
  [ "$(dpkg-query -W -f='${Essential}' "$1" 2>/dev/null)" = yes ] ||
    [ "$(dpkg-query -W -f='${Priority}' "$1" 2>/dev/null)" = required ]
}

check_table() {
  local listed cmd pkg where path owner opt
  listed=$(listed_packages "$deps_file")
  [ "${DT_CHECK_LISTS_ONLY:-0}" = 1 ] || load_owners
  while read -r cmd pkg where; do
    [ -n "$cmd" ] || continue
    opt=0
    case $pkg in optional:*) pkg=${pkg#optional:}; opt=1 ;; esac
    if [ "$pkg" != base ] && ! grep -qx "$pkg" <<< "$listed"; then
      say "$where calls '$cmd', whose package $pkg is not in $deps_file"
      continue
    fi
    [ "${DT_CHECK_LISTS_ONLY:-0}" = 1 ] && continue  # the self-test needs only the line above
    if ! path=$(command -v "$cmd" 2>/dev/null) || [ "${path#/}" = "$path" ]; then
      [ $opt = 1 ] && continue  # an optional program may be absent; its caller copes and says so
      say "$where calls '$cmd', which is not installed (bash scripts/deps.sh installs $pkg)"
      continue
    fi
    if ! owner=$(owner_of "$path") || [ -z "$owner" ]; then
      say "$where calls '$cmd' = $path, which no Debian package provides (installed by hand?)"
      continue
    fi
    if [ "$pkg" = base ]; then
      is_base_package "$owner" ||
        say "$where calls '$cmd' from package $owner, which is not Essential/required: add it to $deps_file"
    elif [ "$owner" != "$pkg" ] && ! grep -qx "$owner" <<< "$(depends_closure "$pkg")"; then
      say "$where calls '$cmd' from package $owner, which $pkg (in $deps_file) does not bring"
    fi
  done <<< "$TABLE"
}

in_table() { awk -v c="$1" '$1 == c { found = 1 } END { exit !found }' <<< "$TABLE"; }

# Prints "file: command" for every command word the scan finds. Every grep may find nothing
# (|| true): under set -e and pipefail a grep without a match would end the scan early, silently.
scan_sources() {
  local f
  # Shell scripts: the first word of every pipeline segment (after VAR=value assignments);
  # $(...) contents become segments of their own before quoted strings are dropped.
  local shells=(scripts/*.sh book/*.sh web/*.sh .ci/run)
  [ -n "${DT_SCAN_SCRIPT:-}" ] && shells=("$DT_SCAN_SCRIPT")  # the self-test's planted script
  for f in "${shells[@]}"; do
    [ -f "$f" ] || continue
    perl -0777 -n scripts/scan_commands.pl "$f"
  done
  # C++ sources that run commands through a shell: literals that begin with a program name and
  # a space.
  while IFS= read -r f; do
    { grep -oE '"[a-z][a-z0-9+._-]* [^"]*' "$f" || true; } | sed -e 's/^"//' -e 's/^command -v //' |
      awk -v file="$f" '{ print file ": " $1 }'
  done < <(grep -rlE 'std::system\(|popen\(|exec[lv]p?\(' code chapters cli tests book 2>/dev/null || true)
  # C++ sources that run commands without a shell (chapters/process.h, .cpp): the call form
  # runProgram({"prog", ...}) names the program as the vector's first literal.
  { grep -roE 'runProgram\(\{ *"[a-z][a-z0-9+._-]*"' code chapters cli tests book 2>/dev/null || true; } |
    sed -E 's/^([^:]*):.*"([^"]*)"$/\1: \2/' 
  # gnuplot scripts: system("prog ...") and system(sprintf("prog ...")).
  for f in figures/*/*.gp; do
    [ -f "$f" ] || continue
    { grep -oE "system\((sprintf\()?[\"'][a-z][a-z0-9+._-]*" "$f" || true; } |
      sed -E "s/.*[\"']//" | awk -v file="$f" '{ print file ": " $1 }'
  done
  # CMake: find_program(VAR name ...), find_package(Doxygen), COMMAND <literal program>.
  for f in CMakeLists.txt */CMakeLists.txt */*/CMakeLists.txt book/*.cmake; do
    [ -f "$f" ] || continue
    { grep -oE 'find_program\([A-Za-z_]+ +[a-z][a-z0-9+._-]*' "$f" || true; } | awk -v file="$f" '{ print file ": " $2 }'
    grep -qi 'find_package(Doxygen' "$f" && echo "$f: doxygen"
    { grep -oE 'COMMAND +[a-z][a-z0-9+._-]*' "$f" || true; } | awk -v file="$f" '{ print file ": " $2 }'
  done
}

check_scan() {
  local line file word
  while read -r line; do
    file=${line%%: *}; word=${line#*: }
    case " $BUILTINS " in *" $word "*) continue ;; esac
    case $word in */*|Q|-*|\$*|*=*|[0-9]*) continue ;; esac  # paths, strings, variables
    type -P "$word" > /dev/null 2>&1 || in_table "$word" || continue  # not a program name
    in_table "$word" || say "$file calls '$word', which is not in the table of scripts/check_deps.sh"
  done < <(scan_sources | sort -u)
}

if [ "${1:-}" = --self-test ]; then
  # Every package of the table must be load-bearing: without it in deps.sh, the check fails and
  # names the command.
  tmp=$(mktemp)
  trap 'rm -f "$tmp"' EXIT
  status=0
  mapfile -t packages < <(awk 'NF { sub(/^optional:/, "", $2); if ($2 != "base") print $2 }' <<< "$TABLE" | sort -u)
  for pkg in "${packages[@]}"; do
    re=$(sed 's/[+.]/\\&/g' <<< "$pkg")
    sed -E "s/(^|[[:space:](])$re([[:space:])]|$)/\1\2/" scripts/deps.sh > "$tmp"
    if out=$(DT_DEPS_FILE=$tmp DT_CHECK_LISTS_ONLY=1 bash "$0" 2>&1); then
      echo "self-test: FAILED: with $pkg removed from deps.sh the check still passes"; status=1
    elif ! grep -q "package $pkg is not in" <<< "$out"; then
      echo "self-test: FAILED: with $pkg removed the check fails without naming it:"; echo "$out"; status=1
    else
      echo "self-test: without $pkg: $(grep -m1 "package $pkg is not in" <<< "$out" | sed 's/^check_deps: //')"
    fi
  done
  # The scanner: a planted script calls one program that is not in the table (uname), and
  # names three others where the scan must not see a call: hostname in messages holding
  # apostrophes, nice in a case arm, stat in an array. The check must name uname, and only it.
  planted=tests/check_deps_planted.txt  # not a script of the scan: its calls are planted
  out=$(DT_SCAN_SCRIPT=$planted DT_SCAN_ONLY=1 bash "$0" 2>&1) && status=1
  if ! grep -q "calls 'uname'" <<< "$out" || grep "calls '" <<< "$out" | grep -qv "'uname'"; then
    echo "self-test: FAILED: the scan of a planted script should name uname, and nothing else:"
    echo "$out"; status=1
  else
    echo "self-test: the scan names the planted call of uname, and none of the quoted or case-arm words"
  fi
  exit $status
fi

[ "${DT_SCAN_ONLY:-0}" = 1 ] || check_table
[ "${DT_CHECK_LISTS_ONLY:-0}" = 1 ] || check_scan
if [ $fail != 0 ]; then
  echo "check_deps: FAILED (see above): install steps belong in scripts/deps.sh" >&2
  exit 1
fi
echo "check_deps: every external program comes from a package that scripts/deps.sh installs"
