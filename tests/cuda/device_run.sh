#!/usr/bin/env bash
# tests/cuda/device_run.sh [points [gpu_repetitions [cpu_seconds]]] -- on a machine with a CUDA
# GPU: builds shade_gbuffer_check for that GPU (tests/cuda/build.sh, -arch=$LTC_CUDA_ARCH, default
# native) and runs it on a G-buffer of `points` points (default 1048576, a 1024 x 1024 G-buffer:
# enough work to fill a large GPU, so that the launch overhead does not set the rate), printing the
# checks and the throughputs, device and CPU batch (shade_gbuffer_check.cu's comment). Exit status:
# the check's (0 pass, 1 a check failed, 2 a CUDA error), or 3 when it cannot be built.
#
# Needs nvcc (NVCC, /usr/local/cuda/bin/nvcc, or nvcc on PATH) and GLM: where <glm/glm.hpp> is not
# in the compiler's include path (a machine without libglm-dev, and no internet to fetch it), set
# LTC_GLM_INCLUDE to a directory holding a copy of glm/ (absolute, or relative to the repository
# root; e.g. the glm/ of a machine's /usr/include copied into the working tree). Takes well under
# a minute to build and under a minute to run on a 16-core machine (the host reference and the CPU batch,
# one thread each, take most of the run).
set -euo pipefail
cd "$(dirname "$0")/../.."

nvcc=${NVCC:-}
if [[ -z "$nvcc" ]]; then
  if [[ -x /usr/local/cuda/bin/nvcc ]]; then nvcc=/usr/local/cuda/bin/nvcc; else nvcc=$(command -v nvcc || true); fi
fi
if [[ -z "$nvcc" ]]; then
  echo "device_run.sh: no nvcc (set NVCC)" >&2
  exit 3
fi
glm_probe=(g++ -x c++ -std=c++17 -fsyntax-only)
[[ -n "${LTC_GLM_INCLUDE:-}" ]] && glm_probe+=(-I "$LTC_GLM_INCLUDE")
if ! echo '#include <glm/glm.hpp>' | "${glm_probe[@]}" - 2>/dev/null; then
  echo "device_run.sh: <glm/glm.hpp> not found (set LTC_GLM_INCLUDE to a directory holding glm/)" >&2
  exit 3
fi
if command -v nvidia-smi >/dev/null; then
  nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader || true
fi
"$nvcc" --version | tail -n1
nproc

out=$(mktemp -d "${TMPDIR:-/tmp}/ltc-cuda.XXXXXX")
trap 'rm -rf "$out"' EXIT
SECONDS=0
NVCC="$nvcc" LTC_CUDA_COMPILE_CHECK=0 tests/cuda/build.sh "$out" -arch="${LTC_CUDA_ARCH:-native}" || {
  echo "device_run.sh: the build failed" >&2
  exit 3
}
echo "build: ${SECONDS} s"
SECONDS=0
rc=0
"$out/shade_gbuffer_check" "${1:-1048576}" "${2:-20}" "${3:-2}" || rc=$?
echo "run: ${SECONDS} s, exit ${rc}"
exit "$rc"
