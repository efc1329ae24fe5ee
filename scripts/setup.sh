#!/usr/bin/env bash
# Install the Debian packages TemplateQuad needs, then configure and build it.
# Re-running skips what is already done: apt is only called for missing packages,
# and the build is incremental.
#
#   scripts/setup.sh            install packages (if missing) and build into build/
#   scripts/setup.sh --no-build install packages only
set -euo pipefail

repo_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

build=yes
packages=(
  # build
  cmake ninja-build g++ pkg-config
  # core, io, cli, tests
  nlohmann-json3-dev libcli11-dev libgtest-dev
  # core: least-squares fits (a curved loop's surface, fitted_surface.h)
  libeigen3-dev
  # occ: OpenCASCADE 7.6 (Debian's CMake targets link libtbb, hence libtbb-dev)
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev
  libocct-data-exchange-dev libtbb-dev
  # python: the tquad module for Debian's python3 (FreeCAD's)
  pybind11-dev python3-dev python3-numpy
  # FreeCAD (the workbench's host; brings its own OpenCASCADE 7.6 runtime) and a
  # virtual display for its GUI test
  freecad xvfb xauth
  # tests: real readers and the solver of the files written (meshio, Gmsh, CalculiX);
  # Gmsh is also the peer of bench/compare_gmsh.py
  python3-meshio gmsh python3-gmsh calculix-ccx
  # figures: meshes drawn to PNG (tools/draw_mesh.py)
  python3-matplotlib
  # packaging: cpack -G DEB finds the package's library dependencies with
  # dpkg-shlibdeps
  dpkg-dev
  # fuzzing: libFuzzer targets built with clang (scripts/fuzz.sh)
  clang libclang-rt-14-dev
)
for arg in "$@"; do
  case "$arg" in
    --no-build) build=no ;;
    *) echo "setup: unknown option $arg (use --no-build)" >&2; exit 2 ;;
  esac
done

missing=()
for pkg in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$pkg")
  fi
done

if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
else
  echo "setup: all Debian packages present"
fi

if [ "$build" = no ]; then
  exit 0
fi

build_dir="$repo_dir/build"
if [ ! -f "$build_dir/build.ninja" ]; then
  cmake -S "$repo_dir" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$build_dir" --parallel "$(nproc)"

# The FreeCAD workbench, with the module just built, for this user's freecad and
# freecadcmd (freecad_workbench/install.sh --uninstall removes it).
"$repo_dir/freecad_workbench/install.sh" "$build_dir/python/tquad"
