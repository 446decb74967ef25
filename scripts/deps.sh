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
# Optional: CGAL, the reference of bench_kernels (the build detects it; without it the benchmark
# compares the listings with the fast kernel only). Installed only when asked, e.g. by
# scripts/main.sh with DT_WITH_OPTIONAL=1, never required: CI builds without it.
if [ "${DT_WITH_OPTIONAL:-0}" = 1 ] &&
   ! dpkg-query -W -f='${Status}' libcgal-dev 2>/dev/null | grep -q "install ok installed"; then
  echo "installing (optional): libcgal-dev"
  export DEBIAN_FRONTEND=noninteractive
  { apt-get update -qq && apt-get install -y -qq --no-install-recommends libcgal-dev; } ||
    echo "libcgal-dev could not be installed: bench_kernels will run without CGAL"
fi
