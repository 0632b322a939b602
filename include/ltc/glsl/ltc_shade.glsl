// ltc/glsl/ltc_shade.glsl -- the GLSL port of ltc::shade(s, light) with the default model
// (ltc::ggx::ltc_and_cosine: an LTC and the clamped cosine) and a polygon light: the paper's order
// (rotate, M^-1, clip to the horizon exactly), edge_policy::minimax_rational's float-accurate edge
// term and the C++ rules for bad input. GLSL 4.50 (Vulkan or OpenGL); before including, define
//   float ltc_table_node(int lobe, int t, int a, int c);
// node (t, a), channel c of lobe 0 (the cosine) or 1 (the LTC) of ltc::tables::ggx_cosine_lobe_data
// (32 x 32 nodes each, 6 channels: data[((lobe * 32 + a) * 32 + t) * 6 + c]; a storage buffer or
// texelFetch), and optionally LTC_MAX_VERTICES (default 8: the largest light). Then
//   ltc_shading_result r = ltc_shade(s, vertices, light);   // as ltc::shade(s, polygon_light)
// Conventions: those of the C++ (ltc/shading/shade.hpp, lobes.hpp, lights/polygon_light.hpp);
// every function names the C++ one it ports. Where GLSL cannot throw (a light that
// polygon_light::one_sided rejects), the light has no vertices and emits nothing.
// tests/test_glsl_port.cpp runs it on a Vulkan device against the C++ within a derived bound.

#ifndef LTC_GLSL_SHADE
#define LTC_GLSL_SHADE

#ifndef LTC_MAX_VERTICES
#define LTC_MAX_VERTICES 8
#endif
#define LTC_TABLE_SIZE 32

float ltc_table_node(int lobe, int t, int a, int c);

// The C++ float constants: pi<float>(), min_normal<float>(), epsilon<float>().
const float LTC_PI = 3.14159265358979323846;
const float LTC_MIN_NORMAL = 1.17549435e-38;
const float LTC_EPSILON = 1.1920929e-7;

// Every arithmetic result below is `precise` (SPIR-V NoContraction): no fused multiply-add and no
// reassociation, the operations of the C++ built with -ffp-contract=off, so that the cancellations
// the C++ relies on (stable_cross, x - x for a finiteness test) happen here too.

struct ltc_surface {       // ltc::surface<float>
    vec3 position;
    vec3 normal;
    vec3 view;             // towards the viewer, any length
    float roughness;       // clamped to [0, 1], NaN read as 0
    vec3 f0;
    vec3 albedo;
};

struct ltc_shading_result {  // ltc::shading_result<float>
    vec3 specular;
    vec3 diffuse;
};

struct ltc_shading_frame {   // ltc::shading_frame<float>
    vec3 t1;
    vec3 t2;
    vec3 n;
    float cos_theta_v;
    bool valid;
};

struct ltc_coefficients {    // ltc::ltc_coefficients<float>
    mat3 m_inv;
    float magnitude;
    float fresnel;
};

struct ltc_lobes {           // ltc::lobes::ltc_and_cosine<float>
    ltc_coefficients ltc;
    ltc_coefficients cosine;  // its magnitude and fresnel; m_inv the identity
};

// ltc::polygon_light<float>: the vertices are passed beside it, in the caller's order; the light
// walks them forwards or backwards so that its front is the side from which they turn clockwise.
struct ltc_polygon_light {
    int count;               // vertices used (<= LTC_MAX_VERTICES; < 3: emits nothing)
    bool reversed;           // walk vertices[count - 1] ... vertices[0]
    bool two_sided;          // emits from both faces (|signed integral|)
    vec3 radiance;
};

// ---- ltc/detail/math.hpp ------------------------------------------------------------------

