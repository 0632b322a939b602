// ltc/core/detail/polygon_stages.hpp -- the streaming stages of the shading_first clipping of
// ltc/shading/polygon_light_integrals.hpp: vertices flow one at a time through Sutherland-Hodgman
// clips to z >= 0, M^-1, a tee and sums of edge terms (paper eq. 11). Each stage holds only its
// first and previous vertex, so a polygon of any n is clipped twice without a vertex buffer.
#pragma once

#include <ltc/config.hpp>
#include <ltc/core/edge_integral.hpp>  // edge_integral_z
#include <ltc/core/edge_policy.hpp>    // edge_policy::exact
#include <ltc/core/horizon_clip.hpp>   // horizon_crossing_direction
#include <ltc/detail/math.hpp>         // safe_normalize

#include <glm/glm.hpp>

LTC_NAMESPACE_BEGIN

namespace detail {

/// Streaming sum of edge_integral_z over a closed polygon given vertex by vertex (unit vectors).
template <typename T, typename Policy = edge_policy::exact>
struct edge_sum {
    glm::vec<3, T> first{T(0)}, prev{T(0)};
    bool started = false;
    T sum{0};
    LTC_HOST_DEVICE void push(const glm::vec<3, T>& q) {
        if (started)
            sum += edge_integral_z<Policy>(prev, q);
        else
            first = q, started = true;
        prev = q;
    }
    LTC_HOST_DEVICE void close() {
        if (started) sum += edge_integral_z<Policy>(prev, first);
    }
};

/// Streaming Sutherland-Hodgman clip of a closed polygon of unit vectors to z >= 0: processes
/// the edges (v0 v1), ..., (v_n-1 v0) as vertices arrive and pushes the clipped polygon's unit
/// vertices to `next` (a cyclic rotation of clip_to_horizon's output, which changes no
/// integral). Crossing points have z exactly 0 (polygon.hpp's division-free construction).
template <typename T, typename Next>
struct clip_stage {
    Next& next;
    glm::vec<3, T> first{T(0)}, prev{T(0)};
    bool started = false;
    LTC_HOST_DEVICE void edge(const glm::vec<3, T>& p, const glm::vec<3, T>& q) {
        const bool p_in = p.z >= T(0), q_in = q.z >= T(0);
        if (p_in != q_in)
            next.push(safe_normalize(p_in ? horizon_crossing_direction(p, q) : horizon_crossing_direction(q, p)));
        if (q_in) next.push(q);
    }
    LTC_HOST_DEVICE void push(const glm::vec<3, T>& q) {
        if (started)
            edge(prev, q);
        else
            first = q, started = true;
        prev = q;
    }
    LTC_HOST_DEVICE void close() {
        if (started) edge(prev, first);
        next.close();
    }
};

/// Applies M^-1 to each unit vertex and forwards the unit result.
template <typename T, typename Next>
struct transform_stage {
    const glm::mat<3, 3, T>& m_inv;
    Next& next;
    LTC_HOST_DEVICE void push(const glm::vec<3, T>& q) { next.push(safe_normalize(m_inv * q)); }
    LTC_HOST_DEVICE void close() { next.close(); }
};

/// Forwards each vertex to two consumers.
template <typename T, typename A, typename B>
struct tee_stage {
    A& a;
    B& b;
    LTC_HOST_DEVICE void push(const glm::vec<3, T>& q) {
        a.push(q);
        b.push(q);
    }
    LTC_HOST_DEVICE void close() {
        a.close();
        b.close();
    }
};

}  // namespace detail

LTC_NAMESPACE_END
