// tests/cuda/shade_gbuffer_check.cu -- shade_gbuffer (shade_gbuffer.cuh) run on a CUDA device
// against the host: a fixed-seed G-buffer shaded by eight polygon lights with the one-lobe GGX
// model (ltc::ggx::one_lobe_of over a device copy of ltc::tables::ggx_data), compared
//   (a) with the host's own ltc::shade on the same model over the host table, compiled into this
//       program: bit for bit (a zero of either sign excepted), each light's contribution and the
//       sum over the lights;
//   (b) with the CPU batch, ltc::batch::shade<ltc::ggx::one_lobe> (shade_gbuffer_batch.cpp):
//       the largest difference relative to the value, reported;
// and timed: shading points x lights per second on the device (cudaEvents) and in the CPU batch
// on one host thread (std::chrono), and their ratio. No result may be NaN or infinite.
//
// Why (a) is bit-equal. Built with nvcc -fmad=false (no multiply-add contraction in device code)
// and the defaults -prec-div=true -prec-sqrt=true -ftz=false (float division and sqrtf correctly
// rounded, 0 ulp in the CUDA C++ Programming Guide's table of the maths functions' errors;
// subnormals kept), and with the host compiler told -ffp-contract=off, every operation on the
// path is one IEEE 754 operation, correctly rounded on both sides, in the order the source fixes
// (neither compiler reassociates floating-point expressions without fast-math):
//   - make_shading_frame (ltc/shading/shading_frame.hpp): +, -, *, dot and cross products,
//     safe_normalize's 1 / sqrt (ilogb and ldexp, exact, on its rare rescaling path), the
//     comparisons of glm::clamp, and orthonormal_tangent's std::copysign (exact: a sign bit) and
//     division, for V = +-N;
//   - ltc_table::fetch (ltc/tables/ltc_table.hpp): saturate, sqrt, std::floor and std::abs
//     (exact), int conversions, and the lerps of the device copy of the same floats;
//   - the polygon light (ltc/shading/lights/polygon_light.hpp, polygon_light_integrals.hpp):
//     the local vertices (rescaled: a division by the largest |coordinate|), M^-1 p, the
//     horizon clipping of the quad path (ltc/core/detail/quad_lanes.hpp: the plain-struct lanes
//     on the device; on the host those or the vector ones, shade_gbuffer_batch.hpp says why
//     either: the same bits in every build, as its comment states) and of the general path
//     (ltc/core/horizon_clip.hpp, safe_normalize), the determinant, the sidedness;
//   - the edge terms with the float default, edge_policy::minimax_rational
//     (ltc/core/edge_policy.hpp): a rational function (multiply-adds, one division), pi / |a x b|
//     with glm::length's sqrt, and std::copysign for the horizon edge -- no atan2, acos or other
//     function that CUDA does not round correctly (only edge_policy::exact calls atan2, the
//     default in double, not in float);
//   - brdf_scale, radiance times scale times integral, and shade_point's sums over the lights.
// Constants (T(0.999999965867), pi<float>()) are converted at compile time, round to nearest on
// both sides. So the device's floats are the host's, and any difference is a bug (a call that is
// not correctly rounded, a contraction, a host-only branch): the check requires equality of the
// bits and prints the largest distance in ulps where they differ. One allowance: a zero result
// may come with the other sign. The device compiler selects PTX max.f32 for apply_sidedness's
// `x > 0 ? x : 0` (ltc/core/sidedness.hpp; seen in the PTX of this file), and this check does
// not rest on max.f32 ordering -0 below +0: where a signed integral is -0, a one-sided light's
// contribution may be -0 on the device and +0 on the host, the same value (counted apart).
// The PTX of this program's kernel holds only add, sub, mul, div, sqrt and rcp in their .rn
// forms, abs, neg, copysign, min and max, comparisons and conversions: no fma, no .approx, no
// rsqrt, no .ftz.
//
// (b) The batch lanes differ from the scalar path by rounding within the bound that
// tests/test_batch_shade.cpp derives and checks (its file comment); with (a), that bound is the
// one between the batch and the device. This program reports the largest difference relative to
// the value rather than deriving it again (and where it is: the largest are at V == N with a low
// roughness, where one rounding of cos theta_v just below 1 moves the table's coordinate
// u = sqrt(1 - cos theta_v) by sqrt(eps / 2), about a sixtieth of a cell of the 64-node table, and
// a sharp lobe's shear with it: a real sensitivity of the table's parameterization, not an error
// of either path).
//
// Usage: shade_gbuffer_check [points [gpu_repetitions [cpu_seconds]]] (defaults 4096, 20, 0.5).
// Exit status: 0 when every check passes, or when no CUDA device is found ("skipped: no CUDA
// device", after the host side: the host reference and the timed CPU batch); 1 when a check
// fails (a difference in (a), NaN or infinity); 2 on a CUDA error with a device present.
#include "shade_gbuffer.cuh"
#include "shade_gbuffer_batch.hpp"

