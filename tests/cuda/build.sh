#!/usr/bin/env bash
# tests/cuda/build.sh OUTDIR [nvcc flags...] -- builds the CUDA checks into OUTDIR:
#   OUTDIR/kernel.o             tests/cuda/kernel.cu, compiled only (the device-code compile check);
#   OUTDIR/shade_gbuffer_check  tests/cuda/shade_gbuffer_check.cu linked with the CPU batch
#                               (shade_gbuffer_batch.cpp, host compiler: SIMD lanes), run it to
#                               compare the device with the host (no device: it says "skipped").
# .ci/run builds both in a background job; tests/cuda/device_run.sh builds the check alone
# (LTC_CUDA_COMPILE_CHECK=0) with -arch for the machine's GPU.
#
# The flags the check's bit-equality needs (shade_gbuffer_check.cu's comment says why): -fmad=false
# for device code, -ffp-contract=off for the host compiler, and nvcc's defaults -prec-div=true
# -prec-sqrt=true -ftz=false (never -use_fast_math). Environment: NVCC (default
# /usr/local/cuda/bin/nvcc, else nvcc on PATH); LTC_GLM_INCLUDE, a directory holding glm/ where GLM
# is not installed in the compiler's include path.
set -euo pipefail

out=${1:?usage: tests/cuda/build.sh OUTDIR [nvcc flags...]}
shift
mkdir -p "$out"
nvcc=${NVCC:-}
if [[ -z "$nvcc" ]]; then
  if [[ -x /usr/local/cuda/bin/nvcc ]]; then nvcc=/usr/local/cuda/bin/nvcc; else nvcc=$(command -v nvcc); fi
fi
cd "$(dirname "$0")/../.."

common=(-std=c++17 -I include)
[[ -n "${LTC_GLM_INCLUDE:-}" ]] && common+=(-I "$LTC_GLM_INCLUDE")
# 20012: GLM 0.9.9.8's defaulted constructors carry __host__ __device__ (harmless, GLM's own).
common+=(-diag-suppress 20012 -Werror all-warnings)
check=("${common[@]}" -fmad=false -O2 -Xcompiler -ffp-contract=off "$@")

pids=()
if [[ "${LTC_CUDA_COMPILE_CHECK:-1}" != 0 ]]; then
  "$nvcc" "${common[@]}" "$@" -c tests/cuda/kernel.cu -o "$out/kernel.o" & pids+=($!)
fi
"$nvcc" "${check[@]}" -c tests/cuda/shade_gbuffer_check.cu -o "$out/shade_gbuffer_check.o" & pids+=($!)
"$nvcc" "${check[@]}" -Xcompiler -Wall,-Wextra,-Werror -c tests/cuda/shade_gbuffer_batch.cpp \
  -o "$out/shade_gbuffer_batch.o" & pids+=($!)
rc=0
for p in "${pids[@]}"; do wait "$p" || rc=1; done
[[ $rc == 0 ]] || exit 1
"$nvcc" "${check[@]}" "$out/shade_gbuffer_check.o" "$out/shade_gbuffer_batch.o" -o "$out/shade_gbuffer_check"
echo "built $out/shade_gbuffer_check"
