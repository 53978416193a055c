#!/usr/bin/env bash
# Builds MeshLab 2025.07 (core, GUI and the stock plugins our tests need) from Debian's source, so that
# primitive-edit can be built and tested against the current plugin API. Debian 12 has no binary of it.
#
# The source is Debian's orig tarball of meshlab 2025.07~dfsg (sid/forky), fetched through a deb-src
# entry for sid; its Build-Depends are all in bookworm. The build is cached outside the clone, in
# ${PRIMITIVE_EDIT_CACHE_DIR:-$HOME/.cache/primitive-edit}/meshlab-2025.07, so a second run (or CI on
# the same machine) does not rebuild it; .deps/meshlab-2025.07 links to it. A cold build takes about
# 9 minutes on 2 cores. Safe to run twice. Prints the path of the build when done.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
sudo=""
[ "$(id -u)" = 0 ] || sudo="sudo"

version="2025.07~dfsg-4"
orig="meshlab_2025.07~dfsg.orig.tar.xz"
cache="${PRIMITIVE_EDIT_CACHE_DIR:-$HOME/.cache/primitive-edit}/meshlab-2025.07"
jobs=$(nproc)
# The stock plugins the tests use: PLY/OBJ/STL input and output, the default decorations, selection,
# and Conditional Face Selection (filter_func, with Debian's muparser).
plugins="meshlabplugins/io_base;meshlabplugins/decorate_base;meshlabplugins/filter_select;meshlabplugins/edit_select;meshlabplugins/filter_func"
# Optional libraries come from Debian or not at all: MeshLab's own downloads cannot reach the network here.
no_downloads=""
for lib in BOOST CGAL EMBREE LEVMAR LIB3DS LIB3MF LIBE57 LIBIGL MUPARSER NEXUS OPENCTM QHULL STRUCTURE_SYNTH TINYGLTF \
           U3D XERCES; do
  no_downloads="$no_downloads -DMESHLAB_ALLOW_DOWNLOAD_SOURCE_$lib=OFF"
done
stamp="$cache/build/.primitive-edit-built-$(echo "$plugins" | md5sum | cut -c1-8)"

link_into_deps() {
  mkdir -p "$here/.deps"
  ln -sfn "$cache" "$here/.deps/meshlab-2025.07"
}

if [ -f "$stamp" ] && [ -x "$cache/build/src/distrib/meshlab" ]; then
  link_into_deps
  echo "setup-2025: cached build in $cache"
  exit 0
fi

packages=(cmake g++ qtbase5-dev libqt5opengl5-dev libglew-dev libeigen3-dev libglu1-mesa-dev mesa-common-dev
          libmuparser-dev xz-utils dpkg-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

mkdir -p "$cache"
if [ ! -f "$cache/$orig" ]; then
  # Source only: a deb-src entry never changes which binary packages apt installs.
  sid_src=/etc/apt/sources.list.d/debian-sid-src.sources
  if [ ! -f "$sid_src" ]; then
    printf 'Types: deb-src\nURIs: http://deb.debian.org/debian\nSuites: sid\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' \
      | $sudo tee "$sid_src" >/dev/null
  fi
  $sudo apt-get update -qq
  echo "setup-2025: fetching MeshLab $version source"
  # apt checks the tarball against the signed Sources index; the Debian packaging files are not needed.
  (cd "$cache" && apt-get source --download-only -qq "meshlab=$version" >/dev/null 2>&1 || true)
  [ -f "$cache/$orig" ] || { echo "setup-2025: could not fetch $orig" >&2; exit 1; }
fi
if [ ${#missing[@]} -gt 0 ]; then
  [ -f /var/lib/apt/lists/lock ] && $sudo apt-get update -qq
  echo "setup-2025: installing ${missing[*]}"
  $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

if [ ! -f "$cache/src/ML_VERSION" ]; then
  rm -rf "$cache/src" "$cache/src.tmp"
  mkdir -p "$cache/src.tmp"
  tar xJf "$cache/$orig" -C "$cache/src.tmp" --strip-components=1
  mv "$cache/src.tmp" "$cache/src"
fi

echo "setup-2025: building MeshLab 2025.07 in $cache/build (about 9 min on 2 cores, once)"
# shellcheck disable=SC2086
cmake -S "$cache/src" -B "$cache/build" -DCMAKE_BUILD_TYPE=Release -DMESHLAB_BUILD_STRICT=OFF -DMESHLAB_ALLOW_OPTIONAL_EXTERNAL_LIBRARIES=ON $no_downloads \
      -DMESHLAB_PLUGINS="$plugins" -Wno-dev >"$cache/configure.log" 2>&1 \
  || { tail -40 "$cache/configure.log" >&2; exit 1; }
cmake --build "$cache/build" -j"$jobs" >"$cache/build.log" 2>&1 || { tail -60 "$cache/build.log" >&2; exit 1; }
touch "$stamp"
link_into_deps
echo "setup-2025: built $cache/build"