#include <ltc/reference/splitmix64.hpp>
#include <ltc/tables/ggx.hpp>

#include <glm/glm.hpp>

#include <cuda_runtime.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace {

/// Exit on a CUDA error with its name (status 2: the device, not the library, failed).
void check_cuda(cudaError_t e, const char* what) {
    if (e == cudaSuccess) return;
    std::fprintf(stderr, "CUDA error in %s: %s (%s)\n", what, cudaGetErrorName(e), cudaGetErrorString(e));
    std::exit(2);
}

/// Uniform floats in [lo, hi) from the fixed-seed generator of the library's tests.
struct draw {
    ltc::ground_truth::splitmix64 rng;
    float operator()(float lo, float hi) { return lo + (hi - lo) * float(rng.uniform()); }
    glm::vec3 vec(float lo, float hi) {
        const float x = (*this)(lo, hi);
        const float y = (*this)(lo, hi);
        const float z = (*this)(lo, hi);
        return {x, y, z};
    }
    /// A direction, uniform on the sphere (rejection from the cube), of length 1 to rounding.
    glm::vec3 direction() {
        for (;;) {
            const glm::vec3 v = vec(-1.0f, 1.0f);
            const float l2 = glm::dot(v, v);
            if (l2 > 1e-4f && l2 <= 1.0f) return v / std::sqrt(l2);
        }
    }
};

/// The G-buffer: points on a floor (N = +z) and on surfaces of any orientation (normals of
/// any length), seen from every kind of view the library treats apart: V == N exactly, V
/// parallel to N at another length, V below the surface (N.V < 0, interpolated normals), grazing
/// views, and ordinary ones; roughness 0 and 1 exactly, out of [0, 1] (clamped), and between;
/// one point in 97 with a zero normal (shaded as 0).
std::vector<ltc::surface<float>> make_gbuffer(int count, std::uint64_t seed) {
    draw d{ltc::ground_truth::splitmix64(seed)};
    std::vector<ltc::surface<float>> points(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
        ltc::surface<float>& s = points[static_cast<std::size_t>(i)];
        s.position = glm::vec3(d(-3.0f, 3.0f), d(-3.0f, 3.0f), i % 3 == 0 ? 0.0f : d(0.0f, 1.0f));
        glm::vec3 n = i % 4 == 0 ? glm::vec3(0, 0, 1) : d.direction();
        if (n.z < -0.5f) n.z = -n.z;  // mostly facing the lights, some away (n.z in [-0.5, 0))
        s.normal = n * d(0.5f, 2.0f);
        glm::vec3 v = d.direction();
        switch (i % 8) {
            case 0: v = s.normal; break;            // V == N
            case 1: v = n * 2.5f; break;            // V parallel to N, another length
            case 2:
            case 3: if (glm::dot(v, n) > 0.0f) v = -v; break;  // below the surface
            case 4: v = v - n * glm::dot(v, n) + n * d(0.0f, 1e-3f); break;  // grazing
            default: if (glm::dot(v, n) < 0.0f) v = -v; break;
        }
        s.view = v * d(0.1f, 10.0f);
        switch (i % 13) {
            case 0: s.roughness = 0.0f; break;
            case 1: s.roughness = 1.0f; break;
            case 2: s.roughness = d(-0.5f, 0.0f); break;
            case 3: s.roughness = d(1.0f, 1.5f); break;
            default: s.roughness = d(0.0f, 1.0f); break;
        }
        s.f0 = d.vec(0.02f, 1.0f);
        s.albedo = d.vec(0.0f, 1.0f);
        if (i % 97 == 96) s.normal = glm::vec3(0.0f);
    }
    return points;
}

