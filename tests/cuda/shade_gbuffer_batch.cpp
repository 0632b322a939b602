// tests/cuda/shade_gbuffer_batch.cpp -- shade_gbuffer_batch (shade_gbuffer_batch.hpp): the CPU
// batch of shade_gbuffer_check.cu, compiled by the host compiler (SIMD lanes), not by nvcc.
#include "shade_gbuffer_batch.hpp"

#include <ltc/shading/batch.hpp>
#include <ltc/shading/batch_shade.hpp>
#include <ltc/shading/lights/polygon_light.hpp>

#include <chrono>
#include <cstddef>

namespace {

ltc::polygon_light<float> make_light(const light_spec& l) {
    switch (l.kind) {
        case light_kind::counter_clockwise_front:
            return ltc::polygon_light<float>::one_sided(l.vertices.data(), l.vertices.size(),
                                                        ltc::winding::counter_clockwise_front, l.radiance);
        case light_kind::clockwise_front:
            return ltc::polygon_light<float>::one_sided(l.vertices.data(), l.vertices.size(),
                                                        ltc::winding::clockwise_front, l.radiance);
        case light_kind::two_sided: break;
    }
    return ltc::polygon_light<float>::two_sided(l.vertices.data(), l.vertices.size(), l.radiance);
}

const char* isa_name(ltc::batch::isa which) {
    switch (which) {
        case ltc::batch::isa::scalar: return "scalar";
        case ltc::batch::isa::baseline: return "baseline";
        case ltc::batch::isa::avx2: return "avx2";
        case ltc::batch::isa::avx512: return "avx512";
        case ltc::batch::isa::automatic: break;
    }
    return "automatic";
}

}  // namespace

batch_run shade_gbuffer_batch(const std::vector<ltc::surface<float>>& points, const std::vector<light_spec>& lights,
                              double min_seconds) {
    const std::size_t count = points.size();
    // The G-buffer as batch::surfaces' arrays, one per coordinate, as a renderer's G-buffer holds it.
    // 0-2 position, 3-5 normal, 6-8 view, 9 roughness, 10-12 F0, 13-15 albedo.
    std::vector<float> soa[16];
    for (auto& a : soa) a.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        const ltc::surface<float>& s = points[i];
        for (int c = 0; c < 3; ++c) {
            soa[c][i] = s.position[c], soa[3 + c][i] = s.normal[c], soa[6 + c][i] = s.view[c];
            soa[10 + c][i] = s.f0[c], soa[13 + c][i] = s.albedo[c];
        }
        soa[9][i] = s.roughness;
    }
    ltc::batch::surfaces<float> pts;
    pts.count = count;
    pts.position = {soa[0].data(), soa[1].data(), soa[2].data()};
    pts.normal = {soa[3].data(), soa[4].data(), soa[5].data()};
    pts.view = {soa[6].data(), soa[7].data(), soa[8].data()};
    pts.roughness = soa[9].data();
    pts.f0 = {soa[10].data(), soa[11].data(), soa[12].data()};
    pts.albedo = {soa[13].data(), soa[14].data(), soa[15].data()};

    std::vector<ltc::polygon_light<float>> built;
    for (const light_spec& l : lights) built.push_back(make_light(l));
    // Light l's results: channel c of specular at out[l][c], of diffuse at out[l][3 + c].
    std::vector<std::vector<float>> out(lights.size() * 6, std::vector<float>(count));
    std::vector<ltc::batch::shading_results<float>> results(lights.size());
    for (std::size_t l = 0; l < lights.size(); ++l)
        for (int c = 0; c < 3; ++c)
            results[l].specular[c] = out[6 * l + c].data(), results[l].diffuse[c] = out[6 * l + 3 + c].data();
    const auto pass = [&] {
        for (std::size_t l = 0; l < built.size(); ++l)
            ltc::batch::shade<ltc::ggx::one_lobe>(pts, built[l], results[l]);
    };

    batch_run run;
    run.isa = isa_name(ltc::batch::resolve(ltc::batch::isa::automatic));
    pass();  // warm-up: page faults on the outputs, the table into the caches
    run.per_light.resize(lights.size() * count);
    for (std::size_t l = 0; l < lights.size(); ++l)
        for (std::size_t i = 0; i < count; ++i)
            for (int c = 0; c < 3; ++c) {
                run.per_light[l * count + i].specular[c] = out[6 * l + c][i];
                run.per_light[l * count + i].diffuse[c] = out[6 * l + 3 + c][i];
            }
    using clock = std::chrono::steady_clock;
    const clock::time_point start = clock::now();
    double elapsed = 0;
    do {
        pass();
        ++run.passes;
        elapsed = std::chrono::duration<double>(clock::now() - start).count();
    } while (elapsed < min_seconds);
    run.seconds_per_pass = elapsed / run.passes;
    return run;
}
