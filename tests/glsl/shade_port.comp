#version 450
// tests/test_glsl_port.cpp's shader: include/ltc/glsl/ltc_shade.glsl over the points and lights
// the test uploads, one invocation per point; its stages (the frame and the lobes) and, for every
// light, ltc_shade_lobes at that frame and those lobes and ltc_shade itself. Layouts: the test's.
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 0) readonly buffer Table { float table[]; };  // ggx_cosine_lobe_data
float ltc_table_node(int lobe, int t, int a, int c) { return table[((lobe * 32 + a) * 32 + t) * 6 + c]; }

#include "ltc/glsl/ltc_shade.glsl"

// 16 floats a point: position, normal, view, roughness, f0, albedo.
layout(std430, set = 0, binding = 1) readonly buffer Points { float points[]; };
// 44 floats a light: count, kind (0 one-sided towards a normal, 1 clockwise front, 2 counter-
// clockwise front, 3 two-sided), 2 unused; radiance, 1 unused; emission normal, 1 unused; 8 vertices
// of 4 floats (the fourth unused).
layout(std430, set = 0, binding = 2) readonly buffer Lights { float lights[]; };
// A point's 20 floats (t1, t2, n, cos theta_v, valid, the LTC's m00 m02 m20 m22 magnitude fresnel,
// the cosine's magnitude and fresnel, 1 unused), then 12 a light (shade_lobes' specular and diffuse, then
// ltc_shade's).
layout(std430, set = 0, binding = 3) writeonly buffer Results { float results[]; };
layout(push_constant) uniform Counts { int point_count; int light_count; };

vec3 load3(int i) { return vec3(points[i], points[i + 1], points[i + 2]); }
vec3 light3(int i) { return vec3(lights[i], lights[i + 1], lights[i + 2]); }
void store3(int i, vec3 v) { results[i] = v.x, results[i + 1] = v.y, results[i + 2] = v.z; }

void main() {
    const int p = int(gl_GlobalInvocationID.x);
    if (p >= point_count) return;
    const int b = 16 * p;
    const ltc_surface s = ltc_surface(load3(b), load3(b + 3), load3(b + 6), points[b + 9], load3(b + 10), load3(b + 13));
    const ltc_shading_frame f = ltc_make_shading_frame(s.normal, s.view);
    const ltc_lobes c = ltc_fetch_lobes(f.cos_theta_v, s.roughness);
    const int o = p * (20 + 12 * light_count);
    store3(o, f.t1), store3(o + 3, f.t2), store3(o + 6, f.n);
    results[o + 9] = f.cos_theta_v, results[o + 10] = f.valid ? 1.0 : 0.0;
    results[o + 11] = c.ltc.m_inv[0][0], results[o + 12] = c.ltc.m_inv[0][2];
    results[o + 13] = c.ltc.m_inv[2][0], results[o + 14] = c.ltc.m_inv[2][2];
    results[o + 15] = c.ltc.magnitude, results[o + 16] = c.ltc.fresnel;
    results[o + 17] = c.cosine.magnitude, results[o + 18] = c.cosine.fresnel, results[o + 19] = 0.0;
    for (int l = 0; l < light_count; ++l) {
        const int a = 44 * l;
        const int n = int(lights[a]), kind = int(lights[a + 1]);
        vec3 v[LTC_MAX_VERTICES];
        for (int i = 0; i < LTC_MAX_VERTICES; ++i) v[i] = light3(a + 12 + 4 * i);
        const vec3 radiance = light3(a + 4);
        const ltc_polygon_light light =
            kind == 0 ? ltc_one_sided_light(v, n, light3(a + 8), radiance)
                      : kind == 3 ? ltc_two_sided_light(n, radiance) : ltc_one_sided_light_wound(n, kind == 2, radiance);
        const ltc_shading_result staged = ltc_shade_lobes(f, s, c, v, light);
        const ltc_shading_result whole = ltc_shade(s, v, light);
        const int r = o + 20 + 12 * l;
        store3(r, staged.specular), store3(r + 3, staged.diffuse);
        store3(r + 6, whole.specular), store3(r + 9, whole.diffuse);
    }
}
