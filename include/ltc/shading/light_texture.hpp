// ltc/shading/light_texture.hpp -- prefiltered textures of textured polygonal lights (paper sections
// 5.2 and 5.3): the stack of Gaussian-filtered levels that the fetch of
// ltc/shading/lights/textured_quad_light.hpp reads.
//
//   std::vector<glm::vec3> rgb(width * height);                  // linear RGB, row-major
//   ltc::light_texture<float> tex(width, height, rgb.data());    // prefilters every level
//   glm::vec3 c = tex.lookup(glm::vec2(u, v), tex.lod_for_sigma(sigma));   // trilinear
//
// Section 5.3: I_L of eq. (14) is the texture filtered by F = D / int_P D projected to texture
// space; level k replaces F by a texture-space Gaussian of standard deviation sigma_k, clamped to
// the texture and renormalized inside it (light_texture). Conventions: texel (x, y) of the
// row-major image is centred at uv = ((x + 0.5) / width, (y + 0.5) / height), v = 0 on the first
// row; a quad light's corners carry uv (0,0), (1,0), (1,1), (0,1). Degenerate cases: the
// constructor throws std::invalid_argument for bad input; lookups are finite for any uv and lod.
#pragma once

#include <ltc/config.hpp>
#include <ltc/shading/detail/texture_filter.hpp>  // texture_axis, gaussian_taps, parallel_for, lerp_exact
#include <ltc/shading/cell_pyramid.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

LTC_NAMESPACE_BEGIN

/// Bilinear lookup of an unfiltered width x height row-major RGB image at uv (texel centres at
/// ((x + 0.5) / width, (y + 0.5) / height), clamp-to-edge): the radiance L(uv) of a textured
/// light, as the ground truth (ltc/reference/textured_ground_truth.hpp) sees it. Non-finite uv -> centre.
template <typename C, typename T>
inline C bilinear_image_lookup(int width, int height, const C* rgb, T u, T v) {
    if (!std::isfinite(static_cast<double>(u))) u = T(0.5);
    if (!std::isfinite(static_cast<double>(v))) v = T(0.5);
    const double x = std::min(std::max(double(u) * width - 0.5, 0.0), double(width - 1));
    const double y = std::min(std::max(double(v) * height - 0.5, 0.0), double(height - 1));
    const int x0 = std::min(static_cast<int>(x), std::max(width - 2, 0));
    const int y0 = std::min(static_cast<int>(y), std::max(height - 2, 0));
    const int x1 = std::min(x0 + 1, width - 1), y1 = std::min(y0 + 1, height - 1);
    using S = typename C::value_type;
    const S fx = static_cast<S>(x - x0), fy = static_cast<S>(y - y0);
    const C a = rgb[std::size_t(y0) * width + x0] + fx * (rgb[std::size_t(y0) * width + x1] - rgb[std::size_t(y0) * width + x0]);
    const C b = rgb[std::size_t(y1) * width + x0] + fx * (rgb[std::size_t(y1) * width + x1] - rgb[std::size_t(y1) * width + x0]);
    return a + fy * (b - a);
}

/// The texel under uv of an unfiltered width x height row-major RGB image (texel (x, y) covers
/// [x / width, (x + 1) / width] x [y / height, (y + 1) / height], clamp-to-edge): the radiance of
/// the texel-constant texture, which the exact cell integrals (ltc/shading/textured_cells.hpp)
/// integrate. Non-finite uv -> centre.
template <typename C, typename T>
inline C nearest_image_lookup(int width, int height, const C* rgb, T u, T v) {
    if (!std::isfinite(static_cast<double>(u))) u = T(0.5);
    if (!std::isfinite(static_cast<double>(v))) v = T(0.5);
    const double x = std::min(std::max(std::floor(double(u) * width), 0.0), double(width - 1));
    const double y = std::min(std::max(std::floor(double(v) * height), 0.0), double(height - 1));
    return rgb[std::size_t(y) * std::size_t(width) + std::size_t(x)];
}

