// ltc/tables/ltc_table.hpp -- precomputed LTC tables and their bilinear lookup (paper section 4,
// "Representation and Storage"; Hill and Heitz 2016 for the Fresnel term).
//
//   const ltc::ltc_table table(data, width, height);     // a view over width*height*6 floats
//   ltc::ltc_coefficients<float> c = table.fetch(cos_theta_v, roughness);
//   float e = c.magnitude * ltc::transformed<ltc::clamped_cosine<float>>::from_inverse(c.m_inv)
//                               .integrate(polygon, n);
//
// Shading with a specular colour F0 and Schlick's Fresnel (Hill 2016):
//   integral over P of rho cos F ~= (F0 * magnitude + (1 - F0) * fresnel) * I_ltc(P).
//
// Conventions: 6 floats per node (namespace channel), nodes at u = sqrt(1 - cos theta_v) and
// v = roughness (ltc_table), m_inv in the local frame N = +z, V in the xz-plane. Degenerate cases:
// inputs are clamped to [0, 1] and NaN counts as 0, so any input gives finite coefficients.
#pragma once

#include <ltc/config.hpp>
#include <ltc/detail/math.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>

LTC_NAMESPACE_BEGIN

/// What a table lookup returns: the inverse LTC matrix (any positive scale; here m_inv[1][1] = 1),
/// the magnitude (directional albedo) and the Fresnel term. magnitude * (the LTC's integral over a
/// polygon) approximates the integral of rho(V, L) cos(theta_L) over the polygon.
template <typename T>
struct ltc_coefficients {
    glm::mat<3, 3, T> m_inv{T(1)};
    T magnitude{0};
    T fresnel{0};
};

/// The specular colour's factor on the LTC's integral (Hill 2016's Fresnel split):
/// F0 magnitude + (1 - F0) fresnel.
template <typename T>
LTC_HOST_DEVICE inline glm::vec<3, T> brdf_scale(const glm::vec<3, T>& F0, const ltc_coefficients<T>& c) {
    return F0 * c.magnitude + (glm::vec<3, T>(T(1)) - F0) * c.fresnel;
}

/// Channel indices of a table node. A table holds, for each node (t, a) of a width x height grid,
/// the 6 floats
///
///   channel 0..3: m_inv[0][0], m_inv[0][2], m_inv[2][0], m_inv[2][2]   (GLM m[column][row])
///   channel 4:    magnitude = integral of rho(V, L) cos(theta_L) dL      (directional albedo)
///   channel 5:    fresnel   = integral of rho(V, L) cos(theta_L) (1 - V.H)^5 dL
///
/// where m_inv is the inverse LTC matrix in the local frame N = +z, V = (sin theta_v, 0,
/// cos theta_v), divided by its middle element m_inv[1][1] (which is therefore 1 and not stored);
/// the four other structurally zero elements m_inv[0][1], m_inv[1][0], m_inv[1][2], m_inv[2][1]
/// are 0 for an isotropic BRDF. In the paper's row-major notation, m_inv = [c0 0 c2; 0 1 0; c1 0 c3]
/// with c_k the channels. The data are stored node after node, rows of constant roughness one
/// after the other: data[((a * width) + t) * 6 + channel]. The batch kernels gather the floats
/// with 32-bit lane indices: a table used in batches keeps width * height * 6 below 2^31, at most
/// about 357 million nodes (the shipped tables have 1024 or 4096).
namespace channel {
inline constexpr int m_inv_00 = 0;  ///< m_inv[0][0]
inline constexpr int m_inv_02 = 1;  ///< m_inv[0][2]: column 0, row 2 (the paper's bottom-left element)
inline constexpr int m_inv_20 = 2;  ///< m_inv[2][0]: column 2, row 0 (the paper's top-right element)
inline constexpr int m_inv_22 = 3;  ///< m_inv[2][2]
inline constexpr int magnitude = 4;
inline constexpr int fresnel = 5;
inline constexpr int count = 6;
}  // namespace channel

