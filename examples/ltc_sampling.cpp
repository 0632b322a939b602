// ltc_sampling -- importance sampling a polygonal light with its LTC in a path tracer: the
// specular integral int_P rho_GGX cos of one shading point estimated by Monte Carlo with the
// LTC restricted to the light (ltc_polygon_sampler, density D / I_D: paper eq. 1 and 3) and with
// uniform samples of the light's area, next to the analytic LTC value magnitude * I_D. The
// program to copy from for a renderer that traces the light's samples (shadow rays) itself.
//
//   ltc_sampling [--samples N]
#include "common/cli.hpp"

#include <ltc/ltc.hpp>

#include <cmath>
#include <cstdio>

int main(int argc, char** argv) {
    int samples = 256;
    const auto help = [](const char* program) {
        std::printf("usage: %s [options]\n  --samples N   samples per estimate (256)\n"
                    "  --help, -h    this text\n", program);
    };
    const auto flag = [](const std::string&) { return false; };
    const auto option = [&](const std::string& name, const ltc_examples::option_value& v) {
        if (name != "--samples") return ltc_examples::option_status::unknown;
        if (!v.integer_in(1, 1e8)) return ltc_examples::option_status::bad;
        samples = static_cast<int>(v.number);
        return ltc_examples::option_status::taken;
    };
    if (const int r = ltc_examples::parse_options(argc, argv, help, flag, option)) return r == 1 ? 0 : r;

    // The local frame of the tables: N = +z, V in the xz-plane; a quad light above the point.
    const float roughness = 0.4f, alpha = roughness * roughness;
    const glm::vec3 V(std::sqrt(1 - 0.6f * 0.6f), 0, 0.6f);
    const glm::vec3 quad[4] = {{-0.5f, -1, 1.5f}, {-0.5f, 1, 1.5f}, {-2.5f, 1, 1.0f}, {-2.5f, -1, 1.0f}};
    const ltc::ltc_coefficients<float> c = ltc::ggx::fetch(V.z, roughness);
    const auto d = ltc::transformed<ltc::clamped_cosine<float>>::from_inverse(c.m_inv);
    const ltc::ltc_polygon_sampler<float> by_ltc(d, quad, 4);
    const ltc::polygon_area_sampler<float> by_area(quad, 4);

    // f = rho cos, the BRDF's integrand (no Fresnel, like the table's magnitude).
    const auto f = [&](const glm::vec3& l) { return ltc::brdf::ggx<float>::eval(V, l, alpha); };
    double ltc_sum = 0, area_sum = 0;
    for (int k = 0; k < samples; ++k) {
        const float u1 = (float(k) + 0.5f) / float(samples);
        const float u2 = float(k) * 0.618034f - std::floor(float(k) * 0.618034f);
        const ltc::polygon_sample<float> x = by_ltc.sample({u1, u2});  // trace a shadow ray along x.direction here
        if (x.pdf > 0) ltc_sum += f(x.direction) / x.pdf;
        const glm::vec3 y = by_area.sample({u1, u2});
        const float p = by_area.solid_angle_pdf(glm::vec3(0), y);
        if (p > 0) area_sum += f(glm::normalize(y)) / p;
    }
    std::printf("int_P rho cos: analytic LTC %.5f; Monte Carlo with %d samples: LTC sampling %.5f, area sampling %.5f\n",
                c.magnitude * d.integrate(quad, 4), samples, ltc_sum / samples, area_sum / samples);
    return 0;
}
