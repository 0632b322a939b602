// gbuffer_pass -- a deferred renderer's lighting pass with ltc::batch::shade (ltc/shading/
// batch_shade.hpp): a G-buffer of width x height floor points in structures of arrays (the
// normal and the material uniform, the rest per pixel), one quad light over all of them in SIMD
// lanes, checked against the scalar ltc::shade and timed against it.
//
//   gbuffer_pass [--width W] [--height H]
#include "common/cli.hpp"

#include <ltc/ltc.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

int main(int argc, char** argv) {
    int width = 256, height = 128;
    const auto help = [](const char* program) {
        std::printf("usage: %s [options]\n  --width W    G-buffer width (256)\n"
                    "  --height H   G-buffer height (128)\n  --help, -h   this text\n", program);
    };
    const auto flag = [](const std::string&) { return false; };
    const auto option = [&](const std::string& name, const ltc_examples::option_value& v) {
        int* target = name == "--width" ? &width : name == "--height" ? &height : nullptr;
        if (target == nullptr) return ltc_examples::option_status::unknown;
        if (!v.integer_in(1, 16384)) return ltc_examples::option_status::bad;
        *target = static_cast<int>(v.number);
        return ltc_examples::option_status::taken;
    };
    if (const int r = ltc_examples::parse_options(argc, argv, help, flag, option)) return r == 1 ? 0 : r;

    // The G-buffer: floor positions and view directions towards a camera at (0, -6, 3).
    const std::size_t count = std::size_t(width) * std::size_t(height);
    std::vector<float> p[3], v[3], out_data(6 * count);
    for (auto* a : {p, v})
        for (int c = 0; c < 3; ++c) a[c].resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        const glm::vec3 P(-4 + 8 * float(i % width) / width, -2 + 8 * float(i / width) / height, 0);
        const glm::vec3 V = glm::vec3(0, -6, 3) - P;
        for (int c = 0; c < 3; ++c) p[c][i] = P[c], v[c][i] = V[c];
    }
    ltc::batch::surfaces<float> gbuffer;
    gbuffer.count = count;
    gbuffer.position = {p[0].data(), p[1].data(), p[2].data()};
    gbuffer.normal = ltc::batch::uniform(glm::vec3(0, 0, 1));
    gbuffer.view = {v[0].data(), v[1].data(), v[2].data()};
    gbuffer.roughness = ltc::batch::uniform(0.35f);
    gbuffer.f0 = ltc::batch::uniform(glm::vec3(0.04f));
    gbuffer.albedo = ltc::batch::uniform(glm::vec3(0.7f, 0.6f, 0.5f));
    ltc::batch::shading_results<float> out;
    for (int c = 0; c < 3; ++c) out.specular[c] = &out_data[c * count], out.diffuse[c] = &out_data[(3 + c) * count];

    const glm::vec3 quad[4] = {{-1, 1, 2}, {1, 1, 2}, {1, 2, 2.5f}, {-1, 2, 2.5f}};
    const auto light = ltc::polygon_light<float>::one_sided(quad, 4, {0, -1, -2}, glm::vec3(8));
    using clock = std::chrono::steady_clock;
    const auto t0 = clock::now();
    ltc::batch::shade(gbuffer, light, out);
    const auto t1 = clock::now();
    float largest = 0, difference = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const ltc::shading_result<float> r = ltc::shade(gbuffer.at(i), light);
        for (int c = 0; c < 3; ++c) {
            largest = std::max(largest, r.specular[c] + r.diffuse[c]);
            difference = std::max({difference, std::abs(out.specular[c][i] - r.specular[c]),
                                   std::abs(out.diffuse[c][i] - r.diffuse[c])});
        }
    }
    const auto t2 = clock::now();
    const double batch_ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
    const double scalar_ms = std::chrono::duration<double, std::milli>(t2 - t1).count();
    const char* isa_names[] = {"automatic", "scalar", "baseline", "avx2", "avx512"};
    std::printf("%d x %d pixels: batch %.2f ms (%s), scalar %.2f ms; largest radiance %.4f, largest difference %.2e\n",
                width, height, batch_ms, isa_names[int(ltc::batch::resolve(ltc::batch::isa::automatic))], scalar_ms,
                largest, difference);
    return difference <= 1e-4f * std::max(1.0f, largest) ? 0 : 1;
}
