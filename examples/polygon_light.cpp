// polygon_light -- one polygonal light over a row of floor points, each of the three GGX models
// (ltc::shade<Model>, ltc/shading/shade.hpp), printed as a table. The program to copy from for a
// renderer's shading of one light:
//
//   polygon_light [--roughness R]
#include "common/cli.hpp"

#include <ltc/ltc.hpp>

#include <cstdio>

int main(int argc, char** argv) {
    float roughness = 0.3f;
    const auto help = [](const char* program) {
        std::printf("usage: %s [options]\n  --roughness R   the floor's roughness in [0, 1] (0.3)\n"
                    "  --help, -h      this text\n", program);
    };
    const auto flag = [](const std::string&) { return false; };
    const auto option = [&](const std::string& name, const ltc_examples::option_value& v) {
        if (name != "--roughness") return ltc_examples::option_status::unknown;
        if (!v.is_number || v.number < 0 || v.number > 1) return ltc_examples::option_status::bad;
        roughness = static_cast<float>(v.number);
        return ltc_examples::option_status::taken;
    };
    if (const int r = ltc_examples::parse_options(argc, argv, help, flag, option)) return r == 1 ? 0 : r;

    // A 2 m x 1 m light, 2 m above the floor, emitting downwards.
    const glm::vec3 quad[4] = {{-1, -0.5f, 2}, {1, -0.5f, 2}, {1, 0.5f, 2}, {-1, 0.5f, 2}};
    const auto light = ltc::polygon_light<float>::one_sided(quad, 4, {0, 0, -1}, glm::vec3(10));
    std::printf("   x | one_lobe: spec  diff | ltc_and_cosine: spec | two_lobes: spec\n");
    for (int i = 0; i <= 8; ++i) {
        const float x = -2.0f + 0.5f * float(i);
        const ltc::surface<float> s{{x, 0, 0}, {0, 0, 1}, {0, -2, 1}, roughness, glm::vec3(0.04f), glm::vec3(0.6f)};
        const auto a = ltc::shade<ltc::ggx::one_lobe>(s, light);
        const auto b = ltc::shade<ltc::ggx::ltc_and_cosine>(s, light);
        const auto c = ltc::shade<ltc::ggx::two_lobes>(s, light);
        std::printf("%4.1f | %13.5f %5.3f | %20.5f | %15.5f\n", x, a.specular.x, a.diffuse.x, b.specular.x, c.specular.x);
    }
    return 0;
}
