#!/usr/bin/env bash
# Installs the Debian packages superpack builds and tests with, and only those missing:
# a second run on a ready machine does nothing and asks no mirror.
set -euo pipefail
packages=(build-essential cmake libboost-dev libmpfr-dev libgmp-dev libeigen3-dev catch2
          libmpfi-dev libflint-arb-dev libflint-dev nlohmann-json3-dev libcli11-dev
          gnuplot-nox python3 python3-mpmath python3-dev pybind11-dev python3-pybind11 python3-pytest
          python3-setuptools python3-wheel python3-venv)
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "install-deps: installing ${missing[*]}" >&2
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