/// A planar regular n-gon about `center` of circumradius r, in the plane orthogonal to the
/// direction `facing`, its vertices turning counter-clockwise about `facing` (the right-hand
/// normal is along `facing`), or clockwise where `clockwise`.
std::vector<glm::vec3> regular_polygon(int n, glm::dvec3 center, double r, glm::dvec3 facing, bool clockwise) {
    const glm::dvec3 f = glm::normalize(facing);
    const glm::dvec3 a = std::abs(f.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 e1 = glm::normalize(glm::cross(a, f)), e2 = glm::cross(f, e1);  // e1 x e2 = f
    std::vector<glm::vec3> v;
    for (int k = 0; k < n; ++k) {
        const double t = 2.0 * ltc::pi<double>() * (clockwise ? -k : k) / n;
        v.push_back(glm::vec3(center + r * (std::cos(t) * e1 + std::sin(t) * e2)));
    }
    return v;
}

/// Eight lights of 3 to 8 vertices, one-sided by each winding and two-sided, above the floor,
/// tilted and crossing the floor's horizon (z < 0), facing the G-buffer from its front. A
/// one-sided light emits along `down` (its emission side): counter_clockwise_front with its
/// vertices turning counter-clockwise about it, clockwise_front with them turning clockwise.
std::vector<light_spec> make_lights() {
    using k = light_kind;
    const auto one_sided = [](int n, glm::dvec3 c, double r, glm::dvec3 emits, k kind, glm::vec3 L) {
        return light_spec{regular_polygon(n, c, r, emits, kind == k::clockwise_front), kind, L};
    };
    return {
        one_sided(4, {0.0, 0.0, 2.0}, 0.7, {0, 0, -1}, k::counter_clockwise_front, {4, 4, 4}),
        one_sided(3, {1.5, -1.0, 1.2}, 0.6, {-0.3, 0.4, -1}, k::clockwise_front, {3, 2, 1}),
        light_spec{regular_polygon(5, {-2.5, 0.0, 0.6}, 0.8, {1, 0.2, 0}, false), k::two_sided, {1, 2, 3}},
        light_spec{regular_polygon(4, {2.0, 2.0, 0.3}, 1.0, {-1, -1, 0.5}, true), k::two_sided, {2, 2, 1}},
        one_sided(6, {-1.0, 1.5, 1.6}, 0.5, {0.5, -0.5, -1}, k::clockwise_front, {1, 3, 2}),
        one_sided(7, {0.5, -2.0, 0.8}, 0.9, {0, 1, -0.3}, k::counter_clockwise_front, {2, 1, 3}),
        one_sided(8, {0.0, 0.0, 3.5}, 1.5, {0.1, 0, -1}, k::counter_clockwise_front, {1, 1, 1}),
        one_sided(4, {0.0, 3.0, 0.2}, 0.8, {0, -1, 0}, k::clockwise_front, {5, 3, 1}),
    };
}

/// The light of `spec` over `vertices` (the host's, or the device copy of them: the factories
/// used here check the pointer only).
ltc::polygon_light<float> make_light(const light_spec& spec, const glm::vec3* vertices) {
    const std::size_t n = spec.vertices.size();
    switch (spec.kind) {
        case light_kind::counter_clockwise_front:
            return ltc::polygon_light<float>::one_sided(vertices, n, ltc::winding::counter_clockwise_front,
                                                        spec.radiance);
        case light_kind::clockwise_front:
            return ltc::polygon_light<float>::one_sided(vertices, n, ltc::winding::clockwise_front, spec.radiance);
        case light_kind::two_sided: break;
    }
    return ltc::polygon_light<float>::two_sided(vertices, n, spec.radiance);
}

bool finite(const ltc::shading_result<float>& r) {
    for (int c = 0; c < 3; ++c)
        if (!std::isfinite(r.specular[c]) || !std::isfinite(r.diffuse[c])) return false;
    return true;
}

/// The six floats of r: specular, then diffuse.
void channels(const ltc::shading_result<float>& r, float (&out)[6]) {
    for (int c = 0; c < 3; ++c) out[c] = r.specular[c], out[3 + c] = r.diffuse[c];
}

/// Distance in ulps between two finite floats (their order-preserving integer images).
std::int64_t ulps(float a, float b) {
    const auto key = [](float x) {
        std::int32_t i;
        std::memcpy(&i, &x, sizeof i);
        return i < 0 ? std::int64_t(INT32_MIN) - i : std::int64_t(i);
    };
    const std::int64_t d = key(a) - key(b);
    return d < 0 ? -d : d;
}

/// Counts the items of `got` that differ from `want`'s (a channel whose value is not the same
/// float: different bits, but a zero of either sign equals a zero), and the largest distance in
/// ulps; and the items whose bits differ in the sign of a zero alone.
struct bit_comparison {
    std::size_t items = 0, differing = 0, zero_signs = 0;
    std::int64_t max_ulps = 0;
    void add(const ltc::shading_result<float>& got, const ltc::shading_result<float>& want) {
        ++items;
        if (std::memcmp(&got, &want, sizeof got) == 0) return;
        float g[6], w[6];
        channels(got, g), channels(want, w);
        bool differs = false;
        for (int c = 0; c < 6; ++c) {
            differs = differs || !(g[c] == w[c]);
            max_ulps = std::max(max_ulps, ulps(g[c], w[c]));
        }
        ++(differs ? differing : zero_signs);
    }
};

/// How far `got` is from `want` (items [l * points + i], light l's contribution to point i),
/// relative to the value: the largest |got - want| / max(|got|, |want|) over the channels whose
/// value is at least 1e-3 of that light's largest value of that channel over the G-buffer (the
/// relative difference of a near-zero value, e.g. a mirror's 1e-8 specular off its reflection,
/// says nothing), with the item where it occurs; and the largest |got - want| relative to that
/// largest value (the difference on the image's scale); and how many items have a channel
/// (above the same floor) whose relative difference exceeds 1e-4.
struct relative_comparison {
    double max_relative = 0, max_of_peak = 0;
    std::size_t at = 0, beyond = 0, items = 0;
};

relative_comparison compare_relative(const std::vector<ltc::shading_result<float>>& got,
                                     const std::vector<ltc::shading_result<float>>& want, std::size_t points) {
    relative_comparison r;
    for (std::size_t base = 0; base < got.size(); base += points) {
        double peak[6] = {};
        for (std::size_t i = base; i < base + points; ++i) {
            float g[6], w[6];
            channels(got[i], g), channels(want[i], w);
            for (int c = 0; c < 6; ++c) peak[c] = std::max({peak[c], double(std::abs(g[c])), double(std::abs(w[c]))});
        }
        for (std::size_t i = base; i < base + points; ++i) {
            float g[6], w[6];
            channels(got[i], g), channels(want[i], w);
            ++r.items;
            bool beyond = false;
            for (int c = 0; c < 6; ++c) {
                if (!(peak[c] > 0)) continue;
                const double diff = std::abs(double(g[c]) - double(w[c]));
                const double size = std::max(std::abs(double(g[c])), std::abs(double(w[c])));
                r.max_of_peak = std::max(r.max_of_peak, diff / peak[c]);
                if (size < 1e-3 * peak[c]) continue;
                beyond = beyond || diff / size > 1e-4;
                if (diff / size > r.max_relative) r.max_relative = diff / size, r.at = i;
            }
            r.beyond += beyond ? 1 : 0;
        }
    }
    return r;
}

/// Prints a relative_comparison with the G-buffer point where the largest relative difference is.
void print_relative(const char* what, const relative_comparison& r, const std::vector<ltc::surface<float>>& points) {
    const ltc::surface<float>& s = points[r.at % points.size()];
    const ltc::shading_frame<float> f = ltc::make_shading_frame(s.normal, s.view);
    std::printf("%s: largest relative difference %.3g (light %zu, point %zu: cos theta_v %.9g, roughness %.3g), "
                "largest difference relative to the light's largest value %.3g; %zu of %zu items differ by more "
                "than 1e-4 relative\n",
                what, r.max_relative, r.at / points.size(), r.at % points.size(), double(f.cos_theta_v),
                double(s.roughness), r.max_of_peak, r.beyond, r.items);
}

template <typename T>
T* device_copy(const T* host, std::size_t count, const char* what) {
    T* p = nullptr;
    check_cuda(cudaMalloc(&p, count * sizeof(T)), what);
    check_cuda(cudaMemcpy(p, host, count * sizeof(T), cudaMemcpyHostToDevice), what);
    return p;
}

}  // namespace

