#!/usr/bin/env bash
# Installs the Debian packages pcsg needs, skipping those already present.
# Usage: scripts/install-deps.sh [--no-render]
set -euo pipefail
pkgs=(cmake g++ make pkg-config libeigen3-dev libfcl-dev libyaml-cpp-dev nlohmann-json3-dev
      libcli11-dev libgtest-dev libbenchmark-dev)
render_pkgs=(libosmesa6-dev libimgui-dev libstb-dev libassimp-dev libgraphviz-dev fonts-dejavu-core)
if [[ "${1:-}" != "--no-render" ]]; then pkgs+=("${render_pkgs[@]}"); fi

missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#pkgs[@]} packages present" >&2
  exit 0
fi
echo "install-deps: installing ${missing[*]}" >&2
SUDO=""
if [[ $(id -u) -ne 0 ]]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
