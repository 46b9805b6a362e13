#!/usr/bin/env bash
# Installs every Debian package hvi needs; quiet and quick when all are present.
set -euo pipefail
pkgs=(build-essential cmake pkg-config libeigen3-dev libhdf5-dev libvtk9-dev libgtest-dev libgmock-dev
      libfmt-dev libtomlplusplus-dev libcli11-dev libspdlog-dev nlohmann-json3-dev libbenchmark-dev
      python3-numpy python3-h5py python3-matplotlib)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "hvi setup: installing ${missing[*]}"
SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
