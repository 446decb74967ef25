#!/usr/bin/env bash
# The rooms of code/ are layered: a file may include the headers of its own room and of the
# rooms before it in code/rooms.txt, never of a room after it; delaunay.h/.cpp in code/ itself
# may include every room, and no room includes them. Includes are bare names ("mesh.h"), so a
# header name must be unique across the rooms, and every folder of code/ must be a listed room.
#
#   bash scripts/layering.sh [ROOT]      checks ROOT/code (default: this checkout); prints each
#                                        include that climbs, then fails
#   bash scripts/layering.sh --self-test plants an include that climbs, a header name used by
#                                        two rooms and an unlisted folder in copies of code/, and
#                                        requires the check to fail on each, naming it, and to
#                                        pass the unchanged copy
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)

check() {
  local code=$1/code fail=0 room f inc k name
  local -a rooms=()
  local -A rank=() where=()
  while IFS= read -r room; do
    [[ $room =~ ^[a-z_]+$ ]] && rooms+=("$room")
  done < "$code/rooms.txt"
  for k in "${!rooms[@]}"; do rank[${rooms[$k]}]=$k; done
  local top=${#rooms[@]}
  for f in "$code"/*/; do
    room=$(basename "$f")
    [ -n "${rank[$room]+x}" ] || { echo "layering: code/$room/ is not a room of code/rooms.txt"; fail=1; }
  done
  # Where each header lives (the top's headers rank above every room).
  for f in "$code"/*.h "$code"/*/*.h; do
    [ -e "$f" ] || continue
    name=$(basename "$f"); room=${f#"$code"/}; room=${room%/*}
    [ "$room" = "$name" ] && room=.
    if [ -n "${where[$name]+x}" ]; then
      echo "layering: $name is a header of code/${where[$name]}/ and of code/$room/ (includes are bare names)"
      fail=1
    fi
    where[$name]=$room
  done
  for f in "$code"/*/*.h "$code"/*/*.cpp; do
    [ -e "$f" ] || continue
    room=${f#"$code"/}; room=${room%%/*}
    [ -n "${rank[$room]+x}" ] || continue
    while IFS= read -r inc; do
      if [ -z "${where[$inc]+x}" ]; then
        echo "layering: ${f#"$1"/} includes \"$inc\", which is no header of code/"; fail=1; continue
      fi
      local to=${where[$inc]} r=$top
      [ "$to" = . ] || r=${rank[$to]}
      if [ "$r" -gt "${rank[$room]}" ]; then
        echo "layering: ${f#"$1"/} (room $room) includes $inc of the higher room ${to/#./code/ itself}"
        fail=1
      fi
    done < <(sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"\([^"]*\)".*/\1/p' "$f")
  done
  return $fail
}

if [ "${1:-}" = --self-test ]; then
  tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
  status=0
  plant() {  # plant NAME EXPECTED-WORDS: a fresh copy, changed by the commands on stdin
    rm -rf "${tmp:?}/$1"; mkdir -p "$tmp/$1"; cp -r "$here/code" "$tmp/$1/code"
    ( cd "$tmp/$1/code" && bash )
    local out
    if out=$(check "$tmp/$1" 2>&1); then
      echo "self-test: FAILED: the check passes the copy with $1"; status=1
    elif ! grep -qF -- "$2" <<< "$out"; then
      echo "self-test: FAILED: with $1 the check fails without naming '$2':"; echo "$out"; status=1
    else
      echo "self-test: $1: $(grep -m1 -F -- "$2" <<< "$out")"
    fi
  }
  plant upward-include 'includes fast_core.h of the higher room fast' <<< \
    "sed -i '0,/^#include/s//#include \"fast_core.h\"\n#include/' base/tri.h"
  plant top-include 'includes delaunay.h of the higher room code/ itself' <<< \
    "sed -i '0,/^#include/s//#include \"delaunay.h\"\n#include/' io/writers.cpp"
  plant twin-header 'mesh.h is a header of' <<< "cp listings/mesh.h checks/mesh.h"
  plant unlisted-room 'code/attic/ is not a room' <<< "mkdir attic && cp base/tri.h attic/old_tri.h"
  rm -rf "${tmp:?}/clean"; mkdir -p "$tmp/clean"; cp -r "$here/code" "$tmp/clean/code"
  if out=$(check "$tmp/clean" 2>&1); then echo "self-test: the unchanged copy passes"
  else echo "self-test: FAILED: the unchanged copy fails:"; echo "$out"; status=1; fi
  exit $status
fi

root=${1:-$here}
check "$root"
echo "layering: every include of code/ stays in its room or goes to a room before it"
