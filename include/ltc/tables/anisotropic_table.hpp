// ltc/tables/anisotropic_table.hpp -- the layout of a table of LTCs of an anisotropic BRDF over
// (alpha_x, alpha_y, theta_v, phi_v) and its quadrilinear lookup (anisotropic_table), after Kt,
// Heitz, Dupuy and Narayanan 2022, "Bringing Linearly Transformed Cosines to Anisotropic GGX"
// (section 4: the 4D table and its symmetries).
//
//   const ltc::anisotropic_table table(data, size);           // a view over the generated floats
//   ltc::ltc_coefficients<float> c = table.fetch(cos_theta_v, phi_v, alpha_x, alpha_y);
//   float e = c.magnitude * ltc::transformed<ltc::clamped_cosine<float>>::from_inverse(c.m_inv)
//                               .integrate(polygon, n);
#pragma once

#include <ltc/config.hpp>

#include <ltc/detail/math.hpp>
#include <ltc/tables/ltc_table.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>
#include <limits>

// Frame: N = +z, tangent (the direction of alpha_x) = +x, V = (sin t cos p, sin t sin p, cos t)
// with t = theta_v and p = phi_v. The BRDF (anisotropic GGX, ltc::brdf::ggx_anisotropic) has
// the symmetries used to store a quarter of the 4D domain:
//   phi -> -phi          mirrors y: m_inv -> Fy m_inv Fy,  Fy = diag(1, -1, 1)
//   phi -> pi - phi      mirrors x: m_inv -> Fx m_inv Fx,  Fx = diag(-1, 1, 1)
//   ax <-> ay with phi -> pi/2 - phi swaps x and y: m_inv -> S m_inv S (S swaps rows/columns 0, 1)
// (F m_inv F instead of F m_inv keeps det m_inv > 0: the clamped cosine is invariant under F).
//
// Grid (the published 8^4 table's, so that both compare node for node): node (i, j, k, l) of an
// n^4 grid is at alpha_x = max(i / (n-1), alpha_min), alpha_y = max(j / (n-1), alpha_min),
// theta_v = k / (n-1) * theta_max (theta_max = 0.9999 pi/2) and phi_v = l / (n-1) * pi/2. Only
// the nodes with i >= j are stored (alpha pair p = i (i+1) / 2 + j, n (n+1) / 2 pairs); node
// (i, j, k, l) with i < j is S node(j, i, k, n-1-l) S.
//
// Channels (11 floats per node): M[c][r] at 3 c + r (GLM column-major), the LTC matrix itself
// (not its inverse) in the canonical form of ltc/fitting/anisotropic_parameters.hpp (M^-1 with
// det > 0 and a symmetric upper-left 2x2 block of the largest trace; M scaled to |M e_z| = 1);
// 9: magnitude (directional albedo); 10: fresnel. Data: data[((p * n + k) * n + l) * 11 + channel].
//
// Lookup: alpha clamped to [0, 1], cos theta_v to [0, 1] (NaN counts as 0), phi_v any real
// (reduced mod 2 pi; NaN and Inf count as 0), then quadrilinear interpolation of all 11 channels
// in the stored quadrant phi in [0, pi/2] (M, as Kt et al.'s shader interpolates it), the mirrors
// above, and m_inv = M^-1 (adjugate / det). Finite for any input: an interpolated M whose
// determinant is not positive and finite (never between the shipped table's nodes) gives
// m_inv = I, the clamped cosine.

LTC_NAMESPACE_BEGIN

/// The grid and channel layout of an anisotropic table (the file comment).
namespace anisotropic_layout {
inline constexpr int channels = 11;
inline constexpr int magnitude = 9;
inline constexpr int fresnel = 10;
inline constexpr double alpha_min = 1e-4;
/// 0.9999 pi / 2: the last theta node (V.z = 0 leaves rho undefined).
inline constexpr double theta_max = 0.9999 * 1.5707963267948966;

/// Index of the stored alpha pair (i, j), i >= j.
inline constexpr std::size_t pair_index(int i, int j) {
    return static_cast<std::size_t>(i) * static_cast<std::size_t>(i + 1) / 2 + static_cast<std::size_t>(j);
}
/// Floats in a table of size n.
inline constexpr std::size_t float_count(int n) {
    return pair_index(n, 0) * static_cast<std::size_t>(n) * static_cast<std::size_t>(n) * channels;
}
}  // namespace anisotropic_layout

