// ltc/core/transformed.hpp -- Linearly Transformed Spherical Distributions (paper section 3,
// supplement section 2): D(w) = D_o(M^-1 w / |M^-1 w|) |M^-1| / |M^-1 w|^3   (eq. 1).
//
//   ltc::transformed<ltc::clamped_cosine<float>> d = ...::from_inverse(m_inv);
//   float e = d.integrate(vertices, n);   // eq. (3): D_o's closed form over M^-1 P, two-sided
//
// GLM matrices are column-major: the paper's (row-major) M = [a 0 b; 0 c 0; d 0 1] is
// glm::transpose(glm::mat3(a, 0, b, 0, c, 0, d, 0, 1)), i.e. glm::mat3 M; M[col][row].
#pragma once

#include <ltc/config.hpp>
#include <ltc/detail/math.hpp>
#include <ltc/core/sidedness.hpp>
#include <ltc/core/detail/defined_later.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>

LTC_NAMESPACE_BEGIN

/// Thrown by the checked factories of transformed<> for a singular or non-finite matrix; a
/// std::invalid_argument, defined in ltc/core/invalid_transform.hpp, which a caller of checked()
/// or checked_from_inverse() includes (ltc/ltc.hpp does): <stdexcept> alone is larger to parse
/// than the rest of this header, which the cheap factories never need.
class invalid_transform;

namespace detail {

/// a x b with each component by difference_of_products (one rounding error each).
template <typename T>
LTC_HOST_DEVICE inline glm::vec<3, T> accurate_cross(const glm::vec<3, T>& a, const glm::vec<3, T>& b) {
    return glm::vec<3, T>(difference_of_products(a.y, b.z, a.z, b.y),
                          difference_of_products(a.z, b.x, a.x, b.z),
                          difference_of_products(a.x, b.y, a.y, b.x));
}

/// Inverse and determinant of a 3x3 matrix through the cross products of its columns:
/// det = c0 . (c1 x c2) and the rows of the inverse are (c1 x c2, c2 x c0, c0 x c1) / det.
/// The checked factories use this accurate form (each cofactor with one rounding error).
template <typename T>
struct inverse_result {
    glm::mat<3, 3, T> inverse;
    T determinant;
};

template <typename T>
LTC_HOST_DEVICE inline inverse_result<T> accurate_inverse(const glm::mat<3, 3, T>& m) {
    const glm::vec<3, T> r0 = accurate_cross(m[1], m[2]);
    const glm::vec<3, T> r1 = accurate_cross(m[2], m[0]);
    const glm::vec<3, T> r2 = accurate_cross(m[0], m[1]);
    const T det = glm::dot(m[0], r0);
    return {glm::transpose(glm::mat<3, 3, T>(r0, r1, r2)) / det, det};
}

/// The same with plain cross products: what the cheap constructors use in inner loops, where
/// std::fma may be a library call (no -mfma) that would cost more than the integral itself.
template <typename T>
LTC_HOST_DEVICE inline inverse_result<T> fast_inverse(const glm::mat<3, 3, T>& m) {
    const glm::vec<3, T> r0 = glm::cross(m[1], m[2]);
    const glm::vec<3, T> r1 = glm::cross(m[2], m[0]);
    const glm::vec<3, T> r2 = glm::cross(m[0], m[1]);
    const T det = glm::dot(m[0], r0);
    return {glm::transpose(glm::mat<3, 3, T>(r0, r1, r2)) * (T(1) / det), det};
}

/// The determinant of a finite M^-1 whose determinant overflows (entries near the largest finite
/// value): infinite, with the sign of the determinant of M^-1 rescaled by a power of two (exact),
/// which is what the integrals use of it. Out of line: the rare slow path of from_inverse.
template <typename T>
LTC_HOST_DEVICE LTC_NOINLINE T overflowed_determinant(const glm::mat<3, 3, T>& m_inv) {
    const glm::mat<3, 3, T> s = rescale_pow2(m_inv);
    const T det = glm::dot(s[0], glm::cross(s[1], s[2]));
    return det < T(0) ? -T(INFINITY) : T(INFINITY);  // INFINITY: usable in CUDA device code
}

/// The unit directions of M^-1 p_i, computed on the fly. Where M^-1 p overflows (huge finite
/// vertices, or entries of M^-1 near the largest finite value) p and M^-1 are first rescaled by
/// powers of two (exactly): the integrals only see directions.
template <typename T>
struct transformed_vertices {
    glm::mat<3, 3, T> m_inv;  // a copy: a reference would keep the owning transformed<> in memory
    const glm::vec<3, T>* v;
    LTC_HOST_DEVICE LTC_INLINE glm::vec<3, T> operator()(std::size_t i) const {
        const glm::vec<3, T> p = v[i];
        const glm::vec<3, T> q = m_inv * p;
        const T l2 = glm::dot(q, q);
        if (l2 > T(1e-30) && l2 < T(1e30)) return q * (T(1) / std::sqrt(l2));
        return rescaled(m_inv, p);
    }
    /// M^-1 p_i before normalization (for the quad path, ltc/core/quad_path.hpp).
    LTC_HOST_DEVICE LTC_INLINE glm::vec<3, T> raw(std::size_t i) const { return m_inv * v[i]; }
    static LTC_HOST_DEVICE LTC_NOINLINE glm::vec<3, T> rescaled(const glm::mat<3, 3, T>& m, const glm::vec<3, T>& p) {
        // Both by exact powers of two: with entries of M^-1 near the largest finite value,
        // M^-1 p overflows even for a p of unit scale.
        return safe_normalize(rescale_pow2(m) * rescale_pow2(p));
    }
};

}  // namespace detail

