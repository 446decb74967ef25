#!/usr/bin/env bash
# Installs the Debian packages the companion needs, if any is missing (run as root).
# Called by scripts/main.sh and scripts/test.sh; .ci/run calls it too. Every program the
# repository runs comes from one of these packages (or from Debian's base system):
# scripts/check_deps.sh checks it, and fails if a package is missing here.
set -euo pipefail
DT_PACKAGES=(g++ cmake make libgmp-dev libmpfr-dev doctest-dev gnuplot-nox doxygen
             libjs-mathjax clang libclang-rt-14-dev chromium fonts-dejavu-core fonts-dejavu-extra git
             shellcheck)
# Optional: CGAL, the reference of bench_kernels (the build detects it; without it the benchmark
# compares the listings with the fast kernel only), and perf, which samples one Table 2.1 run for
# the 2.3.4 page (without it that table says so). Installed only when asked, e.g. by
# scripts/main.sh with DT_WITH_OPTIONAL=1, never required: the tests do not need them.
DT_OPTIONAL_PACKAGES=(libcgal-dev linux-perf)

missing_of() {
  local p
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || echo "$p"
  done
}
export DEBIAN_FRONTEND=noninteractive
mapfile -t missing < <(missing_of "${DT_PACKAGES[@]}")
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
if [ "${DT_WITH_OPTIONAL:-0}" = 1 ]; then
  for p in $(missing_of "${DT_OPTIONAL_PACKAGES[@]}"); do
    echo "installing (optional): $p"
    { apt-get update -qq && apt-get install -y -qq --no-install-recommends "$p"; } ||
      echo "$p could not be installed: the programs that use it say so and go on without it"
  done
fi