// glm::dot, glm::cross, M v and glm::length in GLM's order of operations, spelled out: the
// built-ins carry no NoContraction, and an implementation may fuse inside them.
float ltc_dot(vec3 a, vec3 b) {
    precise float r = a.x * b.x + a.y * b.y + a.z * b.z;
    return r;
}
vec3 ltc_cross(vec3 a, vec3 b) {
    precise vec3 r = vec3(a.y * b.z - b.y * a.z, a.z * b.x - b.z * a.x, a.x * b.y - b.x * a.y);
    return r;
}
vec3 ltc_mul(mat3 m, vec3 v) {
    precise vec3 r = vec3(m[0][0] * v.x + m[1][0] * v.y + m[2][0] * v.z, m[0][1] * v.x + m[1][1] * v.y + m[2][1] * v.z,
                          m[0][2] * v.x + m[1][2] * v.y + m[2][2] * v.z);
    return r;
}
float ltc_length(vec3 v) {
    precise float r = sqrt(ltc_dot(v, v));
    return r;
}

// rescale_pow2: v times the power of two that brings its largest |coordinate| into [1, 2).
vec3 ltc_rescale_pow2(vec3 v) {
    precise float m = max(max(abs(v.x), abs(v.y)), abs(v.z));
    if (!(m > 0.0)) return vec3(0.0);
    int e;
    frexp(m, e);  // m = f 2^e, f in [0.5, 1): ilogb(m) = e - 1
    return ldexp(v, ivec3(1 - e));
}

// safe_normalize: v / |v|, 0 for v = 0, without overflow or underflow of |v|^2.
vec3 ltc_safe_normalize(vec3 v) {
    precise float l2 = ltc_dot(v, v);
    if (l2 > 1e-30 && l2 < 1e30) {
        precise vec3 r = v * (1.0 / sqrt(l2));
        return r;
    }
    precise vec3 s = ltc_rescale_pow2(v);
    precise float s2 = ltc_dot(s, s);
    precise vec3 r = s2 > 0.0 ? s * (1.0 / sqrt(s2)) : s;
    return r;
}

// stable_cross: a x b = a x (b -+ a) for unit a, b, accurate relative to |a x b|.
vec3 ltc_stable_cross(vec3 a, vec3 b, float a_dot_b) {
    precise vec3 d = a_dot_b >= 0.0 ? b - a : b + a;
    precise vec3 r = ltc_cross(a, d);
    return r;
}

// detail::saturate: x clamped to [0, 1], NaN to 0.
float ltc_saturate(float x) { return x > 0.0 ? (x < 1.0 ? x : 1.0) : 0.0; }

// ---- ltc/core/edge_policy.hpp, edge_integral.hpp ------------------------------------------

// edge_policy::minimax_rational's fit of theta / sin(theta) at c = 1 - y >= 0.
float ltc_theta_over_sin_positive(float y) {
    precise float p = 0.999999965867 + y * (-0.44145776482 + y * (0.0170912151505 + y * 0.00123519700345));
    precise float q = 1.0 + y * (-0.774792977409 + y * 0.142038957683);
    precise float f = p / q;
    return f;
}

// edge_integral_z<minimax_rational>: the z component of eq. (11)'s edge term theta (a x b) / |a x b|;
// for c < 0, theta / sin = pi / s - f(-c) (symmetric_extension).
float ltc_edge_integral_z(vec3 a, vec3 b) {
    precise float c = ltc_dot(a, b);
    if (c >= 0.0) {
        precise float r = (a.x * (b.y - a.y) - a.y * (b.x - a.x)) * ltc_theta_over_sin_positive(1.0 - c);
        return r;
    }
    precise vec3 axb = ltc_stable_cross(a, b, c);
    precise float s = ltc_length(axb);
    precise float f = s > LTC_MIN_NORMAL ? LTC_PI / s - ltc_theta_over_sin_positive(1.0 + c) : 0.0;
    precise float r = axb.z * f;
    return r;
}

// ---- ltc/core/horizon_clip.hpp, form_factor.hpp --------------------------------------------

// horizon_crossing_direction, normalized: where in (z >= 0) -> out (z < 0) meets z = 0.
vec3 ltc_horizon_crossing(vec3 p_in, vec3 p_out) {
    precise vec3 x = p_in * (-p_out.z) + p_out * p_in.z;
    x.z = 0.0;
    return ltc_safe_normalize(x);
}

// stream_unit_edges' emit: the edge from the last vertex to x, or x the first vertex.
void ltc_emit(vec3 x, inout precise float sum, inout vec3 first, inout vec3 last, inout bool started) {
    if (started) sum += ltc_edge_integral_z(last, x);
    else first = x, started = true;
    last = x;
}

