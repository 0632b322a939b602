// common/pinhole.hpp -- the renderers' pinhole camera (render, shadows): z up, no roll, one ray
// through each pixel centre (no antialiasing: every method of a comparison shades the same points).
#pragma once

#include "math.hpp"

#include <glm/glm.hpp>

#include <cmath>

namespace ltc_examples {

class pinhole {
  public:
    /// A camera at `eye` looking at `target`, vfov_deg the vertical field of view, for an image of
    /// width x height pixels.
    pinhole(const vec3& eye, const vec3& target, float vfov_deg, int width, int height)
        : forward_(glm::normalize(target - eye)),
          right_(glm::normalize(glm::cross(forward_, vec3(0, 0, 1)))),
          up_(glm::cross(right_, forward_)),
          h_(std::tan(0.5f * vfov_deg * static_cast<float>(deg))),
          w_(h_ * static_cast<float>(width) / static_cast<float>(height)),
          width_(width),
          height_(height) {}

    /// The unit direction of the ray through the centre of pixel (x, y), row 0 at the top.
    vec3 direction(int x, int y) const {
        const float sx = (2.0f * (static_cast<float>(x) + 0.5f) / static_cast<float>(width_) - 1.0f) * w_;
        const float sy = (1.0f - 2.0f * (static_cast<float>(y) + 0.5f) / static_cast<float>(height_)) * h_;
        return glm::normalize(forward_ + sx * right_ + sy * up_);
    }

    /// The unit vectors of the view and of the image's rows and columns, and a pixel's side on the
    /// image plane at unit distance along forward().
    const vec3& forward() const { return forward_; }
    const vec3& right() const { return right_; }
    const vec3& up() const { return up_; }
    float pixel_size() const { return 2.0f * h_ / static_cast<float>(height_); }

  private:
    vec3 forward_, right_, up_;
    float h_, w_;  // half the image plane's height and width at unit distance
    int width_, height_;
};

}  // namespace ltc_examples