namespace detail {

/// Swaps x and y of m (S m S, S the permutation of rows/columns 0 and 1).
template <typename T>
LTC_HOST_DEVICE inline glm::mat<3, 3, T> swap_xy(const glm::mat<3, 3, T>& m) {
    glm::mat<3, 3, T> r;
    const int s[3] = {1, 0, 2};
    for (int c = 0; c < 3; ++c)
        for (int w = 0; w < 3; ++w) r[c][w] = m[s[c]][s[w]];
    return r;
}

/// F m F for F = diag(fx ? -1 : 1, fy ? -1 : 1, 1): negates the elements that couple a mirrored
/// axis to another.
template <typename T>
LTC_HOST_DEVICE inline glm::mat<3, 3, T> mirror(const glm::mat<3, 3, T>& m, bool fx, bool fy) {
    const T f[3] = {fx ? T(-1) : T(1), fy ? T(-1) : T(1), T(1)};
    glm::mat<3, 3, T> r;
    for (int c = 0; c < 3; ++c)
        for (int w = 0; w < 3; ++w) r[c][w] = m[c][w] * (f[c] * f[w]);
    return r;
}

}  // namespace detail

/// A non-owning view of an anisotropic table of size n (n^4 virtual nodes, the layout of the
/// file comment), with its quadrilinear lookup.
class anisotropic_table {
  public:
    static constexpr int channels = anisotropic_layout::channels;

    constexpr anisotropic_table(const float* data, int size) : data_(data), size_(size) {}

    constexpr const float* data() const { return data_; }
    constexpr int size() const { return size_; }

    /// The stored float of channel c at node (i, j, k, l), i >= j.
    constexpr float stored(int i, int j, int k, int l, int c) const { return data_[offset(i, j, k, l) + std::size_t(c)]; }

    /// The 11 channels of any node (i, j, k, l): stored, or by the swap symmetry for i < j.
    template <typename T>
    void node(int i, int j, int k, int l, T* out) const {
        if (i >= j) {
            for (int c = 0; c < channels; ++c) out[c] = T(stored(i, j, k, l, c));
            return;
        }
        const int s[3] = {1, 0, 2};
        for (int c = 0; c < 3; ++c)
            for (int w = 0; w < 3; ++w) out[3 * c + w] = T(stored(j, i, k, size_ - 1 - l, 3 * s[c] + s[w]));
        out[anisotropic_layout::magnitude] = T(stored(j, i, k, size_ - 1 - l, anisotropic_layout::magnitude));
        out[anisotropic_layout::fresnel] = T(stored(j, i, k, size_ - 1 - l, anisotropic_layout::fresnel));
    }

    /// The coefficients at node (i, j, k, l).
    template <typename T>
    ltc_coefficients<T> node(int i, int j, int k, int l) const {
        T v[channels];
        node(i, j, k, l, v);
        return coefficients(v);
    }

