// ltc/core/polygon.hpp -- exact integrals over spherical polygons, and horizon clipping: the
// polygon machinery of the library, usable on its own (conventions in full below):
//   - clip_to_horizon:        Sutherland-Hodgman clipping of an n-gon to the half-space z >= 0;
//   - edge_integral:          the exact edge term of the paper's eq. (11) (Baum et al. 1989);
//   - vector_form_factor:     F = 1/(2 pi) sum of edge terms, the "vector irradiance" of the
//                             unclipped polygon (input of the horizon-clipping approximations);
//   - form_factor:            the clamped-cosine integral of the clipped polygon, eq. (11),
//                             signed, one-sided (max(0, sum)) or two-sided (abs(sum));
//   - solid_angle / clipped_solid_angle: signed solid angles (Van Oosterom & Strackee 1983).
//
// Conventions: n >= 3 vertices (any scale) of a simple planar polygon seen from the shading point
// at the origin, z the normal; signed results positive when the vertices turn clockwise as seen
// from the origin. Degenerate cases: never NaN or Inf for finite vertices; 0 for n < 3, a vertex
// at the origin, or a polygon below the horizon (clipped integrals).
#pragma once

// Conventions. A polygon is given by n >= 3 vertices (any scale, not necessarily unit) of a
// simple planar polygon, seen from the shading point at the origin; z is the normal of the
// shading frame. Signed results are positive when the vertices turn clockwise as seen from the
// origin, i.e. when dot(p, sum_i p_i x p_i+1) > 0 for any point p of the polygon's plane: the
// polygon's vector area points away from the shading point (for a convex polygon,
// dot(p0, (p1 - p0) x (p2 - p0)) > 0 says the same). Non-convex polygons are handled: every
// result integrates over the winding number of the boundary, which is the polygon's indicator
// for a simple polygon.
//
// Degenerate input never yields NaN or Inf for finite vertices:
//   - n < 3, or a vertex exactly at the origin (then the polygon's plane contains the shading
//     point and the polygon is seen edge-on): every integral is 0;
//   - repeated or collinear vertices: zero-length edges contribute exactly 0;
//   - an edge whose line passes through the origin has no defined great circle: it contributes 0;
//   - a polygon entirely below the horizon clips to nothing: clipped integrals are 0.
//
// Speed. The clamped-cosine integral of a quad (the common light shape) takes a path of its own:
// clipped before normalization by a switch on the vertices above the horizon, as the paper's
// shader does, then five edge terms without a branch on the vertex count; other polygons, and
// the quads whose degenerate cases need care, take a streaming clipper on unit vertices. The
// edge policies (edge_policy) trade the exact atan2 for float-accurate fits.

#include <ltc/core/edge_integral.hpp>    // edge_integral, edge_integral_z
#include <ltc/core/edge_policy.hpp>      // edge_policy::exact, minimax_rational, polynomial, ...
#include <ltc/core/form_factor.hpp>      // vector_form_factor, form_factor_signed, form_factor
#include <ltc/core/horizon_clip.hpp>     // clipped_capacity, clip_to_horizon
#include <ltc/core/quad_path.hpp>        // the quad fast path of form_factor
#include <ltc/core/sidedness.hpp>        // sidedness, apply_sidedness
#include <ltc/core/solid_angle.hpp>      // triangle_solid_angle, solid_angle, clipped_solid_angle
