#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Installs the Debian packages flexrock builds and tests with, only those missing.
# Usage: scripts/install-deps.sh [--python] [--bench] [--lint] [--mpi] [--fuzz] [--docs]
# (the Python module, its tests and the validation checks are part of the release build: their
# packages are always installed; --python is accepted and adds nothing)
set -euo pipefail

pkgs=(build-essential cmake ninja-build pkg-config
      libeigen3-dev libboost-dev libboost-math-dev
      libtomlplusplus-dev nlohmann-json3-dev libcli11-dev libfmt-dev
      libgtest-dev libgmock-dev python3 python3-sympy
      pybind11-dev python3-dev python3-numpy python3-scipy python3-matplotlib python3-pytest
      python3-pandas
      python3-venv python3-pip python3-setuptools python3-wheel)  # pip install . (offline)
for arg in "$@"; do
  case "$arg" in
    --python) pkgs+=(pybind11-dev python3-dev python3-numpy python3-matplotlib python3-pytest
                     python3-pandas) ;;
    --bench) pkgs+=(libbenchmark-dev python3-scipy python3-numpy python3-matplotlib
                    python3-siconos valgrind) ;;
    --lint) pkgs+=(clang-format) ;;
    --mpi) pkgs+=(openmpi-bin libopenmpi-dev) ;;  # studies across processes
    --fuzz) pkgs+=(clang-14 libclang-rt-14-dev) ;;  # libFuzzer targets (fuzz/, preset "fuzz")
    --docs) pkgs+=(doxygen python3-sphinx) ;;  # the API reference (scripts/api-docs.sh)
    *) echo "install-deps.sh: unknown option '$arg' (expected --python, --bench, --lint, --mpi, --fuzz or --docs)" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "install-deps.sh: installing ${missing[*]}"
sudo_cmd=()
[ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
