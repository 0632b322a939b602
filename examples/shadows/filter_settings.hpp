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

    /// Whether (d) records blockers and takes the penumbra's radii at the resolved radius R: only
    /// where there is a filter (R >= 1).
    bool penumbra_at(int radius) const { return penumbra && radius > 0; }
};

}  // namespace shadows