int main(int argc, char** argv) {
    const int count = argc > 1 ? std::atoi(argv[1]) : 4096;
    const int gpu_repetitions = argc > 2 ? std::atoi(argv[2]) : 20;
    const double cpu_seconds = argc > 3 ? std::atof(argv[3]) : 0.5;
    if (count < 1 || gpu_repetitions < 1) {
        std::fprintf(stderr, "usage: %s [points [gpu_repetitions [cpu_seconds]]]\n", argv[0]);
        return 1;
    }
    int devices = 0;
    const bool have_device = cudaGetDeviceCount(&devices) == cudaSuccess && devices > 0;

    const std::vector<ltc::surface<float>> points = make_gbuffer(count, 0x17c40u);
    const std::vector<light_spec> specs = make_lights();
    const int light_count = int(specs.size());
    const std::size_t n = points.size();
    std::vector<ltc::polygon_light<float>> host_lights;
    for (const light_spec& s : specs) host_lights.push_back(make_light(s, s.vertices.data()));

    // (a)'s reference: the host's ltc::shade, the same model over the host table.
    const ltc::ggx::one_lobe_of host_model{
        ltc::ltc_table(ltc::tables::ggx_data, ltc::tables::ggx_size, ltc::tables::ggx_size)};
    std::vector<ltc::shading_result<float>> host_per_light(n * specs.size()), host_sum(n);
    const auto scalar_start = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < n; ++i) {
        for (int l = 0; l < light_count; ++l)
            host_per_light[std::size_t(l) * n + i] =
                shade_point(host_model, points[i], &host_lights[std::size_t(l)], 1);
        host_sum[i] = shade_point(host_model, points[i], host_lights.data(), light_count);
    }
    const double scalar_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - scalar_start).count();

    const batch_run batch = shade_gbuffer_batch(points, specs, cpu_seconds);
    const double items = double(n) * light_count;
    const double cpu_rate = items / batch.seconds_per_pass;

    bool ok = true;
    std::size_t nonfinite = 0;
    for (const auto& r : host_per_light) nonfinite += finite(r) ? 0 : 1;
    for (const auto& r : host_sum) nonfinite += finite(r) ? 0 : 1;
    for (const auto& r : batch.per_light) nonfinite += finite(r) ? 0 : 1;
    if (nonfinite > 0) {
        std::printf("FAIL: %zu host or batch results are NaN or infinite\n", nonfinite);
        ok = false;
    }

    std::printf("G-buffer: %zu points x %d lights (3 to 8 vertices; one-sided by each winding, two-sided)\n", n,
                light_count);
    std::printf("host ltc::shade (scalar, one thread, this program's nvcc host build): %.3g s for the points x lights "
                "and their sums\n",
                scalar_seconds);
    std::printf("CPU batch (ltc::batch::shade<ggx::one_lobe>, isa %s, one thread): %.4g s per pass (%d timed), "
                "%.4g points x lights / s\n",
                batch.isa, batch.seconds_per_pass, batch.passes, cpu_rate);
    print_relative("CPU batch against host ltc::shade", compare_relative(batch.per_light, host_per_light, n), points);

    if (!have_device) {
        std::printf("skipped: no CUDA device\n");
        return ok ? 0 : 1;
    }

    cudaDeviceProp prop{};
    check_cuda(cudaGetDeviceProperties(&prop, 0), "cudaGetDeviceProperties");
    std::printf("device: %s (compute capability %d.%d)\n", prop.name, prop.major, prop.minor);

    // The table, the vertices (one array, each light's run of them) and the lights over them.
    const float* d_table = device_copy(ltc::tables::ggx_data, sizeof ltc::tables::ggx_data / sizeof(float), "table");
    std::vector<glm::vec3> all_vertices;
    for (const light_spec& s : specs) all_vertices.insert(all_vertices.end(), s.vertices.begin(), s.vertices.end());
    const glm::vec3* d_vertices = device_copy(all_vertices.data(), all_vertices.size(), "vertices");
    std::vector<ltc::polygon_light<float>> device_lights;
    std::size_t first = 0;
    for (const light_spec& s : specs) {
        device_lights.push_back(make_light(s, d_vertices + first));
        first += s.vertices.size();
    }
    const ltc::polygon_light<float>* d_lights = device_copy(device_lights.data(), device_lights.size(), "lights");
    const ltc::surface<float>* d_points = device_copy(points.data(), n, "points");
    ltc::shading_result<float>* d_out = nullptr;
    check_cuda(cudaMalloc(&d_out, n * sizeof(ltc::shading_result<float>)), "cudaMalloc out");

    const int block = 128, grid = int((n + block - 1) / block);
    const auto launch = [&](const ltc::polygon_light<float>* lights, int lights_n) {
        shade_gbuffer<<<grid, block>>>(d_points, int(n), lights, lights_n, d_table, ltc::tables::ggx_size, d_out);
        check_cuda(cudaGetLastError(), "shade_gbuffer launch");
    };
    const auto fetch = [&](std::vector<ltc::shading_result<float>>& to) {
        to.resize(n);
        check_cuda(cudaMemcpy(to.data(), d_out, n * sizeof(ltc::shading_result<float>), cudaMemcpyDeviceToHost),
                   "cudaMemcpy out");
    };

    // (a) and (b): each light alone, then the sum over the lights.
    bit_comparison per_light_bits, sum_bits;
    std::vector<ltc::shading_result<float>> device_per_light(n * specs.size());
    std::size_t device_nonfinite = 0;
    std::vector<ltc::shading_result<float>> got;
    for (int l = 0; l < light_count; ++l) {
        launch(d_lights + l, 1);
        fetch(got);
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t k = std::size_t(l) * n + i;
            device_nonfinite += finite(got[i]) ? 0 : 1;
            per_light_bits.add(got[i], host_per_light[k]);
            device_per_light[k] = got[i];
        }
    }
    launch(d_lights, light_count);
    fetch(got);
    for (std::size_t i = 0; i < n; ++i) {
        device_nonfinite += finite(got[i]) ? 0 : 1;
        sum_bits.add(got[i], host_sum[i]);
    }
    std::printf("(a) device against host ltc::shade, bit for bit: %zu of %zu per-light items differ (largest %lld "
                "ulps), %zu of %zu sums differ (largest %lld ulps); zeros of the other sign: %zu and %zu items\n",
                per_light_bits.differing, per_light_bits.items, static_cast<long long>(per_light_bits.max_ulps),
                sum_bits.differing, sum_bits.items, static_cast<long long>(sum_bits.max_ulps),
                per_light_bits.zero_signs, sum_bits.zero_signs);
    print_relative("(b) CPU batch against the device", compare_relative(batch.per_light, device_per_light, n), points);
    if (per_light_bits.differing + sum_bits.differing > 0) {
        std::printf("FAIL: the device's results are not the host's floats\n");
        ok = false;
    }
    if (device_nonfinite > 0) {
        std::printf("FAIL: %zu device results are NaN or infinite\n", device_nonfinite);
        ok = false;
    }

    // Throughput: every light over every point per launch; two untimed launches first (module
    // load, clocks), then gpu_repetitions launches between two events.
    cudaEvent_t start, stop;
    check_cuda(cudaEventCreate(&start), "cudaEventCreate");
    check_cuda(cudaEventCreate(&stop), "cudaEventCreate");
    launch(d_lights, light_count);
    launch(d_lights, light_count);
    check_cuda(cudaEventRecord(start), "cudaEventRecord");
    for (int r = 0; r < gpu_repetitions; ++r) launch(d_lights, light_count);
    check_cuda(cudaEventRecord(stop), "cudaEventRecord");
    check_cuda(cudaEventSynchronize(stop), "cudaEventSynchronize");
    float ms = 0;
    check_cuda(cudaEventElapsedTime(&ms, start, stop), "cudaEventElapsedTime");
    const double gpu_seconds = double(ms) / 1000.0 / gpu_repetitions;
    const double gpu_rate = items / gpu_seconds;
    std::printf("device: %.4g s per launch (%d timed, %d threads per block), %.4g points x lights / s\n", gpu_seconds,
                gpu_repetitions, block, gpu_rate);
    std::printf("device against the CPU batch on one host thread: %.3gx\n", gpu_rate / cpu_rate);

    cudaFree(d_out);
    cudaFree(const_cast<ltc::surface<float>*>(d_points));
    cudaFree(const_cast<ltc::polygon_light<float>*>(d_lights));
    cudaFree(const_cast<glm::vec3*>(d_vertices));
    cudaFree(const_cast<float*>(d_table));
    cudaEventDestroy(start);
    cudaEventDestroy(stop);
    std::printf(ok ? "PASS\n" : "FAIL\n");
    return ok ? 0 : 1;
}
