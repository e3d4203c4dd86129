#!/usr/bin/env bash
# Installs the Debian 12 packages mdrsim needs to build, test and draw the paper's figures,
# and to build and test its Python module.
# Idempotent: when every package is already installed it only runs dpkg -s and exits,
# so the test and reproduce scripts can call it every time at no cost.
# `setup.sh fuzz` adds clang and its compiler-rt (libFuzzer, sanitizers) for scripts/fuzz.sh.
set -euo pipefail

packages=(
  cmake g++ make
  libeigen3-dev libspdlog-dev libfmt-dev libgtest-dev libbenchmark-dev libboost-dev
  libtomlplusplus-dev libcli11-dev nlohmann-json3-dev
  # Readers of measured force curves (engine/measured/, docs/afm.md): libzip opens JPK's zip
  # archives, HDF5's C library reads afmformats' .h5 exports; both found through pkg-config
  # (Debian's libzip CMake package also demands zipcmp, zipmerge and ziptool).
  libzip-dev libhdf5-dev pkgconf
  python3-matplotlib python3-numpy
  # The Python module (python/, docs/python.md "Installing"): pybind11, a venv and pip that install
  # offline, pytest; pandas for Result.to_dataframe (optional for users, tested here).
  pybind11-dev python3-dev python3-venv python3-pip python3-setuptools python3-wheel
  python3-pytest python3-pandas
  # The fitting example (python/examples) and its test, which executes the notebook.
  python3-scipy python3-nbclient python3-nbformat python3-ipykernel
  # mdrsim.sweep on a Dask cluster: python/tests/test_sweep.py runs a LocalCluster.
  python3-distributed
)
if [ "${1:-}" = "fuzz" ]; then
  packages+=(clang-14 libclang-rt-14-dev)
fi

missing=()
for p in "${packages[@]}"; do
  # dpkg -s succeeds for removed-but-configured packages too; check the status line.
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present" >&2
  exit 0
fi

echo "setup: installing ${missing[*]}" >&2
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then
    if [ -t 0 ]; then
      sudo_cmd=(sudo)      # a user at a terminal may be asked for a password
    else
      sudo_cmd=(sudo -n)   # no terminal (CI): fail rather than wait for a password
    fi
  else
    echo "setup: not root and no sudo; install as root: apt-get install ${missing[*]}" >&2
    exit 1
  fi
fi
"${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -q
"${sudo_cmd[@]}" env DEBIAN_FRONTEND=noninteractive \
  apt-get install -y -q --no-install-recommends "${missing[@]}"
