// shadows/filter_settings.hpp -- what the command line sets of (d)'s and (e)'s filter
// (denoise.hpp), apart from the filter itself so that the options need not see Embree.
#pragma once

namespace shadows {

/// The radius (-1: auto_radius(K)), (d)'s LTC correction (ltc::corrected_specular), and (d)'s
/// radius per pixel from the penumbra's width there (penumbra_radii; at most the radius).
struct filter_settings {
    int radius = -1;
    bool ltc_correction = true;
    bool penumbra = true;
};

}  // namespace shadows
