// ltc/shading/batch_soa.hpp -- the structure-of-arrays inputs and outputs of the batch API:
// many polygons for ltc/shading/batch.hpp (vertex coordinates in one array per vertex and axis,
// and each item's inverse matrix M^-1, eq. 11 being integrated over M^-1 P, in nine arrays or
// shared by all items); many shading points (surfaces) and many polygon lights (polygon_lights)
// for ltc::batch::shade (ltc/shading/batch_shade.hpp), each field an array per item or one
// value for all (uniform):
//
//   ltc::batch::surfaces<float> pts{count, {px, py, pz}, {nx, ny, nz}, {vx, vy, vz},
//                                   roughness, ltc::batch::uniform(F0), ltc::batch::uniform(albedo)};
//   pts.roughness = ltc::batch::uniform(0.3f);          // any field, by name
//   auto lights = ltc::batch::polygon_lights<float>::two_sided(count, x, y, z, ltc::batch::uniform(L));
//
// and the old shading points of 16 arrays (shading_points, ltc/shading/batch_shading.hpp).
#pragma once

#include <ltc/config.hpp>
#include <ltc/core/sidedness.hpp>
#include <ltc/shading/lights/light_error.hpp>
#include <ltc/shading/lights/polygon_light.hpp>
#include <ltc/shading/surface.hpp>

#include <glm/glm.hpp>

#include <cstddef>

LTC_NAMESPACE_BEGIN
namespace batch {

/// Where each item's inverse matrix M^-1 comes from: nine arrays (one per entry, indexed like
/// glm: entry[c][r][i] = (M^-1 of item i)[c][r], column c, row r), or one matrix shared by all.
template <typename T>
struct matrices {
    const T* entry[3][3] = {};    ///< per-item arrays; all null: `shared` is used for every item
    glm::mat<3, 3, T> shared{T(1)};

    static matrices per_item(const T* const (&e)[3][3]) {
        matrices m;
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) m.entry[c][r] = e[c][r];
        return m;
    }
    static matrices same_for_all(const glm::mat<3, 3, T>& m_inv) {
        matrices m;
        m.shared = m_inv;
        return m;
    }
    bool is_shared() const { return entry[0][0] == nullptr; }
};

/// count polygons of N vertices each: vertex k of item i is (x[k][i], y[k][i], z[k][i]), in the
/// shading frame (any scale; see ltc/core/polygon.hpp for orientation and degenerate input).
template <typename T, std::size_t N>
struct polygon_soa {
    matrices<T> m_inv;
    const T* x[N] = {};
    const T* y[N] = {};
    const T* z[N] = {};
};

template <typename T>
using quad_soa = polygon_soa<T, 4>;

/// The same with n known at run time only: x[k] (k < n) points to the x coordinates of vertex k.
template <typename T>
struct ngon_soa {
    matrices<T> m_inv;
    std::size_t n = 0;
    const T* const* x = nullptr;
    const T* const* y = nullptr;
    const T* const* z = nullptr;
};

/// Shading points for ltc::batch::shade_polygon_light (ltc/shading/batch_shading.hpp): point i is
/// P = (px[i], py[i], pz[i]), its normal N, its direction towards the eye V (neither needs to be
/// normalized), its roughness (alpha = roughness^2), its specular colour F0 = (f0[0][i], f0[1][i],
/// f0[2][i]) and diffuse albedo, all in world space, as for ltc::shade_polygon_light.
template <typename T>
struct shading_points {
    const T* px = nullptr;
    const T* py = nullptr;
    const T* pz = nullptr;
    const T* nx = nullptr;
    const T* ny = nullptr;
    const T* nz = nullptr;
    const T* vx = nullptr;
    const T* vy = nullptr;
    const T* vz = nullptr;
    const T* roughness = nullptr;
    const T* f0[3] = {};
    const T* albedo[3] = {};

    /// The view of 16 arrays in the order px, py, pz, nx, ny, nz, vx, vy, vz, roughness, f0 r g b,
    /// albedo r g b.
    static shading_points from_columns(const T* const (&c)[16]) {
        shading_points p;
        p.px = c[0], p.py = c[1], p.pz = c[2], p.nx = c[3], p.ny = c[4], p.nz = c[5];
        p.vx = c[6], p.vy = c[7], p.vz = c[8], p.roughness = c[9];
        for (int k = 0; k < 3; ++k) p.f0[k] = c[10 + k], p.albedo[k] = c[13 + k];
        return p;
    }
};

