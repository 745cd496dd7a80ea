#!/usr/bin/env bash
# Installs everything gjkx needs from Debian's packages. Idempotent: when every
# package is already installed it only checks (no apt-get update, no download).
set -euo pipefail

packages=(
  build-essential cmake pkg-config git
  libeigen3-dev            # linear algebra
  libcairo2-dev libpango1.0-dev fonts-dejavu-core   # the figures: Cairo draws (PNG, SVG, PDF), Pango sets the labels
  libosmesa6-dev           # offscreen OpenGL for the 3D figures
  libqhull-dev             # convex hulls of point sets
  catch2                   # tests (v2)
  libcli11-dev             # the command line of every program (CLI11, header only)
  doxygen graphviz libjs-mathjax   # docs (MathJax so formulas read offline)
  gnuplot-nox              # plots
  clang libclang-rt-14-dev # the sanitizer build and the libFuzzer targets (tests/fuzz)
  # the comparative study (chapter 09): the peers and the benchmark harness
  libccd-dev libfcl-dev libbullet-dev libbox2d-dev libbenchmark-dev
  # nonconvex bodies (mesh, kdop): meshes in through Assimp, HACD's convex decomposition
  # (Bullet's extras); assimp-testmodels gives real meshes nobody here wrote (BSD-3-clause)
  libassimp-dev assimp-testmodels libbullet-extras-dev
  # the simulation (dynamics, timewarp): Boost.Odeint's Dormand-Prince, JSON scene files
  libboost-dev nlohmann-json3-dev
  # the peers side by side on the simulation's scenes (docs 08): MuJoCo and ODE
  libmujoco-dev libode-dev
  # animations of a simulation or a query (animated WebP, shown inline by browsers)
  libwebp-dev
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
