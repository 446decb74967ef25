#!/usr/bin/env bash
# Installs the Debian packages the companion needs, if any is missing (run as root).
# Called by scripts/main.sh and scripts/test.sh; .ci/run calls it too. Every program the
# repository runs comes from one of these packages (or from Debian's base system):
# scripts/check_deps.sh checks it, and fails if a package is missing here.
set -euo pipefail
DT_PACKAGES=(g++ cmake make libgmp-dev libmpfr-dev doctest-dev gnuplot-nox doxygen
             libjs-mathjax clang libclang-rt-14-dev chromium fonts-dejavu-core fonts-dejavu-extra git
             shellcheck emscripten dpkg-dev bubblewrap binutils nodejs
             poppler-utils ccache)
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
# The live figures (web/, book/live.md) need GMP compiled to WebAssembly; it is built
# (web/build_wasm.sh) from Debian's own source package, fetched here, once, with
# `apt-get source gmp` into /var/cache/dt-wasm-src. deb-src is enabled for the system's Debian
# release only if no source index is configured yet.
wasm_src=${DT_WASM_SRC:-/var/cache/dt-wasm-src}
if ! ls "$wasm_src"/gmp_*.dsc > /dev/null 2>&1; then
  if [ -z "$(apt-cache showsrc gmp 2>/dev/null)" ]; then
    codename=$(sed -n 's/^VERSION_CODENAME=//p' /etc/os-release)
    printf '%s\n' "# Added by scripts/deps.sh: Debian's source packages (GMP for WebAssembly)" \
      "Types: deb-src" "URIs: http://deb.debian.org/debian" "Suites: $codename" \
      "Components: main" "Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg" \
      > /etc/apt/sources.list.d/dt-deb-src.sources
    apt-get update -qq
  fi
  mkdir -p "$wasm_src"
  chown _apt "$wasm_src" 2>/dev/null || true  # apt downloads as _apt when it can
  (cd "$wasm_src" && apt-get source --download-only -qq gmp)
fi
# npm: Debian ships it as its own package; a nodejs from elsewhere (NodeSource) brings its own
# npm and conflicts with Debian's, so the package is installed only when no npm is there.
if ! command -v npm > /dev/null; then
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends npm
fi
# axe-core (the accessibility rules the book's and the live figures' checks run in Chromium),
# the one npm package, at the version package-lock.json pins; installed again only when the
# lock file changed since the last install.
(
  cd "$(dirname "$0")/.."
  if ! cmp -s package-lock.json node_modules/.dt-installed-lock.json 2> /dev/null ||
     [ ! -f node_modules/axe-core/axe.min.js ]; then
    npm ci --no-audit --no-fund --ignore-scripts --loglevel=error
    cp package-lock.json node_modules/.dt-installed-lock.json
  fi
)
if [ "${DT_WITH_OPTIONAL:-0}" = 1 ]; then
  for p in $(missing_of "${DT_OPTIONAL_PACKAGES[@]}"); do
    echo "installing (optional): $p"
    { apt-get update -qq && apt-get install -y -qq --no-install-recommends "$p"; } ||
      echo "$p could not be installed: the programs that use it say so and go on without it"
  done
fi