namespace detail {

/// x clamped to [0, 1], with NaN mapped to 0.
template <typename T>
LTC_HOST_DEVICE inline T saturate(T x) {
    return x > T(0) ? (x < T(1) ? x : T(1)) : T(0);
}

/// Node index i0 in [0, n - 2] and weight f in [0, 1] of the position s in [0, n - 1] (node units),
/// where s is first snapped to the nearest node when it is within `tolerance` of it.
template <typename T>
LTC_HOST_DEVICE inline void axis_position(T s, int n, T tolerance, int& i0, T& f) {
    if (n < 2) {
        i0 = 0;
        f = T(0);
        return;
    }
    const T nearest = std::floor(s + T(0.5));
    if (std::abs(s - nearest) <= tolerance) s = nearest;
    int i = static_cast<int>(s);  // s >= 0
    if (i > n - 2) i = n - 2;
    i0 = i;
    f = s - T(i);
}

}  // namespace detail

/// A non-owning view of a width x height LTC table (6 floats per node, layout: namespace
/// channel), with the bilinear lookup of a GPU texture fetch.
///
/// Parameterization (the one of the paper's code release, which samples grazing angles densely):
///   u = sqrt(1 - cos theta_v)   node t at u = t / (width - 1),  i.e. cos theta_v = 1 - u^2;
///   v = roughness               node a at v = a / (height - 1), alpha = max(roughness^2, alpha_min).
///
/// Lookup: bilinear interpolation between the four surrounding nodes with clamp-to-edge, which is
/// what a GPU texture fetch of a width x height texture computes at the texel coordinates
/// (u * (width - 1) + 0.5) / width, (v * (height - 1) + 0.5) / height (the "LUT_SCALE / LUT_BIAS"
/// of the paper's shaders), except that the weights are exact instead of 8-bit fixed point.
/// Inputs are clamped to [0, 1] and NaN counts as 0, so any input gives finite coefficients.
/// Coordinates within rounding error of a node return that node's values exactly.
class ltc_table {
  public:
    static constexpr int channels = channel::count;

    LTC_HOST_DEVICE constexpr ltc_table(const float* data, int width, int height) : data_(data), width_(width), height_(height) {}

    LTC_HOST_DEVICE constexpr const float* data() const { return data_; }
    LTC_HOST_DEVICE constexpr int width() const { return width_; }    ///< nodes along u = sqrt(1 - cos theta_v)
    LTC_HOST_DEVICE constexpr int height() const { return height_; }  ///< nodes along v = roughness

    /// The stored value of a channel at node (t, a): t along u, a along roughness.
    LTC_HOST_DEVICE constexpr float node(int t, int a, int c) const {
        return data_[(static_cast<std::size_t>(a) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(t)) *
                         channels +
                     static_cast<std::size_t>(c)];
    }

    /// Where a lookup reads: the nodes (t0, a0) and (t1, a1) around the position and the lerps'
    /// weights. The same for every table of this width and height, so that a second table of the
    /// same size reuses it (ggx_two_lobe::fetch, ggx_cosine_lobe::fetch: one square root and one
    /// snap for both).
    template <typename T>
    struct position {
        int t0, t1, a0, a1;
        T fu, fv;
    };

    /// Bilinear interpolation of all channels at the table coordinates (u, v) in [0, 1]^2 (clamped,
    /// NaN counts as 0): out[c] for c < channels.
    template <typename T>
    LTC_HOST_DEVICE void lookup(T u, T v, T* out) const {
        u = detail::saturate(u);
        v = detail::saturate(v);
        const T eps = detail::epsilon<T>();
        const T su = u * T(width_ - 1);
        const T sv = v * T(height_ - 1);
        interpolate(locate_nodes(su, sv, T(4) * eps * su, T(4) * eps * sv), out);
    }

    /// Where fetch(cos_theta_v, roughness) reads (inputs clamped to [0, 1], NaN counts as 0).
    template <typename T>
    LTC_HOST_DEVICE position<T> locate(T cos_theta_v, T roughness) const {
        const T c = detail::saturate(cos_theta_v);
        const T u = std::sqrt(T(1) - c);
        const T v = detail::saturate(roughness);
        const T eps = detail::epsilon<T>();
        const T su = u * T(width_ - 1);
        const T sv = v * T(height_ - 1);
        // cos theta_v is known to eps, so s = (width - 1) sqrt(1 - c) only to about
        // (width - 1)^2 eps / (2 s): near normal incidence a node cannot be hit more precisely.
        const T w1 = T(width_ > 1 ? width_ - 1 : 1);
        const T tol_u = eps * (w1 * w1 / (su > T(1) ? su : T(1)) + T(2) * su);
        return locate_nodes(su, sv, tol_u, T(4) * eps * sv);
    }