/// The prefiltered texture of a textured polygonal light. T is the scalar type of the lookup's
/// coordinates; the levels are float RGB. The texture covers [0, 1]^2.
///
/// What a level holds (section 5.3). I_L of eq. (14) is the texture filtered by F = D / int_P D
/// projected to texture space. The prefilter replaces F by a texture-space Gaussian of standard
/// deviation sigma (uv units, isotropic in uv) that keeps F's two properties: it is clamped to
/// the texture (zero outside) and renormalized inside it. Level k stores, at sample points p of
/// a regular grid,
///
///   F_k(p) = sum_c w(p, c) L(c) / sum_c w(p, c),                                      (*)
///   w(p, c) = exp(-(p.x - c.x)^2 / (2 s_x(p)^2) - (p.y - c.y)^2 / (2 s_y(p)^2)),
///   s_a(p)  = sqrt(sigma_k^2 + d_a(p)^2),   d_a(p) = max(0, -p.a, p.a - 1),
///
/// with c running over all texel centres and L(c) the texel's colour. Inside the texture d = 0
/// and w is the Gaussian of standard deviation sigma_k clamped to the texture and renormalized;
/// in the margin around it (d > 0) the radius grows with the distance d to the texture along
/// each axis, so that the filter always meets the texture with a weight comparable to its peak,
/// and F_k is smooth and lower-frequency the farther out the point is (the paper's figure 6).
/// Beyond the margin the coordinates are clamped to it (clamp-to-edge on the level's grid).
///
/// Levels. sigma_0 = 0 (level 0 is the image itself: (*) with sigma = 0 picks the nearest texel,
/// so level 0's samples inside the texture are exactly the texels), and for k >= 1
///
///   sigma_k = 2^(k-1) / max(width, height)      (uv units: level 1 is one texel of the larger
///                                                side, each level doubles)
///
/// up to the first level with sigma_k >= 2 (filters wider than twice the texture are nearly the
/// plain average: their weights across it stay within a factor exp(-1/8) of their peak). Level k
/// samples each axis of n texels at the pitch h = 1 / n_k, n_k = clamp(floor(2 / sigma_k), 1, n)
/// cells across [0, 1] (centres at (i + 0.5) / n_k): at the texel pitch while sigma_k <= 2 texels,
/// then at sigma_k / 2, so the resolution halves with each level, as in a MIP pyramid, and a
/// Gaussian is sampled at least twice per standard deviation (bilinear reconstruction error of
/// the Gaussian-blurred signal <= h^2 / 8 |f''| <= 1/32 of its amplitude). The margin adds
/// ceil(margin * n_k) cells on each side, so level k covers at least [-margin, 1 + margin]^2.
///
/// Computation: (*) is separable. Its weight is a product of a function of x and one of y (s_x
/// depends on p.x only, s_y on p.y only), and so is its normalization: sum_c w = (sum_x w_x)
/// (sum_y w_y). So F_k = sum_y (w_y / S_y) sum_x (w_x / S_x) L(x, y): a pass along rows (for
/// each row and each output column) then one along columns, each 1D kernel normalized on its
/// own, accumulated in double (the row pass stores doubles), stored as float RGB. The kernels
/// are truncated at 7 s_a from the sample point (always keeping the nearest texel): the dropped
/// weights are below exp(-24.5) = 2.3e-11 of the peak, and their sum below 1e-10 of the kernel's
/// total, under float rounding (2^-24 = 6e-8).
/// Cost: level k costs O(n^2 (1 + sigma_k / h_k)) inside the texture, i.e. O(n^2) per level
/// (the output count falls by 4 when the kernel doubles), O(n^2 log n) for the stack; in the
/// margin the kernel width grows with d, O(n^3 margin^2) per level in the worst case (level 0),
/// so the margin dominates. Rows and columns are split over std::thread::hardware_concurrency()
/// threads (the 1D taps and the thread split: ltc/shading/detail/texture_filter.hpp).
///
/// The constructor also builds the image's cell pyramid (cells(): means and ranges of 2^k x 2^k
/// texel blocks, about 16 bytes per texel in float) for the exact integrals of
/// ltc/shading/textured_cells.hpp.
///
/// Storage: float RGB whatever T is. Levels 0 to 2 are at the texel pitch, then each level has a
/// quarter of the samples of the previous one: about (3 + 1/3) (1 + 2 margin)^2 width height
/// 12 bytes (65.5 MB for 1024 x 1024 at the default margin 0.125).
template <typename T>
class light_texture {
  public:
    using vec2 = glm::vec<2, T>;
    using vec3 = glm::vec<3, T>;

    /// Default margin (uv units) around the texture on each side.
    static constexpr double default_margin = 0.125;

    struct level {
        detail::texture_axis x, y;
        double sigma = 0;              ///< sigma_k, uv units
        std::vector<glm::vec3> texels; ///< x.count() * y.count(), row-major
        const glm::vec3& at(int i, int j) const { return texels[std::size_t(j) * x.count() + i]; }
    };