/// Where the shading batches write: specular[c][i] and diffuse[c][i], channel c of item i.
template <typename T>
struct shading_results {
    T* specular[3] = {};
    T* diffuse[3] = {};
};

/// A value that every item of a batch shares: batch::uniform(F0), batch::uniform(0.5f).
template <typename V>
struct uniform_value {
    V value;
};

template <typename V>
constexpr uniform_value<V> uniform(const V& value) {
    return {value};
}

/// One scalar per item: data[i], or `value` for every item where data is null (uniform).
template <typename T>
struct scalar_field {
    const T* data = nullptr;
    T value{0};

    constexpr scalar_field() = default;
    constexpr scalar_field(const T* per_item) : data(per_item) {}
    template <typename V>
    constexpr scalar_field(uniform_value<V> u) : value(T(u.value)) {}

    bool is_uniform() const { return data == nullptr; }
    T at(std::size_t i) const { return data ? data[i] : value; }
};

/// One 3-vector per item: (x[i], y[i], z[i]), or `value` for every item where x is null
/// (uniform; y and z are then not read). uniform(s) of a scalar s is (s, s, s).
template <typename T>
struct vec3_field {
    const T* x = nullptr;
    const T* y = nullptr;
    const T* z = nullptr;
    glm::vec<3, T> value{T(0)};

    vec3_field() = default;
    vec3_field(const T* per_item_x, const T* per_item_y, const T* per_item_z)
        : x(per_item_x), y(per_item_y), z(per_item_z) {}
    /// The three arrays of c[0], c[1], c[2] (shading_points::f0, quad_lights::radiance).
    vec3_field(const T* const (&c)[3]) : x(c[0]), y(c[1]), z(c[2]) {}
    template <typename V>
    vec3_field(uniform_value<V> u) : value(glm::vec<3, T>(u.value)) {}

    bool is_uniform() const { return x == nullptr; }
    /// Channel c's array (null where uniform).
    const T* component(int c) const { return x == nullptr ? nullptr : c == 0 ? x : c == 1 ? y : z; }
    glm::vec<3, T> at(std::size_t i) const { return x ? glm::vec<3, T>(x[i], y[i], z[i]) : value; }
};

/// count shading points for ltc::batch::shade, in world space, each field per point or uniform:
/// point i is the ltc::surface at(i) (ltc/shading/surface.hpp: the fields' meaning and bad
/// input), the fields in that struct's order and with its defaults (uniform).
template <typename T>
struct surfaces {
    std::size_t count = 0;
    vec3_field<T> position = uniform(surface<T>{}.position);
    vec3_field<T> normal = uniform(surface<T>{}.normal);
    vec3_field<T> view = uniform(surface<T>{}.view);
    scalar_field<T> roughness = uniform(surface<T>{}.roughness);
    vec3_field<T> f0 = uniform(surface<T>{}.f0);
    vec3_field<T> albedo = uniform(surface<T>{}.albedo);
    vec3_field<T> tangent = uniform(surface<T>{}.tangent);                     ///< anisotropic models only
    scalar_field<T> roughness_bitangent = uniform(surface<T>{}.roughness_bitangent);  ///< anisotropic models only

    surface<T> at(std::size_t i) const {
        return {position.at(i), normal.at(i), view.at(i), roughness.at(i), f0.at(i), albedo.at(i), tangent.at(i),
                roughness_bitangent.at(i)};
    }
};

/// count polygon lights of N world-space vertices each for ltc::batch::shade over one point:
/// vertex k of light i is (x[k][i], y[k][i], z[k][i]), its radiance radiance.at(i), and all
/// share one facing rule, that of the ltc::polygon_light factory of the same name
/// (ltc/shading/lights/polygon_light.hpp): one-sided towards an emission normal (per light or
/// uniform; either vertex order), one-sided by a winding convention, or two-sided. A view of the
/// caller's arrays, which must outlive the calls. light(i, buffer) is light i as ltc::shade takes
/// it: the emission normal is checked there (ltc::invalid_light), so batch::shade throws for a
/// light whose normal is zero, not finite or in its plane.
template <typename T, std::size_t N = 4>
class polygon_lights {
public:
    using vec3 = glm::vec<3, T>;
    using axis = const T* const (&)[N];
    static_assert(N >= 1, "polygon_lights: at least one vertex");

