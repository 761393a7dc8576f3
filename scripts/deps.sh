#!/usr/bin/env bash
# Installs what the build, the tests and the optional targets use, and only what is
# missing: Debian packages (as root, with apt-get) and npm packages into the project's
# own node_modules/ (from package.json / package-lock.json).
#
#   scripts/deps.sh [GROUP ...]      default: build
#
# Groups:
#   build    compilers and the libraries the library links (always included)
#   node     Node.js + npm, then the npm packages (gltf-validator, three, Playwright)
#   video    ffmpeg (MP4 of image sequences, checks of the video outputs)
#   blender  Blender (headless import checks of the glTF/OBJ/PC2/BVH outputs)
#   studio   emscripten, Chromium and the node group (the browser studio and its tests)
#   fuzz     clang and its sanitizer runtimes (libFuzzer harnesses)
#   test     build + node + video + clang-format (what `make test` needs)
#
# Without root it names what is missing and fails.
set -eu

build_packages=(
  build-essential     # gcc, make
  cmake
  pkg-config
  libomp-dev          # OpenMP runtime headers (gcc brings libgomp; clang builds use this)
  libpng-dev          # PNG read
  libdeflate-dev      # fast deflate for the PNG writer
  libopenexr-dev      # EXR read/write through the C API openexr.h
  libcjson-dev        # JSON presets, glTF
  libcmocka-dev       # unit tests
  liblapacke-dev      # dense symmetric solves (LAPACKE dposv/dpotrf)
  libsuitesparse-dev  # sparse Cholesky (CHOLMOD) for the tissue simulation
  libembree-dev       # ray tracing (Embree 3)
  libmeshoptimizer-dev # levels of detail
  libsmf-dev          # Standard MIDI Files
)
node_packages=(nodejs npm)
video_packages=(ffmpeg)
lint_packages=(clang-format) # the layout check (tests/lint/format.sh)
blender_packages=(blender python3-numpy) # numpy: Blender's glTF importer needs it
studio_packages=(emscripten node-acorn chromium)
fuzz_packages=(clang libclang-rt-14-dev)

groups=("$@")
[ ${#groups[@]} -eq 0 ] && groups=(build)

want=("${build_packages[@]}")
want_npm=0
for g in "${groups[@]}"; do
  case "$g" in
    build) ;;
    node) want_npm=1 ;;
    video) want+=("${video_packages[@]}") ;;
    blender) want+=("${blender_packages[@]}") ;;
    studio) want+=("${studio_packages[@]}"); want_npm=1 ;;
    fuzz) want+=("${fuzz_packages[@]}") ;;
    test) want+=("${video_packages[@]}" "${lint_packages[@]}"); want_npm=1 ;;
    *) echo "deps: error: unknown group '$g' (build node video blender studio fuzz test)" >&2; exit 2 ;;
  esac
done
# Node.js may come from elsewhere than Debian (e.g. a newer release): only install
# Debian's when no node/npm is on the PATH.
if [ "$want_npm" = 1 ]; then
  command -v node >/dev/null 2>&1 || want+=(nodejs)
  command -v npm >/dev/null 2>&1 || want+=(npm)
fi

missing=()
for p in "${want[@]}"; do
  if ! dpkg -s "$p" 2>/dev/null | grep -q '^Status: install ok installed'; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "deps: all ${#want[@]} packages present (${groups[*]})"
else
  echo "deps: installing ${missing[*]}"
  if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null 2>&1; then
      SUDO=sudo
    else
      echo "deps: error: missing packages (${missing[*]}) and not running as root" >&2
      exit 1
    fi
  else
    SUDO=
  fi
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -q
  $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
  echo "deps: installed ${missing[*]}"
fi

if [ "$want_npm" = 1 ]; then
  root=$(cd "$(dirname "$0")/.." && pwd)
  # Installed only when package-lock.json changed since the last install.
  stamp="$root/node_modules/.package-lock.json"
  if [ ! -f "$stamp" ] || [ "$root/package-lock.json" -nt "$stamp" ]; then
    echo "deps: npm packages into node_modules/"
    (cd "$root" && PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 npm ci --no-audit --no-fund --loglevel=error)
  else
    echo "deps: npm packages present"
  fi
fi
