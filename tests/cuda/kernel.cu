// Compile check: the headers are usable in CUDA device code (LTC_HOST_DEVICE). .ci/run compiles
// this file with nvcc, warnings as errors, when /usr/local/cuda/bin/nvcc exists.
#include <ltc/ltc.hpp>

// shade_gbuffer: world-space shading of a G-buffer with ltc::shade over a device table (run and
// checked against the host by shade_gbuffer_check.cu).
#include "shade_gbuffer.cuh"

__global__ void integrate_quads(const glm::vec3* quads, const glm::mat3* m_inv, float* out, int count) {
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= count) return;
    const glm::vec3* q = quads + 4 * i;
    const auto d = ltc::transformed<ltc::clamped_cosine<float>>::from_inverse(m_inv[i]);
    out[i] = d.integrate(q, 4, ltc::sidedness::two_sided) + ltc::form_factor(q, 4, ltc::sidedness::one_sided) +
             ltc::uniform_sphere<float>::integrate(q, 4) + ltc::uniform_hemisphere<float>::integrate(q, 4) +
             ltc::squared_clamped_cosine<float>::integrate(q, 4) + d.eval(glm::normalize(q[0])) +
             d.sample(glm::vec2(0.25f, 0.5f)).z + ltc::vector_form_factor(q, 4).z;
}

// The samplers of polygonal lights (projected cosine, LTC, area, solid angle, spherical triangle),
// one sample each, with their pdf and inversion.
__global__ void sample_quads(const glm::vec3* quads, const glm::mat3* m_inv, glm::vec4* out, int count) {
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= count) return;
    const glm::vec3* q = quads + 4 * i;
    const glm::vec2 u(0.25f, 0.5f);
    const ltc::projected_polygon_sampler<float> cosine(q, 4);
    const ltc::ltc_polygon_sampler<float> lobe(ltc::transformed<ltc::clamped_cosine<float>>::from_inverse(m_inv[i]), q, 4);
    const ltc::polygon_area_sampler<float> area(q, 4);
    const ltc::spherical_polygon_sampler<float> solid(q, 4);
    const ltc::spherical_triangle_sampler<float> tri(glm::normalize(q[0]), glm::normalize(q[1]), glm::normalize(q[2]));
    const ltc::polygon_sample<float> a = cosine.sample(u), b = lobe.sample(u);
    const glm::vec3 x = area.sample(u), y = solid.sample(u), z = tri.sample(u);
    const float pdfs = a.pdf + b.pdf + cosine.pdf(a.direction) + lobe.pdf(b.direction) + solid.pdf(y) + tri.pdf(z) +
                       area.solid_angle_pdf(glm::vec3(0.0f), x);
    const float inverses = cosine.invert(a.direction).x + lobe.invert(b.direction).y + solid.invert(y).x + tri.invert(z).y;
    out[i] = glm::vec4(a.direction + b.direction + x + y + z, pdfs + inverses);
}

// The two-lobe shading's second integral (the LTC integral without the form factor): I_ltc
// alone, in world space, for each lobe (coefficients from the two-lobe table on the host: the
// tables are host data).
__global__ void two_lobe_integrals(const glm::vec3* quads, const glm::mat3* m_inv, float* out, int count) {
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= count) return;
    const auto frame = ltc::make_shading_frame(glm::vec3(0.0f, 0.0f, 1.0f), glm::vec3(0.6f, 0.0f, 0.8f));
    out[i] = ltc::integrate_polygon_light_ltc(frame, m_inv[2 * i], glm::vec3(0.0f), quads + 4 * i, 4) +
             ltc::integrate_polygon_light_ltc(frame, m_inv[2 * i + 1], glm::vec3(0.0f), quads + 4 * i, 4);
}

// Screen-ordered sample points (ltc/core/screen_order.hpp): each pixel's point, and the first
// point of a lattice of n shifted by it one period (shadow_options::stratified_rotation).
__global__ void screen_points(glm::vec4* out, int width, int count, unsigned long long seed, unsigned n) {
    const int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i >= count) return;
    const glm::vec2 p = ltc::screen_point<float>(unsigned(i % width), unsigned(i / width), seed);
    out[i] = glm::vec4(p, ltc::detail::lattice_point(0, n, p, true));
}
