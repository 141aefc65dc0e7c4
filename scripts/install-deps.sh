#!/usr/bin/env bash
# Installs every Debian package texsynth needs to build, test and run its demo.
# Idempotent: packages already present are skipped, apt is only called when something is missing.
# Extra package names given as arguments are installed too (scripts/fuzz.sh adds clang).
set -euo pipefail

PACKAGES=(
  # toolchain
  build-essential cmake ninja-build pkg-config git clang-format ccache
  # libraries
  libeigen3-dev libtbb-dev libstb-dev libopenexr-dev libimath-dev zlib1g-dev libjpeg62-turbo-dev
  libnanoflann-dev libfaiss-dev libcgal-dev libopenvdb-dev libboost-iostreams-dev libblosc-dev libtinygltf-dev
  libcli11-dev nlohmann-json3-dev libgtest-dev libgmock-dev libbenchmark-dev libglpk-dev libzfp-dev
  # real data: exemplars, meshes, malformed models; a peer synthesizer for comparisons
  gimp-data libcgal-demo assimp-testmodels gmic
  # benchmarks: /usr/bin/time (bench/gradient_synthesis.sh), python3 (reads eval's JSON in
  # bench/synthesis_comparison.sh)
  time python3
  # flow animation videos and GIFs (texsynth animate)
  ffmpeg
  # texsynth studio: its HTTP server, and the browser its tests drive (headless, software WebGL)
  libcpp-httplib-dev chromium
)
# The studio page's packages come from npm (web/package.json); a machine with Node.js already keeps it.
command -v npm >/dev/null 2>&1 || PACKAGES+=(nodejs npm)
PACKAGES+=("$@")

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages present"
else
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  echo "install-deps: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# libcgal-demo ships its meshes inside a tarball under /usr/share/doc; extract the ones texsynth uses.
# Minimal images often drop /usr/share/doc at install time (dpkg path-exclude), so fall back to
# unpacking the package file itself.
DATA_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/.data"
MESHES=(bunny00.off elephant.off armadillo.off cow.off dino.off pig.off fandisk.off sphere.off cube.off)
if [ ! -f "$DATA_DIR/meshes/.complete" ]; then
  tarball=/usr/share/doc/libcgal-dev/data.tar.gz
  unpacked=""
  if [ ! -f "$tarball" ]; then
    unpacked=$(mktemp -d)
    chmod 755 "$unpacked"  # apt downloads as the _apt user
    (cd "$unpacked" && apt-get download -qq libcgal-demo && dpkg-deb -x libcgal-demo_*.deb root)
    tarball="$unpacked/root/usr/share/doc/libcgal-dev/data.tar.gz"
  fi
  mkdir -p "$DATA_DIR/meshes"
  tar -xzf "$tarball" -C "$DATA_DIR/meshes" --strip-components=2 $(printf 'data/meshes/%s ' "${MESHES[@]}")
  [ -n "$unpacked" ] && rm -rf "$unpacked"
  touch "$DATA_DIR/meshes/.complete"
  echo "install-deps: extracted ${#MESHES[@]} CGAL meshes into $DATA_DIR/meshes"
fi

# The studio page's front-end packages (three.js, three-mesh-bvh) and the browser tests' driver
# (playwright-core), at the versions web/package-lock.json pins; again only when the lock changed.
WEB_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/web"
stamp="$WEB_DIR/node_modules/.texsynth-lock"
if ! cmp -s "$WEB_DIR/package-lock.json" "$stamp"; then
  (cd "$WEB_DIR" && npm ci --no-audit --no-fund --loglevel=error)
  cp "$WEB_DIR/package-lock.json" "$stamp"
  echo "install-deps: installed the studio page's npm packages into web/node_modules"
fi
