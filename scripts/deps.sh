#!/usr/bin/env bash
# Installs the Debian packages the build and tests use, and only the missing ones.
# Runs non-interactively as root (apt-get); without root it names what is missing.
set -eu

packages=(
  build-essential   # gcc, make
  cmake
  pkg-config
  libomp-dev        # OpenMP runtime headers (gcc brings libgomp; clang builds use this)
  libpng-dev        # PNG read/write
  libopenexr-dev    # EXR read/write through the C API openexr.h
  libcjson-dev      # JSON presets
  libcmocka-dev     # unit tests
  liblapacke-dev    # dense symmetric solves (LAPACKE dposv/dpotrf)
  libembree-dev     # ray tracing (Embree 3)
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg -s "$p" >/dev/null 2>&1 || ! dpkg -s "$p" 2>/dev/null | grep -q '^Status: install ok installed'; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "deps: all ${#packages[@]} packages present"
  exit 0
fi

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