/// The linearly transformed distribution D of eq. (1) with original distribution Dist (one of
/// uniform_sphere, uniform_hemisphere, clamped_cosine, squared_clamped_cosine, or any type with
/// the same static members).
template <typename Dist>
class transformed {
  public:
    using distribution = Dist;
    using scalar = typename Dist::scalar;
    using T = scalar;
    using vec2 = glm::vec<2, T>;
    using vec3 = glm::vec<3, T>;
    using mat3 = glm::mat<3, 3, T>;

    /// D from M. Precondition: M is finite and invertible (not checked, so that this stays cheap
    /// in inner loops; use checked() for untrusted input). The distribution is invariant to the
    /// scale of M, so any non-zero multiple of M gives the same D.
    LTC_HOST_DEVICE explicit transformed(const mat3& M) {
        const auto inv = detail::fast_inverse(M);
        set(inv.inverse, T(1) / inv.determinant);
    }

    /// D from M^-1 directly, as renderers store it. Same precondition as the constructor.
    /// Costs one determinant: M itself is only formed by sample() and matrix().
    LTC_HOST_DEVICE static transformed from_inverse(const mat3& m_inv) {
        const T det = glm::dot(m_inv[0], glm::cross(m_inv[1], m_inv[2]));
        return transformed(m_inv, std::isfinite(det) ? det : detail::overflowed_determinant(m_inv));
    }

    /// The same M (the same M^-1 and determinant, bit for bit) over another original
    /// distribution of the same scalar type: e.g. the Jacobian of an LTC whose edge policy differs.
    template <typename OtherDist>
    LTC_HOST_DEVICE explicit transformed(const transformed<OtherDist>& other) {
        static_assert(std::is_same<typename OtherDist::scalar, T>::value, "ltc::transformed: the same scalar type");
        set(other.inverse_matrix(), other.inverse_determinant());
    }

    /// Like the constructor, but throws ltc::invalid_transform when M has a non-finite entry or
    /// is numerically singular: |det M| <= sqrt(epsilon) |c0| |c1| |c2| (c_i its columns; the
    /// ratio is 1 for orthogonal and for diagonal matrices, however anisotropic, 0 for singular
    /// ones, and invariant to scale). Below sqrt(epsilon), M^-1 and the round trip
    /// M^-1 (M w) keep fewer than half of T's digits, and sample() could no longer promise
    /// pdf > 0 (the fuzzer found such matrices near epsilon). M is first
    /// divided by its largest entry (D does not change) so that no determinant under- or
    /// overflows; matrix() returns that rescaled M.
    static transformed checked(const mat3& M) {
        const mat3 m = rescaled(M, "M");
        const auto inv = detail::accurate_inverse(m);
        require_invertible(m, inv, "M");
        return transformed(inv.inverse, T(1) / inv.determinant);
    }

