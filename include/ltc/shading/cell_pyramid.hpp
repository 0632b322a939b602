// ltc/shading/cell_pyramid.hpp -- a light's texture as constant cells, level by level: the data of
// the exact textured integral (ltc/shading/textured_cells.hpp).
//
//   ltc::cell_pyramid<float> cells(width, height, rgb);    // or light_texture::cells()
//   glm::vec3 c = cells.mean(level, i, j);                 // the mean of the cell's texels
//
// Each cell holds the mean and the range of its texels: the integral of L D over a cell is
// mean(cell) I_D(cell) to within range(cell) I_D(cell) per channel. Conventions: texel (x, y)
// covers [x / width, (x + 1) / width] x [y / height, (y + 1) / height], v = 0 on the first row
// (as ltc/shading/light_texture.hpp); level 0 is the image, the last level one cell (cell_pyramid).
#pragma once

#include <ltc/config.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

LTC_NAMESPACE_BEGIN

/// Level 0 is the image itself: texel (x, y) is the constant L(x, y) on the uv rectangle
/// [x / width, (x + 1) / width] x [y / height, (y + 1) / height] (v = 0 on the first row, as in
/// ltc/shading/light_texture.hpp). Cell (i, j) of level k covers the texels [i 2^k, (i + 1) 2^k)
/// x [j 2^k, (j + 1) 2^k), clipped to the image (non-power-of-two sizes: the last cell of a row or
/// column is narrower), and holds their mean and their range (the largest max - min over the
/// three channels). The last level is one cell, the whole image. A cell's children are the cells
/// of level k - 1 inside it (one to four).
///
/// Why means and ranges: the integral of L D over a cell is mean(cell) I_D(cell) plus
/// sum_t (L_t - mean) I_D(t) over its texels t, and since every I_D(t) >= 0 (one orientation for
/// all cells) that remainder is at most range(cell) I_D(cell) per channel. The quadtree of
/// ltc/shading/textured_cells.hpp refines the cell with the largest such bound.
///
/// Storage: sum_k cells(k) (3 + 1) T, about (4/3) width height 16 bytes in float (22 MB for
/// 1024 x 1024); built in O(width height), each level from the one below (sums, extremes and
/// counts in double, kept for the level below only).
template <typename T>
class cell_pyramid {
  public:
    using vec3 = glm::vec<3, T>;

    /// The levels of the width x height linear-RGB image (row-major, v = 0 on the first row).
    /// Throws std::invalid_argument for a non-positive size, a null pointer or a non-finite
    /// texel (as light_texture does).
    cell_pyramid(int width, int height, const vec3* linear_rgb) : width_(width), height_(height) {
        if (width <= 0 || height <= 0 || linear_rgb == nullptr)
            throw std::invalid_argument("ltc::cell_pyramid: empty image");
        level base;
        base.nx = width, base.ny = height;
        base.mean.assign(linear_rgb, linear_rgb + std::size_t(width) * std::size_t(height));
        base.range.assign(base.mean.size(), T(0));
        for (const vec3& t : base.mean)
            if (!std::isfinite(double(t.x)) || !std::isfinite(double(t.y)) || !std::isfinite(double(t.z)))
                throw std::invalid_argument("ltc::cell_pyramid: non-finite texel");
        levels_.push_back(std::move(base));
        // Sums, extremes and counts (in double) of the level below only, each level built from
        // the one below: level 1 from the texels themselves.
        if (width == 1 && height == 1) return;
        const auto t = [&](std::size_t s) { return glm::dvec3(linear_rgb[s]); };
        partial below = coarser(width, height, t, t, t, [](std::size_t) { return 1.0; });
        finish(below);
        while (below.nx > 1 || below.ny > 1) {
            partial next = coarser(
                below.nx, below.ny, [&](std::size_t s) { return below.sum[s]; },
                [&](std::size_t s) { return below.lo[s]; }, [&](std::size_t s) { return below.hi[s]; },
                [&](std::size_t s) { return below.count[s]; });
            finish(next);
            below = std::move(next);
        }
    }

    int width() const { return width_; }
    int height() const { return height_; }
    int level_count() const { return int(levels_.size()); }
    int cells_x(int k) const { return levels_[std::size_t(k)].nx; }
    int cells_y(int k) const { return levels_[std::size_t(k)].ny; }

    /// The mean of the texels of cell (i, j) of level k (level 0: the texel itself, exactly).
    const vec3& mean(int k, int i, int j) const { return levels_[std::size_t(k)].mean[index(k, i, j)]; }
    /// The largest (max - min) over the channels of the texels of cell (i, j) of level k.
    T range(int k, int i, int j) const { return levels_[std::size_t(k)].range[index(k, i, j)]; }

    /// The texel rectangle [x0, x1) x [y0, y1) of cell (i, j) of level k.
    void texels(int k, int i, int j, int& x0, int& y0, int& x1, int& y1) const {
        x0 = i << k, y0 = j << k;
        x1 = std::min((i + 1) << k, width_), y1 = std::min((j + 1) << k, height_);
    }

  private:
    struct level {
        int nx = 0, ny = 0;
        std::vector<vec3> mean;
        std::vector<T> range;
    };
    // A level under construction.
    struct partial {
        int nx = 0, ny = 0;
        std::vector<glm::dvec3> sum, lo, hi;
        std::vector<double> count;
    };

    std::size_t index(int k, int i, int j) const { return std::size_t(j) * levels_[std::size_t(k)].nx + std::size_t(i); }

    /// The level above a nx x ny level whose cell s has the given sum, extremes and count.
    template <typename Sum, typename Lo, typename Hi, typename Count>
    static partial coarser(int nx, int ny, const Sum& sum, const Lo& lo, const Hi& hi, const Count& count) {
        partial c;
        c.nx = (nx + 1) / 2, c.ny = (ny + 1) / 2;
        const std::size_t n = std::size_t(c.nx) * c.ny;
        c.sum.assign(n, glm::dvec3(0.0));
        c.count.assign(n, 0.0);
        c.lo.assign(n, glm::dvec3(INFINITY));
        c.hi.assign(n, glm::dvec3(-INFINITY));
        for (int y = 0; y < ny; ++y)
            for (int x = 0; x < nx; ++x) {
                const std::size_t s = std::size_t(y) * nx + x, d = std::size_t(y / 2) * c.nx + x / 2;
                c.sum[d] += sum(s);
                c.count[d] += count(s);
                c.lo[d] = glm::min(c.lo[d], lo(s));
                c.hi[d] = glm::max(c.hi[d], hi(s));
            }
        return c;
    }

    /// The means and ranges of a finished level.
    void finish(const partial& p) {
        level l;
        l.nx = p.nx, l.ny = p.ny;
        l.mean.resize(p.sum.size());
        l.range.resize(p.sum.size());
        for (std::size_t c = 0; c < p.sum.size(); ++c) {
            l.mean[c] = vec3(p.sum[c] / p.count[c]);
            const glm::dvec3 r = p.hi[c] - p.lo[c];
            l.range[c] = T(std::max(r.x, std::max(r.y, r.z)));
        }
        levels_.push_back(std::move(l));
    }

    int width_, height_;
    std::vector<level> levels_;
};

LTC_NAMESPACE_END
