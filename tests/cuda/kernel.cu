// Compile check: the headers are usable in CUDA device code (LTC_HOST_DEVICE). .ci/run compiles
// this file with nvcc, warnings as errors, when /usr/local/cuda/bin/nvcc exists.
#include <ltc/ltc.hpp>

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