// detail::form_factor's general path (for_each_small_unit_edge): sum of the edge terms of the
// polygon raw[0..n) clipped to z >= 0 (Sutherland-Hodgman from the closing edge), over 2 pi: the
// signed integral of the clamped cosine, eq. (11). 0 for n < 3 or a vertex at the origin. The
// C++ takes its quad path for n = 4: the same integral, summed from other roundings.
float ltc_clamped_cosine_signed_integral(vec3 raw[LTC_MAX_VERTICES], int n) {
    if (n < 3) return 0.0;
    vec3 u[LTC_MAX_VERTICES];
    bool at_origin = false;
    int above = 0;
    for (int i = 0; i < n; ++i) {
        u[i] = ltc_safe_normalize(raw[i]);
        at_origin = at_origin || u[i] == vec3(0.0);
        above += u[i].z >= 0.0 ? 1 : 0;
    }
    precise float sum = 0.0;
    if (above == n) {
        for (int i = 0; i + 1 < n; ++i) sum += ltc_edge_integral_z(u[i], u[i + 1]);
        sum += ltc_edge_integral_z(u[n - 1], u[0]);
    } else if (above > 0) {
        vec3 first = vec3(0.0), last = vec3(0.0);
        bool started = false;
        vec3 p = u[n - 1];
        for (int i = 0; i < n; ++i) {
            const vec3 q = u[i];
            const bool p_in = p.z >= 0.0, q_in = q.z >= 0.0;
            if (p_in != q_in)
                ltc_emit(p_in ? ltc_horizon_crossing(p, q) : ltc_horizon_crossing(q, p), sum, first, last, started);
            if (q_in) ltc_emit(q, sum, first, last, started);
            p = q;
        }
        if (started) sum += ltc_edge_integral_z(last, first);
    }
    if (at_origin) return 0.0;  // seen edge-on
    precise float r = sum / (2.0 * LTC_PI);
    return r;
}

// apply_sidedness: one-sided max(s, 0), two-sided |s|.
float ltc_apply_sidedness(float s, bool two_sided) { return two_sided ? abs(s) : (s > 0.0 ? s : 0.0); }

// ---- ltc/shading/shading_frame.hpp ---------------------------------------------------------

// orthonormal_tangent: Duff et al. 2017, listing 3 (copysign(1, n.z) from the sign bit).
vec3 ltc_orthonormal_tangent(vec3 n) {
    const float sign = (floatBitsToUint(n.z) & 0x80000000u) != 0u ? -1.0 : 1.0;
    precise float a = -1.0 / (sign + n.z);
    precise vec3 t = vec3(1.0 + sign * n.x * n.x * a, sign * n.x * n.y * a, -sign * n.x);
    return t;
}

// make_shading_frame: N = +z, T1 = normalize(N x (V x N)) (cancellation-free), T2 = N x T1,
// cos theta_v = clamp(N.V, 0, 1); V parallel to N: Duff's tangent; N = 0: invalid.
ltc_shading_frame ltc_make_shading_frame(vec3 N, vec3 V) {
    ltc_shading_frame f = ltc_shading_frame(vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1), 1.0, true);
    const vec3 n = ltc_safe_normalize(N);
    if (n == vec3(0.0)) {
        f.valid = false;
        return f;
    }
    const vec3 v = ltc_safe_normalize(V);
    precise float nv = ltc_dot(n, v);
    precise vec3 w = ltc_stable_cross(v, n, nv);
    vec3 t1 = ltc_safe_normalize(ltc_cross(n, w));
    if (t1 == vec3(0.0)) t1 = ltc_orthonormal_tangent(n);
    f.n = n;
    f.t1 = t1;
    f.t2 = ltc_cross(n, t1);
    f.cos_theta_v = clamp(nv, 0.0, 1.0);
    return f;
}

// shading_frame::to_local: (d.T1, d.T2, d.N).
vec3 ltc_to_local(ltc_shading_frame f, vec3 d) {
    return vec3(ltc_dot(d, f.t1), ltc_dot(d, f.t2), ltc_dot(d, f.n));
}

// ---- ltc/tables/ltc_table.hpp, ltc/shading/ggx_cosine_lobe_fetch.hpp -------------------------