    /// Like from_inverse(), with the checks of checked() applied to M^-1.
    static transformed checked_from_inverse(const mat3& m_inv) {
        const mat3 mi = rescaled(m_inv, "M^-1");
        const auto inv = detail::accurate_inverse(mi);
        require_invertible(mi, inv, "M^-1");
        return transformed(mi, inv.determinant);
    }

    /// D(w) of eq. (1) at the unit direction w (0 for w = 0).
    LTC_HOST_DEVICE T eval(const vec3& w) const {
        const vec3 wo = m_inv_ * w;
        const T l = glm::length(wo);
        if (!(l > T(0))) return T(0);
        return Dist::eval(wo / l) * (abs_det_inv_ / (l * l * l));
    }

    /// Jacobian d w_o / d w = |M^-1| / |M^-1 w|^3 of the map w -> w_o = M^-1 w / |M^-1 w|
    /// (eq. 1; derived in appendix A of the paper), at the unit direction w.
    LTC_HOST_DEVICE T jacobian(const vec3& w) const {
        const T l = glm::length(m_inv_ * w);
        return l > T(0) ? abs_det_inv_ / (l * l * l) : T(0);
    }

    /// D is normalized (supplement 2.2), so it is its own pdf.
    LTC_HOST_DEVICE T pdf(const vec3& w) const { return eval(w); }

    /// Algorithm 1: w_o ~ D_o, then w = M w_o / |M w_o| has pdf D(w).
    /// Guarantee: pdf(sample(u)) > 0 for every u in [0, 1)^2. A w_o within ~cond(M) epsilon of
    /// D_o's horizon (u.x -> 1 for the uniform hemisphere) can be carried across it by the
    /// rounding of M w_o and M^-1 w, where pdf() is 0; such a sample is lifted off the horizon
    /// by the smallest power-of-16 multiple of epsilon that brings it back (a bias confined to a
    /// set of measure ~cond(M) epsilon, next to a boundary where the density is finite); for
    /// numerically degenerate M, where no lift helps, the sample is the image of the pole.
    LTC_HOST_DEVICE vec3 sample(const vec2& u) const {
        // Directions only: M w_o / |M w_o| needs M up to a positive factor, and the adjugate of
        // M^-1 times the sign of |M^-1| is such a multiple (no division).
        const mat3 m = adjugate_times_sign();
        const vec3 wo = Dist::sample(u);
        vec3 w = detail::safe_normalize(m * wo);
        T lift = detail::epsilon<T>();
        const auto in_support = [&](const vec3& x) { return Dist::eval(detail::safe_normalize(m_inv_ * x)) > T(0); };
        for (int i = 0; i < 16 && !in_support(w); ++i, lift *= T(16))
            w = detail::safe_normalize(m * detail::safe_normalize(wo + vec3(T(0), T(0), lift)));
        // Columns of M of wildly different scales (|c2| / |c0| ~ epsilon, found by fuzzing) drown
        // w_o.z in the rounding of M w_o whatever the lift: fall back to the image of the pole,
        // M e_z, where every original distribution of the library is positive.
        if (!in_support(w)) w = detail::safe_normalize(m[2]);
        return w;
    }

    /// Signed integral of D over the polygon: eq. (3), D_o's closed form over M^-1 P, times the
    /// sign of |M^-1| so that the sign refers to P's own orientation (see polygon.hpp).
    LTC_HOST_DEVICE LTC_INLINE T integrate_signed(const vec3* vertices, std::size_t n) const {
        const T s = Dist::signed_integral(detail::transformed_vertices<T>{m_inv_, vertices}, n);
        return det_inv_ < T(0) ? -s : s;
    }