    /// The LTC coefficients for the view (cos theta_v, phi_v) and the roughness (alpha_x,
    /// alpha_y): clamped as the file comment says, M interpolated quadrilinearly in the stored
    /// quadrant, mirrored into phi_v's quadrant and inverted. At a node, m_inv is the inverse of
    /// the node's M (node()) and magnitude and fresnel are the stored floats.
    template <typename T>
    ltc_coefficients<T> fetch(T cos_theta_v, T phi_v, T alpha_x, T alpha_y) const {
        const T n1 = T(size_ > 1 ? size_ - 1 : 1);
        const T eps = std::numeric_limits<T>::epsilon();
        const T c = detail::saturate(cos_theta_v);
        const T theta = std::atan2(std::sqrt((T(1) - c) * (T(1) + c)), c);
        const T st = detail::saturate(theta / T(anisotropic_layout::theta_max)) * n1;
        // phi mod 2 pi in [0, 2 pi), then into [0, pi/2] by the mirrors.
        const T two_pi = T(2) * pi<T>();
        // fmod(p, 2 pi) is p itself for |p| < 2 pi (view_azimuth's range): skip the call there.
        T p = phi_v > -two_pi && phi_v < two_pi ? phi_v : std::isfinite(phi_v) ? std::fmod(phi_v, two_pi) : T(0);
        if (p < T(0)) p += two_pi;
        const bool fy = p > pi<T>();
        if (fy) p = two_pi - p;
        const bool fx = p > T(0.5) * pi<T>();
        if (fx) p = pi<T>() - p;
        const T sp = detail::saturate(p / (T(0.5) * pi<T>())) * n1;
        const T sx = detail::saturate(alpha_x) * n1;
        const T sy = detail::saturate(alpha_y) * n1;
        int i0[4];
        T f[4];
        const T s[4] = {sx, sy, st, sp};
        // Snap tolerances: alpha and phi are known to a few eps; theta = acos(cos theta_v) only to
        // eps / sin theta, i.e. (n-1) eps / (theta_max sin theta) node units.
        const T g = n1 / T(anisotropic_layout::theta_max);
        T tol[4];
        for (int d = 0; d < 4; ++d) tol[d] = T(8) * eps * (s[d] > T(1) ? s[d] : T(1));
        tol[2] = T(4) * eps * (st + g * g / (st > T(1) ? st : T(1)) + g);
        for (int d = 0; d < 4; ++d) detail::axis_position(s[d], size_, tol[d], i0[d], f[d]);
        // The 16 corners' weights are products of the axes' (1 - f, f); the sum of weight times
        // node is quadrilinear interpolation (at a node, f = 0 on every axis: the node itself).
        // A node with i < j is read by the swap symmetry (node()): its mirrored phi node, and M's
        // channels permuted as S M S.
        static constexpr int swapped[channels] = {4, 3, 5, 1, 0, 2, 7, 6, 8, 9, 10};
        const int last = size_ > 1 ? 1 : 0;
        T w[4][2];
        for (int d = 0; d < 4; ++d) w[d][0] = T(1) - f[d], w[d][1] = f[d];
        T acc[channels] = {};
        for (int bx = 0; bx <= last; ++bx)
            for (int by = 0; by <= last; ++by) {
                const int i = i0[0] + bx, j = i0[1] + by;
                const bool swap = i < j;
                const T wxy = w[0][bx] * w[1][by];
                const float* pair = data_ + (swap ? offset(j, i, 0, 0) : offset(i, j, 0, 0));
                for (int bt = 0; bt <= last; ++bt)
                    for (int bp = 0; bp <= last; ++bp) {
                        const int k = i0[2] + bt, l = i0[3] + bp;
                        const T wb = wxy * w[2][bt] * w[3][bp];
                        const float* v = pair + (std::size_t(k) * std::size_t(size_) +
                                                 std::size_t(swap ? size_ - 1 - l : l)) * channels;
                        if (!swap)
                            for (int ch = 0; ch < channels; ++ch) acc[ch] += wb * T(v[ch]);
                        else
                            for (int ch = 0; ch < channels; ++ch) acc[ch] += wb * T(v[swapped[ch]]);
                    }
            }
        ltc_coefficients<T> r = coefficients(acc);
        r.m_inv = detail::mirror(r.m_inv, fx, fy);
        return r;
    }

    /// The stored (canonical) M of node (i, j, k, l), by the swap symmetry for i < j.
    template <typename T>
    glm::mat<3, 3, T> matrix(int i, int j, int k, int l) const {
        T v[channels];
        node(i, j, k, l, v);
        glm::mat<3, 3, T> M;
        for (int c = 0; c < 3; ++c)
            for (int w = 0; w < 3; ++w) M[c][w] = v[3 * c + w];
        return M;
    }

  private:
    /// The index of channel 0 of node (i, j, k, l), i >= j.
    constexpr std::size_t offset(int i, int j, int k, int l) const {
        return ((anisotropic_layout::pair_index(i, j) * std::size_t(size_) + std::size_t(k)) * std::size_t(size_) +
                std::size_t(l)) *
               channels;
    }

    /// m_inv = M^-1 from the channels (adjugate: rows are cross products of M's columns).
    template <typename T>
    static ltc_coefficients<T> coefficients(const T* v) {
        using vec3 = glm::vec<3, T>;
        const vec3 c0(v[0], v[1], v[2]), c1(v[3], v[4], v[5]), c2(v[6], v[7], v[8]);
        const vec3 r0 = glm::cross(c1, c2), r1 = glm::cross(c2, c0), r2 = glm::cross(c0, c1);
        const T det = glm::dot(c0, r0);
        ltc_coefficients<T> r;  // m_inv = I unless det is positive and finite
        if (det > T(0) && det <= std::numeric_limits<T>::max()) {
            const T inv = T(1) / det;
            const glm::mat<3, 3, T> m = glm::transpose(glm::mat<3, 3, T>(r0 * inv, r1 * inv, r2 * inv));
            bool finite = true;
            for (int c = 0; c < 3; ++c)
                for (int w = 0; w < 3; ++w) finite = finite && std::isfinite(m[c][w]);
            if (finite) r.m_inv = m;
        }
        r.magnitude = v[anisotropic_layout::magnitude];
        r.fresnel = v[anisotropic_layout::fresnel];
        return r;
    }

    const float* data_;
    int size_;
};

LTC_NAMESPACE_END
