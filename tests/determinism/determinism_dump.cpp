// The bits of the scalar float integrals on a fixed set of inputs, for comparing builds: the scalar
// paths (everything outside ltc::batch::) must give the same bits with and without LTC_NO_SIMD,
// with and without -march (x86-64-v3, native), under GCC and Clang, when compiled with
// -ffp-contract=off (no contraction of a * b + c into a fused multiply-add, which rounds once
// where the source rounds twice). Two builds agree when their dumps are identical:
//
//   g++ -std=c++17 -O2 -ffp-contract=off -I include tests/determinism/determinism_dump.cpp -o a
//   g++ -std=c++17 -O2 -ffp-contract=off -DLTC_NO_SIMD -I include ... -o b
//   ./a a.txt && ./b b.txt && cmp a.txt b.txt
//
// Writes one line per input (its index, kind and the hexadecimal bit patterns of its results) to
// the file named by argv[1], or to standard output; a summary (counts per kind and of the quads'
// clip masks, a hash of the dump) to standard error.
//
// Inputs (SplitMix64, fixed seed: the same on every machine and standard library):
//   - 120000 quads under GGX-like inverse matrices [a 0 b; 0 c 0; d 0 1] (row-major; a, c > 0,
//     b, d of either sign, all four drawn), some turned about z or mirrored (negative
//     determinant), some the identity: rectangles in front of the shading point (crossing the
//     horizon, wholly above, wholly below), arbitrary and non-convex quads, rectangles scaled
//     by 10^[-12, 12] (the quad path's hand-backs: tiny and huge vertices) and edge cases
//     (vertices on the horizon or within 1e-20 of it, at the origin, an edge through it,
//     repeated vertices, non-finite coordinates);
//   - each quad's clamped-cosine integral: transformed<clamped_cosine<float>>::integrate signed
//     magnitude and one- and two-sided (the float quad path on lanes), the polynomial policy
//     (lanes too), the exact policy (the switch path), and form_factor on the vertices
//     themselves (the quad path from a vertex pointer);
//   - polygons of 3, 5 and 8 vertices (the general path), and solid_angle and
//     clipped_solid_angle of triangles, quads and pentagons.
#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/edge_policy.hpp>
#include <ltc/core/form_factor.hpp>
#include <ltc/core/sidedness.hpp>
#include <ltc/core/solid_angle.hpp>
#include <ltc/core/transformed.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <vector>