// detail::axis_position: node i0 in [0, n - 2] and weight f of s (node units), s snapped to the
// nearest node within `tolerance`.
void ltc_axis_position(float s, float tolerance, out int i0, out float f) {
    const float nearest = floor(s + 0.5);
    precise float off = s - nearest;
    if (abs(off) <= tolerance) s = nearest;
    i0 = min(int(s), LTC_TABLE_SIZE - 2);
    precise float w = s - float(i0);
    f = w;
}

// ltc_table::interpolate, channel c of a lobe: (1 - f) v0 + f v1 along u, then along roughness.
float ltc_interpolate(int lobe, int c, int t0, int a0, float fu, float fv) {
    precise float lo = (1.0 - fu) * ltc_table_node(lobe, t0, a0, c) + fu * ltc_table_node(lobe, t0 + 1, a0, c);
    precise float hi = (1.0 - fu) * ltc_table_node(lobe, t0, a0 + 1, c) + fu * ltc_table_node(lobe, t0 + 1, a0 + 1, c);
    precise float r = (1.0 - fv) * lo + fv * hi;
    return r;
}

// ggx::ltc_and_cosine::fetch: ltc_table::locate (u = sqrt(1 - cos theta_v), v = roughness, the
// snap tolerances), the cosine's magnitude and Fresnel (fetch_scale_at) and the LTC's channels,
// its matrix premultiplied by its magnitude in the table (unpremultiplied).
ltc_lobes ltc_fetch_lobes(float cos_theta_v, float roughness) {
    const float c = ltc_saturate(cos_theta_v);
    precise float u = sqrt(1.0 - c);
    const float v = ltc_saturate(roughness);
    const float w1 = float(LTC_TABLE_SIZE - 1);
    precise float su = u * w1;
    precise float sv = v * w1;
    precise float tol_u = LTC_EPSILON * (w1 * w1 / (su > 1.0 ? su : 1.0) + 2.0 * su);
    precise float tol_v = 4.0 * LTC_EPSILON * sv;
    int t0, a0;
    float fu, fv;
    ltc_axis_position(su, tol_u, t0, fu);
    ltc_axis_position(sv, tol_v, a0, fv);
    ltc_lobes r;
    r.cosine = ltc_coefficients(mat3(1.0), ltc_interpolate(0, 4, t0, a0, fu, fv), ltc_interpolate(0, 5, t0, a0, fu, fv));
    float m[4];
    for (int k = 0; k < 4; ++k) m[k] = ltc_interpolate(1, k, t0, a0, fu, fv);
    const float magnitude = ltc_interpolate(1, 4, t0, a0, fu, fv);
    r.ltc = ltc_coefficients(mat3(1.0), magnitude, ltc_interpolate(1, 5, t0, a0, fu, fv));
    if (magnitude > 0.0) {
        precise float m00 = m[0] / magnitude, m02 = m[1] / magnitude, m20 = m[2] / magnitude, m22 = m[3] / magnitude;
        r.ltc.m_inv = mat3(m00, 0.0, m02, 0.0, 1.0, 0.0, m20, 0.0, m22);  // GLSL/GLM: m[column][row]
    }
    return r;
}

// brdf_scale: F0 magnitude + (1 - F0) fresnel (Hill 2016's Fresnel split).
vec3 ltc_brdf_scale(vec3 f0, ltc_coefficients c) {
    precise vec3 r = f0 * c.magnitude + (vec3(1.0) - f0) * c.fresnel;
    return r;
}

// ---- ltc/shading/lights/polygon_light.hpp ------------------------------------------------

// polygon_light::one_sided(vertices, n, emission_normal, radiance): emits towards the side the
// normal points to; the C++ throws for a zero, non-finite or in-plane normal: here, no vertices.
ltc_polygon_light ltc_one_sided_light(vec3 vertices[LTC_MAX_VERTICES], int n, vec3 emission_normal, vec3 radiance) {
    precise vec3 area = vec3(0.0);  // detail::vector_area_x2 (Newell's method about vertex 0)
    for (int i = 1; i + 1 < n; ++i) area += ltc_cross(vertices[i] - vertices[0], vertices[i + 1] - vertices[0]);
    precise vec3 z = emission_normal - emission_normal;
    precise float zs = z.x + z.y + z.z;
    precise float facing = ltc_dot(area, emission_normal);
    const bool bad_normal = !(zs == 0.0) || emission_normal == vec3(0.0);
    const bool in_plane = area != vec3(0.0) && !(facing != 0.0);
    return ltc_polygon_light(bad_normal || in_plane ? 0 : n, facing > 0.0, false, radiance);
}