    /// Prefilters the width x height linear-RGB image (row-major, v = 0 on the first row).
    /// Throws std::invalid_argument for a non-positive size, a null pointer, a negative or
    /// non-finite margin, or a non-finite texel (an infinite radiance would make every level
    /// that sees it infinite or NaN).
    light_texture(int width, int height, const vec3* linear_rgb, double margin = default_margin)
        : width_(width), height_(height), margin_(margin), cells_(validated(width, height, linear_rgb, margin)) {
        std::vector<glm::dvec3> image(std::size_t(width) * height);
        for (std::size_t i = 0; i < image.size(); ++i) image[i] = glm::dvec3(linear_rgb[i]);
        const int n = std::max(width, height);
        sigma_1_ = 1.0 / n;
        for (int k = 0;; ++k) {
            const double sigma = k == 0 ? 0.0 : sigma_1_ * std::ldexp(1.0, k - 1);
            levels_.push_back(filter(image, sigma));
            if (sigma >= 2.0) break;
        }
    }

    /// The image as constant cells (ltc/shading/cell_pyramid.hpp): the data of the exact
    /// textured integrals (ltc/shading/textured_cells.hpp).
    const cell_pyramid<T>& cells() const { return cells_; }

    int width() const { return width_; }
    int height() const { return height_; }
    double margin() const { return margin_; }
    int level_count() const { return static_cast<int>(levels_.size()); }
    const level& get_level(int k) const { return levels_[std::size_t(k)]; }
    /// sigma_k in uv units (0 for level 0).
    double sigma_of_level(int k) const { return levels_[std::size_t(std::min(std::max(k, 0), level_count() - 1))].sigma; }

    /// The continuous lod whose standard deviation is sigma (uv units), clamped to
    /// [0, level_count() - 1]; non-decreasing in sigma; NaN -> the last level.
    T lod_for_sigma(T sigma) const {
        const double s = static_cast<double>(sigma);
        const double last = level_count() - 1;
        if (!(s > 0)) return s <= 0 ? T(0) : T(last);
        double lod = s <= sigma_1_ ? s / sigma_1_ : 1.0 + std::log2(s / sigma_1_);
        return T(std::min(std::max(lod, 0.0), last));
    }

    /// Trilinear lookup: bilinear within levels floor(lod) and floor(lod) + 1 (clamp-to-edge on
    /// each level's grid of sample centres), linear between them: a GPU's trilinear fetch. lod is
    /// continuous; lod_for_sigma(sigma) is the lod whose interpolated standard deviation is sigma:
    /// sigma / sigma_1 below level 1 and 1 + log2(sigma / sigma_1) above, clamped to the stack.
    /// A constant texture returns that constant exactly (weights normalized in double, lerps of
    /// equal values written a + t (b - a)). Finite for any input: NaN coordinates read the texture
    /// centre, NaN lod the last level.
    glm::vec<3, T> lookup(const vec2& uv, T lod) const {
        double l = static_cast<double>(lod);
        const double last = level_count() - 1;
        if (!(l >= 0)) l = std::isnan(l) ? last : 0.0;
        if (l > last) l = last;
        const int k0 = static_cast<int>(l);
        const int k1 = std::min(k0 + 1, level_count() - 1);
        const float f = static_cast<float>(l - k0);
        const glm::vec3 a = bilinear(levels_[std::size_t(k0)], uv);
        if (k1 == k0 || f == 0.0f) return glm::vec<3, T>(a);
        const glm::vec3 b = bilinear(levels_[std::size_t(k1)], uv);
        return glm::vec<3, T>(detail::lerp_exact(a, b, f));
    }

    /// Bilinear lookup of one level (clamp-to-edge on its sample grid).
    glm::vec3 lookup_level(const vec2& uv, int k) const {
        return bilinear(levels_[std::size_t(std::min(std::max(k, 0), level_count() - 1))], uv);
    }