    /// The LTC coefficients for the view angle cos(theta_v) and the roughness (alpha = roughness^2),
    /// both clamped to [0, 1] (NaN counts as 0).
    template <typename T>
    LTC_HOST_DEVICE ltc_coefficients<T> fetch(T cos_theta_v, T roughness) const {
        return fetch_at(locate(cos_theta_v, roughness));
    }

    /// fetch at a position from locate (of this table, or of another of the same width and height).
    template <typename T>
    LTC_HOST_DEVICE ltc_coefficients<T> fetch_at(const position<T>& at) const {
        T value[channels];
        interpolate(at, value);
        ltc_coefficients<T> r;
        r.m_inv = glm::mat<3, 3, T>(T(0));
        r.m_inv[0][0] = value[channel::m_inv_00];
        r.m_inv[0][2] = value[channel::m_inv_02];
        r.m_inv[2][0] = value[channel::m_inv_20];
        r.m_inv[2][2] = value[channel::m_inv_22];
        r.m_inv[1][1] = T(1);
        r.magnitude = value[channel::magnitude];
        r.fresnel = value[channel::fresnel];
        return r;
    }

    /// The magnitude and the Fresnel term alone at a position from locate, m_inv the identity: for
    /// a lobe whose matrix is fixed (the clamped cosine of ggx_cosine_lobe::fetch), a third of
    /// fetch_at's reads, each channel the bits fetch_at gives.
    template <typename T>
    LTC_HOST_DEVICE ltc_coefficients<T> fetch_scale_at(const position<T>& at) const {
        static_assert(channel::magnitude == channels - 2 && channel::fresnel == channels - 1,
                      "interpolate reads the channels from magnitude on");
        T value[channels];
        interpolate(at, value, channel::magnitude);
        ltc_coefficients<T> r;  // m_inv: the identity
        r.magnitude = value[channel::magnitude];
        r.fresnel = value[channel::fresnel];
        return r;
    }

  private:
    template <typename T>
    LTC_HOST_DEVICE position<T> locate_nodes(T su, T sv, T tol_u, T tol_v) const {
        position<T> p;
        detail::axis_position(su, width_, tol_u, p.t0, p.fu);
        detail::axis_position(sv, height_, tol_v, p.a0, p.fv);
        p.t1 = width_ > 1 ? p.t0 + 1 : p.t0;
        p.a1 = height_ > 1 ? p.a0 + 1 : p.a0;
        return p;
    }

    /// out[c] for the channels c from `first` on.
    template <typename T>
    LTC_HOST_DEVICE void interpolate(const position<T>& p, T* out, int first = 0) const {
        for (int c = first; c < channels; ++c) {
            // (1 - f) v0 + f v1: exactly v0 at f = 0 and v1 at f = 1, the mean at f = 1/2.
            const T lo = (T(1) - p.fu) * T(node(p.t0, p.a0, c)) + p.fu * T(node(p.t1, p.a0, c));
            const T hi = (T(1) - p.fu) * T(node(p.t0, p.a1, c)) + p.fu * T(node(p.t1, p.a1, c));
            out[c] = (T(1) - p.fv) * lo + p.fv * hi;
        }
    }

    const float* data_;
    int width_;
    int height_;
};

/// Lobe l (0 or 1) of the data of a table of the two-lobe layout (ltc/tables/ggx_two_lobe.hpp,
/// ggx_cosine_lobe.hpp: two square size x size tables, lobe 1's then lobe 2's).
LTC_HOST_DEVICE inline constexpr ltc_table two_lobe_layout_table(const float* data, int size, int l) {
    return ltc_table(data + (l == 0 ? 0 : std::size_t(size) * std::size_t(size) * channel::count), size, size);
}

LTC_NAMESPACE_END
