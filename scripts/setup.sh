#!/usr/bin/env bash
# Installs the Debian packages lathesim needs (scripts/packages.txt) and builds it in
# build/ (Release). Safe to run again: installs only what is missing, rebuilds only what
# changed.
#   scripts/setup.sh              builds only the command, build/lathesim (what a first part needs)
#   scripts/setup.sh TARGET …     builds those targets instead; `all` builds everything, the
#                                 test suite and benchmarks included (scripts/test.sh does) The build runs `npm ci` (viewer/package-lock.json, into build/viewer/) for the
# three.js viewer report.html carries, with Debian's nodejs and npm: the first build needs
# the npm registry, later ones find the packages in npm's cache.
set -euo pipefail
cd "$(dirname "$0")/.."

mapfile -t packages < <(grep -v '^\s*#' scripts/packages.txt | grep -v '^\s*$')
# What installed packages provide counts as installed (e.g. a Node.js package that carries
# its own npm and conflicts with Debian's).
declare -A provided=()
while read -r name; do
  [ -n "$name" ] && provided[$name]=1
done < <(dpkg-query -W -f='${db:Status-Abbrev}|${Provides}\n' 2>/dev/null |
  awk -F'|' '$1 ~ /^ii/ { print $2 }' | tr ',' '\n' | sed -e 's/([^)]*)//' -e 's/^ *//' -e 's/ *$//')
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" && continue
  [ -n "${provided[$p]:-}" ] && continue
  missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  sudo=""; [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

command -v npm >/dev/null || { echo "setup: npm (Debian's npm package) is needed to build report.html's 3D viewer" >&2; exit 1; }
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
targets=("${@:-lathesim}")
cmake --build build --parallel "$(nproc)" --target "${targets[@]}"
echo "setup: built ${targets[*]} in build/"
