// The pre-0.2 flat header paths and the 0.2 paths of headers that moved down a layer (the BRDF
// models, the table format, the sphere form factor), now deprecated forwarding headers, still
// compile and work from outside the project (README, "Headers and the paper").
#include <ltc/batch.hpp>
#include <ltc/brdf/beckmann.hpp>
#include <ltc/brdf/ggx.hpp>
#include <ltc/brdf/model.hpp>
#include <ltc/clamped_cosine.hpp>
#include <ltc/clipless.hpp>
#include <ltc/fit.hpp>
#include <ltc/fitting/brdf/beckmann.hpp>
#include <ltc/fitting/brdf/ggx.hpp>
#include <ltc/fitting/brdf/model.hpp>
#include <ltc/fitting/brdf/schlick.hpp>
#include <ltc/ggx.hpp>
#include <ltc/ground_truth.hpp>
#include <ltc/light_texture.hpp>
#include <ltc/polygon.hpp>
#include <ltc/shading.hpp>
#include <ltc/shading/sphere_form_factor.hpp>
#include <ltc/shading/table.hpp>
#include <ltc/squared_clamped_cosine.hpp>
#include <ltc/table.hpp>
#include <ltc/textured.hpp>
#include <ltc/textured_ground_truth.hpp>
#include <ltc/transformed.hpp>
#include <ltc/uniform_hemisphere.hpp>
#include <ltc/uniform_sphere.hpp>

#include <cmath>
#include <cstdio>

int main() {
    const glm::vec3 quad[4] = {{-1, -1, 2}, {1, -1, 2}, {1, 1, 2}, {-1, 1, 2}};
    const auto c = ltc::ggx::fetch(0.5f, 0.5f);
    const auto d = ltc::transformed<ltc::clamped_cosine<float>>::from_inverse(c.m_inv);
    const float values[] = {
        d.integrate(quad, 4, ltc::sidedness::two_sided),
        ltc::form_factor(quad, 4, ltc::sidedness::two_sided),
        ltc::clipless::form_factor(quad, 4, ltc::sidedness::two_sided),
        ltc::uniform_sphere<float>::integrate(quad, 4),
        ltc::uniform_hemisphere<float>::integrate(quad, 4),
        ltc::squared_clamped_cosine<float>::integrate(quad, 4),
        float(ltc::fit::node_roughness(1, 3)),
        ltc::brdf::ggx<float>::eval(glm::vec3(0, 0, 1), glm::vec3(0, 0, 1), 0.25f),
        ltc::brdf::beckmann<float>::eval(glm::vec3(0, 0, 1), glm::vec3(0, 0, 1), 0.25f),
    };
    bool ok = true;
    for (float v : values) ok = ok && std::isfinite(v) && v > 0.0f;
    std::printf("ltc_consumer_old_paths: %s\n", ok ? "ok" : "FAILED");
    return ok ? 0 : 1;
}