    /// Integral of D over the spherical polygon subtended by vertices[0..n), as seen by a one-sided
    /// (max(0, signed)) or two-sided (|signed|) emitter (ltc/core/sidedness.hpp).
    /// The default, decided here once: two_sided. integrate(v, n) is the integral of D over the
    /// polygon whatever its winding, the quantity of eq. (3); the original distributions'
    /// integrate() and core's other integrals (integrate_disk, ...) default alike. Shading takes no
    /// default (ltc::shade: a light is one_sided or two_sided by construction): there a wrong guess
    /// lights the back of a light. One function, so that integrate(v, n) is integrate(v, n,
    /// two_sided): the same inlined path (the quad path for n = 4) and the same bits.
    LTC_HOST_DEVICE LTC_INLINE T integrate(const vec3* vertices, std::size_t n,
                                           sidedness s = sidedness::two_sided) const {
        // Two-sided: |integral| does not need the sign of |M^-1| (nor, when the compiler sees s, its
        // determinant).
        const T s_o = Dist::signed_integral(detail::transformed_vertices<T>{m_inv_, vertices}, n);
        return s == sidedness::two_sided ? std::abs(s_o) : apply_sidedness(det_inv_ < T(0) ? -s_o : s_o, s);
    }

    /// M, recomputed from the stored M^-1 (equal to the M given to the constructor up to rounding).
    LTC_HOST_DEVICE mat3 matrix() const { return adjugate_times_sign() * (T(1) / std::abs(det_inv_)); }
    LTC_HOST_DEVICE const mat3& inverse_matrix() const { return m_inv_; }
    /// |M^-1|, the determinant of the inverse matrix.
    LTC_HOST_DEVICE T inverse_determinant() const { return det_inv_; }

  private:
    LTC_HOST_DEVICE transformed(const mat3& m_inv, T det_inv) { set(m_inv, det_inv); }

    LTC_HOST_DEVICE void set(const mat3& m_inv, T det_inv) {
        m_inv_ = m_inv;
        det_inv_ = det_inv;
        abs_det_inv_ = std::abs(det_inv);
    }

    // Failures go through invalid_transform::raise (ltc/core/invalid_transform.hpp), which formats
    // the message: named through T, the class is needed only where these are instantiated.
    using error = typename detail::defined_later<invalid_transform, T>::type;

    static mat3 rescaled(const mat3& m, const char* name) {
        T largest(0);
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) {
                if (!std::isfinite(m[c][r])) error::raise(error::non_finite, name, 0.0, 0.0);
                largest = glm::max(largest, std::abs(m[c][r]));
            }
        if (!(largest > T(0))) error::raise(error::zero, name, 0.0, 0.0);
        return m / largest;
    }

    static void require_invertible(const mat3& m, const detail::inverse_result<T>& inv, const char* name) {
        const T hadamard = glm::length(m[0]) * glm::length(m[1]) * glm::length(m[2]);
        const T ratio = std::abs(inv.determinant) / hadamard;
        bool finite = std::isfinite(inv.determinant);
        for (int c = 0; c < 3; ++c) finite = finite && detail::is_finite(inv.inverse[c]);
        const T threshold = std::sqrt(std::numeric_limits<T>::epsilon());
        if (!(ratio > threshold) || !finite) error::raise(error::singular, name, double(ratio), double(threshold));
    }

    /// adj(M^-1) sign(|M^-1|) = M |det M^-1|: a positive multiple of M.
    LTC_HOST_DEVICE mat3 adjugate_times_sign() const {
        const mat3 adj = glm::transpose(mat3(glm::cross(m_inv_[1], m_inv_[2]), glm::cross(m_inv_[2], m_inv_[0]),
                                             glm::cross(m_inv_[0], m_inv_[1])));
        return det_inv_ < T(0) ? -adj : adj;
    }

    mat3 m_inv_{T(1)};
    T det_inv_{1};
    T abs_det_inv_{1};
};

LTC_NAMESPACE_END
