// The scalar paths' outputs over fixed random inputs, as raw bits: every build of this file (with
// and without LTC_NO_SIMD, without forced inlining, with -march=x86-64-v3, with another compiler)
// must write the same bytes (tests/determinism/compare.cmake). Covers the float and double
// integrals of core/ (quads on their fast path, n-gons, one- and two-sided, every symmetric edge
// policy, solid angles, lines, disks) and the scalar shading of every light shape with each of the three GGX tables.
//
//   determinism_dump <file>      exit 0; 77 where built for x86-64-v3 and the CPU lacks it
#include <ltc/ltc.hpp>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <vector>

namespace {

// SplitMix64 (Steele, Lea, Flood 2014), local so that the dump depends on nothing else.
struct splitmix64 {
    std::uint64_t s;
    std::uint64_t next() {
        std::uint64_t z = (s += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    double uniform() { return double(next() >> 11) * 0x1.0p-53; }
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
};

struct dump {
    std::vector<unsigned char> bytes;
    template <typename T>
    void put(T x) {
        unsigned char b[sizeof(T)];
        std::memcpy(b, &x, sizeof(T));
        bytes.insert(bytes.end(), b, b + sizeof(T));
    }
    template <typename T>
    void put(const glm::vec<3, T>& v) {
        put(v.x), put(v.y), put(v.z);
    }
    template <typename T>
    void put(const ltc::polygon_light_result<T>& r) {
        put(r.specular), put(r.diffuse);
    }
};

template <typename T>
glm::vec<3, T> point(splitmix64& g, double lo, double hi) {
    const T x = T(g.uniform(lo, hi));
    const T y = T(g.uniform(lo, hi));
    const T z = T(g.uniform(lo, hi));
    return {x, y, z};
}

/// A GGX-like inverse LTC matrix (the tables' shape, m_inv[1][1] = 1) with a random rotation about z.
template <typename T>
glm::mat<3, 3, T> ltc_like(splitmix64& g) {
    glm::mat<3, 3, T> m(T(1));
    m[0][0] = T(g.uniform(0.05, 4.0));
    m[0][2] = T(g.uniform(-1.0, 1.0));
    m[2][0] = T(g.uniform(-2.0, 2.0));
    m[2][2] = T(g.uniform(0.05, 4.0));
    const T phi = T(g.uniform(0.0, 6.283185307179586));
    glm::mat<3, 3, T> r(T(1));
    r[0][0] = std::cos(phi), r[0][1] = std::sin(phi), r[1][0] = -std::sin(phi), r[1][1] = std::cos(phi);
    return m * r;
}

template <typename T, typename Policy>
void integrals(dump& out, splitmix64& g, int count) {
    using D = ltc::transformed<ltc::clamped_cosine<T, Policy>>;
    for (int i = 0; i < count; ++i) {
        const D d = D::from_inverse(ltc_like<T>(g));
        // A quad around a random centre, below, across and above the horizon; 3 to 8 vertices.
        const glm::vec<3, T> c = point<T>(g, -2.0, 2.0), a = point<T>(g, -1.0, 1.0), b = point<T>(g, -1.0, 1.0);
        const glm::vec<3, T> quad[4] = {c - a - b, c + a - b, c + a + b, c - a + b};
        out.put(d.integrate(quad, 4));
        out.put(d.integrate(quad, 4, ltc::sidedness::one_sided));
        out.put(d.integrate(quad, 4, ltc::sidedness::two_sided));
        glm::vec<3, T> ngon[8];
        const std::size_t n = 3 + std::size_t(g.next() % 6);
        for (std::size_t k = 0; k < n; ++k) {
            const T t = T(6.283185307179586 * double(k) / double(n));
            ngon[k] = c + a * std::cos(t) + b * std::sin(t);
        }
        out.put(d.integrate(ngon, n));
        out.put(d.integrate(ngon, n, ltc::sidedness::one_sided));
        out.put(ltc::solid_angle(ngon, n));
        out.put(d.eval(glm::normalize(c)));
    }
}

template <typename T>
void shading(dump& out, splitmix64& g, int count) {
    using vec3 = glm::vec<3, T>;
    for (int i = 0; i < count; ++i) {
        const vec3 P = point<T>(g, -1.0, 1.0) * T(0.2);
        // One draw per statement: the order of evaluation of arguments differs between compilers.
        const T nx = T(g.uniform(-0.5, 0.5)), ny = T(g.uniform(-0.5, 0.5));
        const T vx = T(g.uniform(-1.0, 1.0)), vy = T(g.uniform(-1.0, 1.0)), vz = T(g.uniform(0.0, 1.0));
        const vec3 N = glm::normalize(vec3(nx, ny, T(1)));
        const vec3 V = glm::normalize(vec3(vx, vy, vz));
        const T roughness = T(g.uniform(0.0, 1.0));
        const vec3 F0(T(0.04), T(0.5), T(0.9)), albedo(T(0.8), T(0.5), T(0.2)), L(T(1), T(2), T(3));
        const vec3 c = point<T>(g, -2.0, 2.0) + vec3(T(0), T(0), T(2)), a = point<T>(g, -1.0, 1.0),
                   b = point<T>(g, -1.0, 1.0);
        const vec3 quad[4] = {c - a - b, c + a - b, c + a + b, c - a + b};
        for (const auto side : {ltc::sidedness::one_sided, ltc::sidedness::two_sided}) {
            out.put(ltc::shade_polygon_light(P, N, V, roughness, F0, albedo, L, quad, 4, side));
            out.put(ltc::shade_polygon_light_one_lobe(P, N, V, roughness, F0, albedo, L, quad, 4, side));
            out.put(ltc::shade_polygon_light_two_lobe(P, N, V, roughness, F0, albedo, L, quad, 4, side));
            out.put(ltc::shade_disk_light(P, N, V, roughness, F0, albedo, L, c, glm::normalize(glm::cross(a, b)),
                                          T(0.7), side));
        }
        out.put(ltc::shade_sphere_light(P, N, V, roughness, F0, albedo, L, c, T(0.5)));
        out.put(ltc::shade_line_light(P, N, V, roughness, F0, albedo, L, c - a, c + a, T(0.01)));
        out.put(ltc::shade_tube_light(P, N, V, roughness, F0, albedo, L, c - a, c + a, T(0.2)));
    }
}

}  // namespace

int main(int argc, char** argv) {
#if defined(LTC_DUMP_NEEDS_X86_64_V3)
    __builtin_cpu_init();
    if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma") || !__builtin_cpu_supports("bmi2")) {
        std::printf("this CPU lacks x86-64-v3\n");
        return 77;
    }
#endif
    if (argc != 2) {
        std::fprintf(stderr, "usage: determinism_dump <output file>\n");
        return 2;
    }
    dump out;
    splitmix64 g{20261201};
    integrals<float, ltc::edge_policy::minimax_rational>(out, g, 20000);
    integrals<float, ltc::edge_policy::polynomial>(out, g, 5000);
    integrals<float, ltc::edge_policy::exact>(out, g, 5000);
    integrals<double, ltc::edge_policy::exact>(out, g, 5000);
    integrals<double, ltc::edge_policy::polynomial>(out, g, 5000);
    shading<float>(out, g, 3000);
    shading<double>(out, g, 1000);
    std::FILE* f = std::fopen(argv[1], "wb");
    if (!f || std::fwrite(out.bytes.data(), 1, out.bytes.size(), f) != out.bytes.size() || std::fclose(f) != 0) {
        std::fprintf(stderr, "determinism_dump: cannot write %s\n", argv[1]);
        return 1;
    }
    std::printf("%zu values\n", out.bytes.size());
    return 0;
}
