// ltc/config.hpp -- version and the host/device annotation shared by every header.
//
// LTC_HOST_DEVICE is empty for host compilers and `__host__ __device__` under CUDA, so the
// same evaluation and integration code runs in a renderer on either side (as pbrt-v4 does).
#pragma once

#define LTC_VERSION_MAJOR 0
#define LTC_VERSION_MINOR 1
#define LTC_VERSION_PATCH 0

#if defined(__CUDACC__)
#define LTC_HOST_DEVICE __host__ __device__
#else
#define LTC_HOST_DEVICE
#endif
