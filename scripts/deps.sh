#!/usr/bin/env bash
# Installs the Debian packages the companion needs, if any is missing (run as root).
# Sourced by scripts/main.sh and scripts/test.sh; .ci/run calls it too.
set -euo pipefail
DT_PACKAGES=(g++ cmake make libgmp-dev libmpfr-dev doctest-dev gnuplot-nox doxygen
             libjs-mathjax clang libclang-rt-14-dev chromium fonts-dejavu-core)
missing=()
for p in "${DT_PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
