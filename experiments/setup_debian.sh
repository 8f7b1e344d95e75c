#!/usr/bin/env bash
# Installs the Debian 12 packages aliaslab needs, skipping those already
# present. Run as root (or with sudo available). Nothing else is downloaded.
# munge and Slurm are for tests/slurm (slurm_test), which starts its own
# single-node cluster from a temporary folder: installing them configures no
# cluster (their services stay down without /etc/slurm/slurm.conf).
# chromium, chromium-driver and python3-selenium drive the page in a real browser
# (tests/browser); python3-openimageio reads the images there independently.
# python3-dev and pybind11-dev build the Python module (python/, docs/python.md).
set -euo pipefail

packages=(
  build-essential cmake ninja-build git
  libeigen3-dev libopenimageio-dev openimageio-tools libcli11-dev zlib1g-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  python3 python3-numpy python3-pandas python3-matplotlib python3-markdown
  parallel clang libclang-rt-14-dev
  munge slurmctld slurmd slurm-client
  chromium chromium-driver python3-selenium python3-openimageio python3-pil
  python3-dev pybind11-dev
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi
echo "setup: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
