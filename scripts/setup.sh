#!/usr/bin/env bash
# Installs the Debian packages walkrad needs (when any is missing), then configures and builds
# the Release preset into build/. Sourced by run.sh and test.sh so both do all their own set-up.
set -euo pipefail

packages=(
  cmake ninja-build g++ pkg-config python3-glad
  libglfw3-dev libglm-dev libosmesa6-dev libtinygltf-dev libimgui-dev libstb-dev
  nlohmann-json3-dev libcli11-dev libgtest-dev libbenchmark-dev
  xvfb xauth python3-xlib
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "walkrad setup: installing ${missing[*]}" >&2
  sudo_cmd=()
  [[ $(id -u) -eq 0 ]] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

cd "$(dirname "${BASH_SOURCE[0]}")/.."
cmake --preset release >/dev/null
cmake --build --preset release