    static polygon_lights one_sided(std::size_t count, axis x, axis y, axis z, const vec3_field<T>& emission_normal,
                                    const vec3_field<T>& radiance) {
        polygon_lights l(count, x, y, z, radiance, rule::emission_normal);
        l.emission_normal_ = emission_normal;
        return l;
    }
    static polygon_lights one_sided(std::size_t count, axis x, axis y, axis z, winding front,
                                    const vec3_field<T>& radiance) {
        polygon_lights l(count, x, y, z, radiance, rule::winding);
        l.front_ = front;
        return l;
    }
    static polygon_lights two_sided(std::size_t count, axis x, axis y, axis z, const vec3_field<T>& radiance) {
        return polygon_lights(count, x, y, z, radiance, rule::two_sided);
    }

    std::size_t size() const { return count_; }
    sidedness sides() const { return rule_ == rule::two_sided ? sidedness::two_sided : sidedness::one_sided; }
    /// Vertex k of light i, in the order given.
    vec3 vertex(std::size_t i, std::size_t k) const { return vec3(x_[k][i], y_[k][i], z_[k][i]); }
    vec3 radiance(std::size_t i) const { return radiance_.at(i); }

    /// The array of coordinate c (0: x, 1: y, 2: z) of vertex k of every light.
    const T* coordinates(int c, std::size_t k) const { return c == 0 ? x_[k] : c == 1 ? y_[k] : z_[k]; }
    const vec3_field<T>& radiances() const { return radiance_; }
    /// The emission normals (one_sided with normals; else uniform 0).
    const vec3_field<T>& emission_normals() const { return emission_normal_; }
    /// Whether the facing rule is the same for every light (winding or two-sided): then so is
    /// the order in which they walk their vertices.
    bool same_order_for_all() const { return rule_ != rule::emission_normal; }
    /// Whether light i walks its vertices in reverse: the decision and the checks of its
    /// polygon_light factory (ltc/shading/lights/polygon_light.hpp), without building it.
    bool reversed(std::size_t i) const {
        switch (rule_) {
            case rule::two_sided: return false;
            case rule::winding: return front_ == winding::counter_clockwise_front;
            case rule::emission_normal:
            default: {
                const vec3 normal = emission_normal_.at(i);
                if (!ltc::detail::finite(normal) || normal == vec3(T(0)))
                    throw invalid_light("polygon_light::one_sided: the emission normal is zero or not finite");
                vec3 v[N];
                for (std::size_t k = 0; k < N; ++k) v[k] = vertex(i, k);
                const vec3 area = N >= 3 ? ltc::detail::vector_area_x2(v, N) : vec3(T(0));
                const T facing = glm::dot(area, normal);
                if (area != vec3(T(0)) && !(facing != T(0)))
                    throw invalid_light("polygon_light::one_sided: the emission normal lies in the polygon's plane");
                return facing > T(0);
            }
        }
    }

    /// Light i as ltc::shade takes it (checked as its factory), over its vertices copied to buffer.
    polygon_light<T> light(std::size_t i, vec3 (&buffer)[N]) const {
        for (std::size_t k = 0; k < N; ++k) buffer[k] = vertex(i, k);
        switch (rule_) {
            case rule::emission_normal:
                return polygon_light<T>::one_sided(buffer, N, emission_normal_.at(i), radiance_.at(i));
            case rule::winding: return polygon_light<T>::one_sided(buffer, N, front_, radiance_.at(i));
            case rule::two_sided:
            default: return polygon_light<T>::two_sided(buffer, N, radiance_.at(i));
        }
    }

private:
    enum class rule { emission_normal, winding, two_sided };

    polygon_lights(std::size_t count, axis x, axis y, axis z, const vec3_field<T>& radiance, rule r)
        : count_(count), radiance_(radiance), rule_(r) {
        for (std::size_t k = 0; k < N; ++k) {
            if (count > 0 && (x[k] == nullptr || y[k] == nullptr || z[k] == nullptr))
                throw invalid_light("batch::polygon_lights: null vertex arrays with count > 0");
            x_[k] = x[k], y_[k] = y[k], z_[k] = z[k];
        }
    }

    std::size_t count_;
    const T* x_[N];
    const T* y_[N];
    const T* z_[N];
    vec3_field<T> radiance_;
    vec3_field<T> emission_normal_;
    rule rule_;
    winding front_ = winding::clockwise_front;
};

namespace detail {

/// The old shading points as surfaces (the deprecated batch functions).
template <typename T>
surfaces<T> surfaces_of(const shading_points<T>& p, std::size_t count) {
    return {count, {p.px, p.py, p.pz}, {p.nx, p.ny, p.nz}, {p.vx, p.vy, p.vz}, p.roughness, p.f0, p.albedo};
}

}  // namespace detail

}  // namespace batch
LTC_NAMESPACE_END
