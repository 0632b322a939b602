#!/usr/bin/env bash
# The core, batch and shading unit tests built for 64-bit ARM (aarch64: the batch kernels' 16-byte
# lanes as NEON) with g++-aarch64-linux-gnu and run under qemu-user, on an x86-64 Debian machine:
#
#   apt-get install -y g++-aarch64-linux-gnu qemu-user libglm-dev catch2 cmake
#   tests/arm/run.sh [build folder, default build-arm]
#
# Emulation checks results, not speed: timings under qemu say nothing about an ARM CPU. GLM and
# Catch2 are header-only: the build folder gets an include folder that holds just their headers
# and two small CMake packages naming it, so that the cross compiler never sees the host's C
# library headers in /usr/include.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=${1:-$root/build-arm}
jobs=${LTC_ARM_JOBS:-2}
for tool in aarch64-linux-gnu-g++ qemu-aarch64; do
  command -v "$tool" >/dev/null || { echo "arm: $tool not found (apt-get install g++-aarch64-linux-gnu qemu-user)" >&2; exit 2; }
done

# The test files: the integrators of core/, the batch kernels and the scalar shading.
filter='^test_(quad_path|polygon_integration|transformed_integration|edge_policies|integrate_defaults|normalization|jacobian|bad_input|batch|batch_lanes|batch_scaling|batch_shade|batch_shading|shading|shading_ggx|shading_accuracy|shade|clipless|polygon_conventions)$'

stage=$build/host-headers
mkdir -p "$stage/include"
ln -sfn /usr/include/glm "$stage/include/glm"
ln -sfn /usr/include/catch2 "$stage/include/catch2"
# Config files of the two header-only packages, naming that folder (Catch.cmake, the test
# discovery, still comes from the host's package: it is CMake code, not target code).
mkdir -p "$stage/glm" "$stage/Catch2"
cat >"$stage/glm/glmConfig.cmake" <<CONFIG
add_library(glm::glm INTERFACE IMPORTED)
set_target_properties(glm::glm PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "$stage/include")
CONFIG
cat >"$stage/Catch2/Catch2Config.cmake" <<CONFIG
set(Catch2_VERSION 2)
add_library(Catch2::Catch2 INTERFACE IMPORTED)
set_target_properties(Catch2::Catch2 PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "$stage/include")
list(APPEND CMAKE_MODULE_PATH /usr/lib/cmake/Catch2)
CONFIG
printf 'set(PACKAGE_VERSION 2)\nset(PACKAGE_VERSION_COMPATIBLE TRUE)\n' >"$stage/Catch2/Catch2ConfigVersion.cmake"

cmake -S "$root" -B "$build" \
  -DCMAKE_TOOLCHAIN_FILE="$root/cmake/toolchains/aarch64-linux-gnu.cmake" \
  -DCMAKE_BUILD_TYPE=Release \
  -Dglm_DIR="$stage/glm" -DCatch2_DIR="$stage/Catch2" \
  -DLTC_BUILD_EXAMPLES=OFF -DLTC_BUILD_BENCHMARKS=OFF -DLTC_WARNINGS_AS_ERRORS=ON \
  -DLTC_CTEST_PER_FILE=ON -DLTC_TEST_FILTER="$filter"
cmake --build "$build" -j"$jobs" --target ltc_tests
file "$build/tests/ltc_tests" | sed 's/^/arm: /'
ctest --test-dir "$build" --output-on-failure -j"$jobs" -L unit
