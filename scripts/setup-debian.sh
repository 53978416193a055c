#!/usr/bin/env bash
# Installs what primitive-edit needs on Debian 12 and fetches MeshLab 2020.09's source (headers and
# vcglib matching Debian's binary) into .deps/. Safe to run twice: each step is skipped when done.
# PRIMITIVE_EDIT_EXTRA_PACKAGES="p1 p2": more Debian packages to install.
# PRIMITIVE_EDIT_BENCH_PACKAGES=1: also OpenCASCADE, for bench/bracket/make_bracket (rebuilding the CAD
# bracket; the bundled bench/data is committed, so nothing else needs it).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
sudo=""
[ "$(id -u)" = 0 ] || sudo="sudo"

bench_packages=""
if [ "${PRIMITIVE_EDIT_BENCH_PACKAGES:-0}" = 1 ]; then
  bench_packages="libocct-modeling-algorithms-dev libocct-modeling-data-dev libocct-foundation-dev
                  libocct-data-exchange-dev libtbb-dev"
fi
packages=(meshlab qtbase5-dev libqt5opengl5-dev libqt5xmlpatterns5-dev libglew-dev libeigen3-dev
          xvfb xauth xdotool imagemagick cmake g++ clang libclang-rt-14-dev libgtest-dev dpkg-dev
          python3 ${PRIMITIVE_EDIT_EXTRA_PACKAGES:-} $bench_packages)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

src_list=/etc/apt/sources.list.d/debian-src.sources
need_src=0
[ -d "$here/.deps/meshlab-2020.09+dfsg1/src" ] || need_src=1
if [ "$need_src" = 1 ] && [ ! -f "$src_list" ] && ! grep -rqs '^Types:.*deb-src\|^deb-src' /etc/apt/sources.list /etc/apt/sources.list.d/; then
  sed -e 's/^Types: deb$/Types: deb-src/' /etc/apt/sources.list.d/debian.sources | $sudo tee "$src_list" >/dev/null
fi

if [ ${#missing[@]} -gt 0 ] || [ "$need_src" = 1 ]; then
  $sudo apt-get update -qq
fi
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
if [ "$need_src" = 1 ]; then
  echo "setup: fetching MeshLab 2020.09 source into .deps/"
  mkdir -p "$here/.deps"
  (cd "$here/.deps" && apt-get source -qq meshlab=2020.09+dfsg1-2 >/dev/null 2>&1 || (cd "$here/.deps" && apt-get source -qq meshlab))
fi
test -f "$here/.deps/meshlab-2020.09+dfsg1/src/common/interfaces.h"
echo "setup: ready"
