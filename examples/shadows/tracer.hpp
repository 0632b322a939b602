// shadows/tracer.hpp -- the scene in Embree 3: the floor, the occluders and the light, each a
// triangle geometry of one RTCScene; closest hits (camera rays, BRDF-sampled rays, the shadow rays
// of (d) whose blockers it records: first_occluder) by rtcIntersect1 and the other shadow rays by
// rtcOccluded1, with the ray offsets of the file comment below.
//
// Offsets. Scene coordinates are at most ~10 units, so a hit point org + t dir carries a float
// rounding error of about 10 * 2^-24 ~ 1e-6 units. Rays leave a surface from P + surface_offset N
// (N facing the side the ray goes to: every ray here leaves towards the light or along a sampled
// direction above the surface): 1e-4, a hundred times that error, and well below a pixel's
// footprint (~0.02 units), so the only shadow it can miss is of geometry within 1e-4 of P (the
// box's base line). Shadow rays towards a point of the light stop light_margin = 1e-3 short of
// it: the light is a triangle of the same scene and must not occlude itself; 1e-3 exceeds the
// offset plus the rounding of t (~1e-6 * t) tenfold, and no occluder comes within 1 unit of the
// light.
#pragma once

#include "scene.hpp"

#include <embree3/rtcore.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace shadows {

constexpr float surface_offset = 1e-4f;
constexpr float light_margin = 1e-3f;

/// What a ray hit first.
struct ray_hit {
    enum kind_t { none, floor, occluder, light } kind = none;
    float t = 0;
    vec3 ng{0.0f};  // geometric normal, unit, as stored (not flipped)
};

class tracer {
  public:
    explicit tracer(const scene& s) {
        device_ = rtcNewDevice(nullptr);
        if (device_ == nullptr) throw std::runtime_error("rtcNewDevice failed");
        const auto report = [](void*, RTCError code, const char* what) {
            std::fprintf(stderr, "embree error %d: %s\n", static_cast<int>(code), what);
        };
        rtcSetDeviceErrorFunction(device_, report, nullptr);
        try {
            scene_ = rtcNewScene(device_);
            rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
            // Robust: no ray slips through the shared edge of two triangles (the floor's
            // diagonal, the panel's strips), which a shadow ray would count as light.
            rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
            floor_id_ = attach(s.floor);
            occluder_id_ = attach(s.occluders);
            light_id_ = attach(s.emitter);
            rtcCommitScene(scene_);
            if (rtcGetDeviceError(device_) != RTC_ERROR_NONE) throw std::runtime_error("cannot build the Embree scene");
        } catch (...) {
            release();
            throw;
        }
    }
    ~tracer() { release(); }
    tracer(const tracer&) = delete;
    tracer& operator=(const tracer&) = delete;

    /// The first hit along org + t dir, t in (0, tfar]. dir need not be unit (t is in its units).
    ray_hit intersect(const vec3& org, const vec3& dir, float tfar = std::numeric_limits<float>::infinity()) const {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRayHit rh;
        set_ray(rh.ray, org, dir, tfar);
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene_, &context, &rh);
        ray_hit h;
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return h;
        h.kind = rh.hit.geomID == floor_id_   ? ray_hit::floor
                 : rh.hit.geomID == light_id_ ? ray_hit::light
                                              : ray_hit::occluder;
        h.t = rh.ray.tfar;
        h.ng = glm::normalize(vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z));
        return h;
    }

    /// True if nothing blocks org + t dir for t in (0, tfar].
    bool unoccluded(const vec3& org, const vec3& dir, float tfar) const {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRay ray;
        set_ray(ray, org, dir, tfar);
        rtcOccluded1(scene_, &context, &ray);
        return ray.tfar >= 0;  // set to -inf when occluded
    }

    /// The shadow ray of the LTC methods: from P (offset along N, the normal facing the light's
    /// side) along the unit direction, stopping light_margin before the light's plane.
    bool light_visible(const vec3& P, const vec3& N, const vec3& unit_direction, float distance) const {
        const shadow_ray r(P, N, distance);
        return r.tfar <= 0 || unoccluded(r.origin, unit_direction, r.tfar);
    }

    /// The same ray as one closest-hit query: the first occluder's distance from the offset
    /// origin, +inf where light_visible is true (for ltc::first_hit: a distance below `distance`
    /// is an occluded sample).
    float first_occluder(const vec3& P, const vec3& N, const vec3& unit_direction, float distance) const {
        const shadow_ray r(P, N, distance);
        const ray_hit h = r.tfar <= 0 ? ray_hit{} : intersect(r.origin, unit_direction, r.tfar);
        return h.kind == ray_hit::none ? std::numeric_limits<float>::infinity() : h.t;
    }

  private:
    /// A shadow ray's offset origin and range (the file comment's offsets); tfar <= 0: none.
    struct shadow_ray {
        shadow_ray(const vec3& P, const vec3& N, float distance)
            : origin(P + surface_offset * N), tfar(distance - light_margin) {}
        vec3 origin;
        float tfar;
    };

    unsigned attach(const mesh& m) {
        RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                              3 * sizeof(float), m.vertices.size()));
        auto* i = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                 3 * sizeof(unsigned), m.indices.size() / 3));
        if (v == nullptr || i == nullptr) {
            rtcReleaseGeometry(g);
            throw std::runtime_error("cannot allocate an Embree buffer");
        }
        for (std::size_t k = 0; k < m.vertices.size(); ++k)
            v[3 * k] = m.vertices[k].x, v[3 * k + 1] = m.vertices[k].y, v[3 * k + 2] = m.vertices[k].z;
        std::memcpy(i, m.indices.data(), m.indices.size() * sizeof(unsigned));
        rtcCommitGeometry(g);
        const unsigned id = rtcAttachGeometry(scene_, g);
        rtcReleaseGeometry(g);  // the scene holds it
        return id;
    }

    void release() {
        if (scene_ != nullptr) rtcReleaseScene(scene_);
        if (device_ != nullptr) rtcReleaseDevice(device_);
        scene_ = nullptr, device_ = nullptr;
    }

    static void set_ray(RTCRay& r, const vec3& org, const vec3& dir, float tfar) {
        r.org_x = org.x, r.org_y = org.y, r.org_z = org.z;
        r.dir_x = dir.x, r.dir_y = dir.y, r.dir_z = dir.z;
        r.tnear = 0.0f;  // the origin is already offset off the surface
        r.tfar = tfar;
        r.time = 0.0f;
        r.mask = ~0u;
        r.id = 0;
        r.flags = 0;
    }

    RTCDevice device_ = nullptr;
    RTCScene scene_ = nullptr;
    unsigned floor_id_ = 0, occluder_id_ = 0, light_id_ = 0;
};

}  // namespace shadows