// polygon_light::one_sided(vertices, n, winding, radiance): the front the convention names.
ltc_polygon_light ltc_one_sided_light_wound(int n, bool counter_clockwise_front, vec3 radiance) {
    return ltc_polygon_light(n, counter_clockwise_front, false, radiance);
}

// polygon_light::two_sided.
ltc_polygon_light ltc_two_sided_light(int n, vec3 radiance) { return ltc_polygon_light(n, false, true, radiance); }

// ---- ltc/shading/polygon_light_integrals.hpp, lobes.hpp, shade.hpp -------------------------

// integrate_polygon_light_at, ltc_space: the form factor E and the LTC integral I_ltc (eq. 3
// through M^-1, negated for det M^-1 < 0), each sided. Vertices in the light's walking order,
// relative to P, divided by their largest coordinate (detail::rescaled), in the frame.
vec2 ltc_polygon_integrals(ltc_shading_frame f, vec3 P, mat3 m_inv, vec3 vertices[LTC_MAX_VERTICES],
                           ltc_polygon_light light) {
    const int n = light.count;
    if (!f.valid || n < 3) return vec2(0.0);
    vec3 local[LTC_MAX_VERTICES], lobe[LTC_MAX_VERTICES];
    for (int i = 0; i < n; ++i) {
        precise vec3 d = vertices[light.reversed ? n - 1 - i : i] - P;
        precise float s = max(max(abs(d.x), abs(d.y)), abs(d.z));
        precise vec3 r = s > 0.0 ? d / s : vec3(0.0);
        local[i] = ltc_to_local(f, r);
        lobe[i] = ltc_mul(m_inv, local[i]);
    }
    const float e = ltc_clamped_cosine_signed_integral(local, n);
    const float s = ltc_clamped_cosine_signed_integral(lobe, n);
    const float i_ltc = determinant(m_inv) < 0.0 ? -s : s;
    return vec2(ltc_apply_sidedness(e, light.two_sided), ltc_apply_sidedness(i_ltc, light.two_sided));
}

// shade_lobes(p, lobes::ltc_and_cosine, light): specular = L (brdf_scale(ltc) I_ltc +
// brdf_scale(cosine) E), diffuse = L albedo E.
ltc_shading_result ltc_shade_lobes(ltc_shading_frame f, ltc_surface s, ltc_lobes c, vec3 vertices[LTC_MAX_VERTICES],
                                   ltc_polygon_light light) {
    const vec2 I = ltc_polygon_integrals(f, s.position, c.ltc.m_inv, vertices, light);
    precise vec3 specular = light.radiance * ltc_brdf_scale(s.f0, c.ltc) * I.y;
    precise vec3 diffuse = light.radiance * s.albedo * I.x;
    specular += light.radiance * ltc_brdf_scale(s.f0, c.cosine) * I.x;
    return ltc_shading_result(specular, diffuse);
}

// shade<ggx::ltc_and_cosine>(s, light): 0 for a non-finite position, normal or view, or a zero
// normal or view; else the frame, the lobes at (cos theta_v, roughness) and their shading.
ltc_shading_result ltc_shade(ltc_surface s, vec3 vertices[LTC_MAX_VERTICES], ltc_polygon_light light) {
    const ltc_shading_result none = ltc_shading_result(vec3(0.0), vec3(0.0));
    precise vec3 z = (s.position - s.position) + (s.normal - s.normal) + (s.view - s.view);
    precise float zs = z.x + z.y + z.z;
    if (!(zs == 0.0) || s.view == vec3(0.0)) return none;
    const ltc_shading_frame f = ltc_make_shading_frame(s.normal, s.view);
    if (!f.valid) return none;
    return ltc_shade_lobes(f, s, ltc_fetch_lobes(f.cos_theta_v, s.roughness), vertices, light);
}

#endif  // LTC_GLSL_SHADE
