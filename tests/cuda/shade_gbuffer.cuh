// tests/cuda/shade_gbuffer.cuh -- a G-buffer pass with ltc::shade on the device: every point
// shaded by every polygon light with the one-lobe model over a table in device memory
// (ltc::ggx::one_lobe_of: the shipped tables are host data). Used by tests/cuda/kernel.cu (the
// compile check) and tests/cuda/shade_gbuffer_check.cu (device against host, and throughput).
//
// The host copies ltc::tables::ggx_data (ltc::tables::ggx_size^2 nodes, 6 floats each), the
// lights' vertices and the lights themselves to the device; each light is built over the device
// copy of its vertices with one_sided(vertices, n, winding, radiance) or two_sided (which check
// the pointer, not the vertices: one_sided with an emission normal reads them on the host), so
// that the copy refers to device memory.
#pragma once

#include <ltc/shading/ggx_models.hpp>
#include <ltc/shading/lights/polygon_light.hpp>
#include <ltc/shading/shade.hpp>
#include <ltc/shading/surface.hpp>
#include <ltc/tables/ltc_table.hpp>

/// The radiance reflected at s from lights[0..light_count), specular and diffuse apart: the sum of
/// ltc::shade(model, s, light) in the lights' order. Host and device run this one function, so
/// that the host reference of shade_gbuffer_check.cu adds in the kernel's order.
__host__ __device__ inline ltc::shading_result<float> shade_point(const ltc::ggx::one_lobe_of& model,
                                                                  const ltc::surface<float>& s,
                                                                  const ltc::polygon_light<float>* lights,
                                                                  int light_count) {
    ltc::shading_result<float> sum;
    for (int l = 0; l < light_count; ++l) {
        const ltc::shading_result<float> r = ltc::shade(model, s, lights[l]);
        sum.specular += r.specular;
        sum.diffuse += r.diffuse;
    }
    return sum;
}

/// One thread per G-buffer point: out[i] = shade_point over the lights, with the one-lobe model
/// over the table_size x table_size table at table_data (device memory, ltc_table's layout).
__global__ void shade_gbuffer(const ltc::surface<float>* points, int count, const ltc::polygon_light<float>* lights,
                              int light_count, const float* table_data, int table_size,
                              ltc::shading_result<float>* out) {
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= count) return;
    const ltc::ggx::one_lobe_of model{ltc::ltc_table(table_data, table_size, table_size)};
    out[i] = shade_point(model, points[i], lights, light_count);
}