namespace {

struct splitmix64 {
    std::uint64_t s;
    std::uint64_t next() {
        std::uint64_t z = (s += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    /// In [0, 1), from the top 53 bits (exact in double on every platform).
    double uniform() { return double(next() >> 11) * 0x1p-53; }
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    unsigned below(unsigned n) { return unsigned(next() % n); }
};

std::uint32_t bits_of(float x) {
    std::uint32_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
}

struct dump {
    std::FILE* out;
    std::uint64_t hash = 0xcbf29ce484222325ull;  // FNV-1a of the values written
    std::size_t values = 0;
    void begin(std::size_t index, const char* kind) { std::fprintf(out, "%zu %s", index, kind); }
    void value(float x) {
        const std::uint32_t b = bits_of(x);
        std::fprintf(out, " %08x", static_cast<unsigned>(b));
        for (int k = 0; k < 4; ++k) hash = (hash ^ ((b >> (8 * k)) & 0xffu)) * 0x100000001b3ull;
        ++values;
    }
    void end() { std::fputc('\n', out); }
};

// GGX-like M^-1 (the layout of the fitted tables), drawn in double and rounded to float once.
glm::mat3 random_matrix(splitmix64& g) {
    const unsigned kind = g.below(10);
    if (kind == 0) return glm::mat3(1.0f);
    const double a = 0.002 + 2.0 * g.uniform(), c = 0.002 + 2.0 * g.uniform();
    const double b = g.uniform(-1.5, 1.5), d = g.uniform(-1.5, 1.5);
    glm::dmat3 m = glm::transpose(glm::dmat3(a, 0, b, 0, c, 0, d, 0, 1));
    if (kind <= 3) {  // the shading frame turned about z
        const double phi = g.uniform(0, 6.283185307179586);
        const glm::dmat3 turn(std::cos(phi), std::sin(phi), 0, -std::sin(phi), std::cos(phi), 0, 0, 0, 1);
        m = m * turn;
    }
    if (kind == 4) m[0] = -m[0];  // mirrored: negative determinant
    return glm::mat3(m);
}

// A rectangle of the given centre, random orientation and size.
void rectangle(splitmix64& g, const glm::dvec3& centre, double scale, glm::vec3* q) {
    const double phi = g.uniform(0, 6.283185307179586), tilt = g.uniform(0, 3.141592653589793);
    const glm::dvec3 ex(std::cos(phi), std::sin(phi), 0);
    const glm::dvec3 ey(-std::sin(phi) * std::cos(tilt), std::cos(phi) * std::cos(tilt), std::sin(tilt));
    const double w = 0.05 + g.uniform(), h = 0.05 + g.uniform();
    const glm::dvec3 p[4] = {centre - w * ex - h * ey, centre + w * ex - h * ey, centre + w * ex + h * ey,
                             centre - w * ex + h * ey};
    for (int k = 0; k < 4; ++k) q[k] = glm::vec3(scale * p[k]);
}

// Draws sequenced one statement each: the order in which a compiler evaluates function arguments
// is unspecified (GCC and Clang differ), and the inputs must not depend on it.
glm::dvec3 random_point(splitmix64& g, double zlo, double zhi) {
    const double x = g.uniform(-1.5, 1.5);
    const double y = g.uniform(-1.5, 1.5);
    const double z = g.uniform(zlo, zhi);
    return glm::dvec3(x, y, z);
}

const char* quad_kind(splitmix64& g, glm::vec3* q) {
    const unsigned kind = g.below(20);
    if (kind < 7) {  // rectangles in front of the shading point, about half crossing the horizon
        rectangle(g, random_point(g, -0.6, 1.2), 1.0, q);
        return "rect";
    }
    if (kind < 9) {  // wholly above or wholly below, mostly
        const glm::dvec3 centre = random_point(g, 1.2, 3.0);
        rectangle(g, g.below(2) ? centre : -centre, 1.0, q);
        return "rect_far";
    }
    if (kind < 12) {  // arbitrary quads: any order, non-convex, self-intersecting
        for (int k = 0; k < 4; ++k) q[k] = glm::vec3(random_point(g, -1.0, 1.0));
        return "any";
    }
    if (kind < 14) {  // tiny to huge
        const glm::dvec3 centre = random_point(g, -0.6, 1.2);
        rectangle(g, centre, std::pow(10.0, g.uniform(-12, 12)), q);
        return "scaled";
    }
    // Edge cases on a rectangle.
    rectangle(g, random_point(g, -0.6, 1.2), 1.0, q);
    const unsigned k = g.below(4), j = (k + 1 + g.below(3)) % 4;
    switch (g.below(10)) {
        case 0: q[k].z = 0.0f; break;                                        // a vertex on the horizon
        case 1: q[k].z = 0.0f, q[(k + 1) % 4].z = 0.0f; break;               // an edge on the horizon
        case 2: q[k].z = 1e-20f, q[(k + 1) % 4].z = -1e-20f; break;          // an edge grazing it
        case 3: q[k].z = g.below(2) ? 1e-30f : -1e-30f; break;               // a vertex within 1e-30
        case 4: q[k] = glm::vec3(0.0f); break;                               // a vertex at the origin
        case 5: q[j] = -q[k] * float(g.uniform(0.1, 10.0)); break;           // a diagonal or edge through it
        case 6: q[j] = q[k]; break;                                          // a repeated vertex
        case 7: q[k] = q[k] * 1e-20f; break;                                 // one tiny vertex
        case 8: q[k].x = std::numeric_limits<float>::infinity(); break;      // not finite
        default: q[k].y = std::numeric_limits<float>::quiet_NaN(); break;
    }
    return "edge_case";
}

}  // namespace

int main(int argc, char** argv) {
    std::FILE* out = argc > 1 ? std::fopen(argv[1], "w") : stdout;
    if (!out) {
        std::perror(argv[1]);
        return 2;
    }
    dump d{out};
    splitmix64 g{0x17c0ffee};
    using cosine = ltc::transformed<ltc::clamped_cosine<float>>;
    using cosine_polynomial = ltc::transformed<ltc::clamped_cosine<float, ltc::edge_policy::polynomial>>;
    using cosine_exact = ltc::transformed<ltc::clamped_cosine<float, ltc::edge_policy::exact>>;
    std::size_t index = 0, masks[17] = {};

    const std::size_t quads = 120000;
    for (std::size_t i = 0; i < quads; ++i, ++index) {
        const glm::mat3 mi = random_matrix(g);
        glm::vec3 q[4];
        const char* kind = quad_kind(g, q);
        unsigned mask = 0;
        bool finite = true;
        for (unsigned k = 0; k < 4; ++k) {
            const glm::vec3 v = mi * q[k];
            mask |= (v.z >= 0.0f ? 1u : 0u) << k;
            finite = finite && std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
        }
        ++masks[finite ? mask : 16u];
        const cosine c = cosine::from_inverse(mi);
        d.begin(index, kind);
        d.value(c.integrate(q, 4));
        d.value(c.integrate(q, 4, ltc::sidedness::two_sided));
        d.value(c.integrate(q, 4, ltc::sidedness::one_sided));
        d.value(c.integrate_signed(q, 4));
        d.value(cosine_polynomial::from_inverse(mi).integrate(q, 4, ltc::sidedness::one_sided));
        d.value(cosine_exact::from_inverse(mi).integrate(q, 4, ltc::sidedness::one_sided));
        d.value(ltc::form_factor<ltc::edge_policy::minimax_rational>(q, 4, ltc::sidedness::one_sided));
        d.value(ltc::form_factor_signed<ltc::edge_policy::polynomial>(q, 4));
        d.end();
    }

    // Polygons of 3, 5 and 8 vertices around a centre (convex or not), the general path.
    const std::size_t polygons = 15000;
    for (const std::size_t n : {std::size_t(3), std::size_t(5), std::size_t(8)}) {
        for (std::size_t i = 0; i < polygons; ++i, ++index) {
            const glm::mat3 mi = random_matrix(g);
            const glm::dvec3 centre = random_point(g, -0.8, 1.5);
            const bool convex = g.below(3) != 0;
            const double r0 = 0.1 + g.uniform();
            glm::vec3 p[8];
            for (std::size_t k = 0; k < n; ++k) {
                const double phi = 6.283185307179586 * (double(k) + (convex ? 0.0 : g.uniform(-0.4, 0.4))) / double(n);
                const double r = convex ? r0 : r0 * g.uniform(0.2, 1.5);
                const double z = g.uniform(-0.5, 0.5);
                p[k] = glm::vec3(centre + r * glm::dvec3(std::cos(phi), std::sin(phi), z));
            }
            const cosine c = cosine::from_inverse(mi);
            d.begin(index, n == 3 ? "tri" : n == 5 ? "penta" : "octa");
            d.value(c.integrate(p, n));
            d.value(c.integrate(p, n, ltc::sidedness::one_sided));
            d.value(cosine_exact::from_inverse(mi).integrate(p, n, ltc::sidedness::two_sided));
            d.value(ltc::form_factor_signed<ltc::edge_policy::minimax_rational>(p, n));
            d.end();
        }
    }

    // Solid angles (unclipped and clipped to the horizon) of triangles, quads and pentagons.
    const std::size_t spherical = 20000;
    for (std::size_t i = 0; i < spherical; ++i, ++index) {
        const std::size_t n = 3 + i % 3;
        glm::vec3 p[5];
        for (std::size_t k = 0; k < n; ++k) p[k] = glm::vec3(random_point(g, -1.0, 1.5));
        d.begin(index, "solid_angle");
        d.value(ltc::solid_angle(p, n));
        d.value(ltc::clipped_solid_angle(p, n));
        d.end();
    }

    if (out != stdout) std::fclose(out);
    std::fprintf(stderr, "determinism_dump: %zu inputs, %zu values, hash %016llx\n", index, d.values,
                 static_cast<unsigned long long>(d.hash));
    std::fprintf(stderr, "quad clip masks (vertices above the horizon; 16: not finite):");
    for (int m = 0; m <= 16; ++m) std::fprintf(stderr, " %d:%zu", m, masks[m]);
    std::fprintf(stderr, "\n");
    return 0;
}
