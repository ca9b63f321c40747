#!/usr/bin/env bash
# Installs what hyperelastic needs from Debian 12's packages, skipping what is
# already there: deal.II 9.4 (with Trilinos, METIS, MPI), CMake, a compiler
# and matplotlib (the pictures of scripts/plot_fit.py and the benchmarks).
set -euo pipefail

packages=(libdeal.ii-dev cmake g++ make openmpi-bin python3-matplotlib)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-dependencies: all of ${packages[*]} are installed"
  exit 0
fi

echo "install-dependencies: installing ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq "${missing[@]}" >/dev/null
echo "install-dependencies: done"