  private:
    static cell_pyramid<T> validated(int width, int height, const vec3* linear_rgb, double margin) {
        if (width <= 0 || height <= 0 || linear_rgb == nullptr)
            throw std::invalid_argument("ltc::light_texture: empty image");
        if (!(margin >= 0.0) || !std::isfinite(margin)) throw std::invalid_argument("ltc::light_texture: bad margin");
        for (std::size_t i = 0; i < std::size_t(width) * std::size_t(height); ++i) {
            const glm::dvec3 c(linear_rgb[i]);
            if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z))
                throw std::invalid_argument("ltc::light_texture: non-finite texel");
        }
        return cell_pyramid<T>(width, height, linear_rgb);
    }

    static detail::texture_axis make_axis(int texels, double sigma, double margin) {
        detail::texture_axis a;
        a.texels = texels;
        if (sigma <= 0) {
            a.cells = texels;
        } else {
            const double c = std::floor(2.0 / sigma);
            a.cells = static_cast<int>(std::min(std::max(c, 1.0), double(texels)));
        }
        a.margin_cells = static_cast<int>(std::ceil(margin * a.cells - 1e-9));
        return a;
    }

    level filter(const std::vector<glm::dvec3>& image, double sigma) const {
        level L;
        L.sigma = sigma;
        L.x = make_axis(width_, sigma, margin_);
        L.y = make_axis(height_, sigma, margin_);
        const int nx = L.x.count(), ny = L.y.count();
        // Row pass: rows[y][i] = sum_x w_x(p_i, x) image(x, y).
        std::vector<glm::dvec3> rows(static_cast<std::size_t>(height_) * nx);
        std::vector<int> xfirst(static_cast<std::size_t>(nx));
        std::vector<std::vector<double>> xw(static_cast<std::size_t>(nx));
        for (int i = 0; i < nx; ++i) detail::gaussian_taps(L.x.position(i), width_, sigma, xfirst[i], xw[i]);
        detail::parallel_for(height_, [&](int y) {
            const glm::dvec3* src = image.data() + std::size_t(y) * width_;
            glm::dvec3* dst = rows.data() + std::size_t(y) * nx;
            for (int i = 0; i < nx; ++i) {
                const std::vector<double>& w = xw[std::size_t(i)];
                const glm::dvec3* s = src + xfirst[std::size_t(i)];
                glm::dvec3 acc(0.0);
                for (std::size_t t = 0; t < w.size(); ++t) acc += w[t] * s[t];
                dst[i] = acc;
            }
        });
        // Column pass: level(i, j) = sum_y w_y(p_j, y) rows[y][i].
        L.texels.assign(std::size_t(nx) * ny, glm::vec3(0.0f));
        detail::parallel_for(ny, [&](int j) {
            int first = 0;
            std::vector<double> w;
            detail::gaussian_taps(L.y.position(j), height_, sigma, first, w);
            std::vector<glm::dvec3> acc(static_cast<std::size_t>(nx), glm::dvec3(0.0));
            for (std::size_t t = 0; t < w.size(); ++t) {
                const glm::dvec3* r = rows.data() + std::size_t(first + int(t)) * nx;
                const double wt = w[t];
                for (int i = 0; i < nx; ++i) acc[std::size_t(i)] += wt * r[i];
            }
            glm::vec3* dst = L.texels.data() + std::size_t(j) * nx;
            for (int i = 0; i < nx; ++i) dst[i] = glm::vec3(acc[std::size_t(i)]);
        });
        return L;
    }

    static glm::vec3 bilinear(const level& L, const vec2& uv) {
        double u = static_cast<double>(uv.x), v = static_cast<double>(uv.y);
        if (!std::isfinite(u)) u = std::isnan(u) ? 0.5 : (u > 0 ? 1e30 : -1e30);
        if (!std::isfinite(v)) v = std::isnan(v) ? 0.5 : (v > 0 ? 1e30 : -1e30);
        const int nx = L.x.count(), ny = L.y.count();
        // Continuous sample index: position(i) = (i - m + 0.5) / cells.
        const double fx = std::min(std::max(u * L.x.cells + L.x.margin_cells - 0.5, 0.0), double(nx - 1));
        const double fy = std::min(std::max(v * L.y.cells + L.y.margin_cells - 0.5, 0.0), double(ny - 1));
        const int i0 = std::min(static_cast<int>(fx), std::max(nx - 2, 0));
        const int j0 = std::min(static_cast<int>(fy), std::max(ny - 2, 0));
        const int i1 = std::min(i0 + 1, nx - 1), j1 = std::min(j0 + 1, ny - 1);
        const float tx = static_cast<float>(fx - i0), ty = static_cast<float>(fy - j0);
        const glm::vec3 a = detail::lerp_exact(L.at(i0, j0), L.at(i1, j0), tx);
        const glm::vec3 b = detail::lerp_exact(L.at(i0, j1), L.at(i1, j1), tx);
        return detail::lerp_exact(a, b, ty);
    }

    int width_, height_;
    double margin_;
    cell_pyramid<T> cells_;
    double sigma_1_ = 1;
    std::vector<level> levels_;
};

LTC_NAMESPACE_END
