// ltc/fitting/fit.hpp -- fitting Linearly Transformed Cosines to a BRDF (paper section 4), and whole
// tables of them (the paper's 64 x 64 GGX table, or any BRDF model of ltc/brdf/model.hpp).
//
//   #include <ltc/fitting/fit.hpp>
//   #include <ltc/brdf/ggx.hpp>
//   ltc::fit::options opt;                                   // 64 x 64, all cores
//   ltc::fit::table tab = ltc::fit::fit_table<ltc::brdf::ggx>(opt);
//   std::vector<float> data = tab.packed();                  // the layout of ltc/tables/ltc_table.hpp
//   ltc::ltc_table view(data.data(), tab.size, tab.size);    // then view.fetch(cos, roughness)
//   std::string text = ltc::fit::table_header_text("ggx", "GGX", tab, opt);  // as ltc/tables/ggx.hpp
//
// f(L) = rho(V, L) cos(theta_L) ~= magnitude * D(L), D the LTC of M = R [m11 0 m13; 0 m22 0; m31 0 1]
// (ltc_parameters), V = (sin theta_v, 0, cos theta_v) in the local frame N = +z. All in double and
// deterministic: the same binary gives the same table bit for bit, whatever the thread count. The
// pieces, each of which can be included on its own: the includes below.
#pragma once

// The pieces, each of which can be included on its own, and each documents its part of the method:
//   ltc/fitting/options.hpp         options (the fit's settings); the coordinates of a table's nodes
//   ltc/fitting/ltc_parameters.hpp  the fitted matrix M (what is fitted) and the fit's own arithmetic on it
//   ltc/fitting/moments.hpp         per-node magnitude, Fresnel term and average direction
//   ltc/fitting/error_metric.hpp    the L3 error, by MIS over frozen samples; measure_error
//   ltc/fitting/nelder_mead.hpp     the minimizer
//   ltc/fitting/fit_node.hpp        fitting one node (fit_node)
//   ltc/fitting/integral_objective.hpp, fit_integrals.hpp  the opt-in objective of options::goal:
//                                   relative error of integrals over a fixed family of polygons
//   ltc/fitting/fit_table.hpp       fitting a whole table on std::threads (fit_table)
//   ltc/fitting/fit_two_lobes.hpp   nodes and tables of two lobes
//   ltc/fitting/table_writer.hpp    a fitted table as a C++ header (table_header_text)
//
// The fit's arithmetic lives in these headers (its own 3x3 inverse, cosine sampler and
// normalization: ltc/fitting/ltc_parameters.hpp) and in the BRDF model, so that changes elsewhere
// in the library do not move the bits of a generated table.
#include <ltc/brdf/model.hpp>
#include <ltc/fitting/options.hpp>
#include <ltc/fitting/ltc_parameters.hpp>
#include <ltc/fitting/moments.hpp>
#include <ltc/fitting/error_metric.hpp>
#include <ltc/fitting/nelder_mead.hpp>
#include <ltc/fitting/integral_objective.hpp>
#include <ltc/fitting/fit_integrals.hpp>
#include <ltc/fitting/fit_node.hpp>
#include <ltc/fitting/fit_table.hpp>
#include <ltc/fitting/fit_two_lobes.hpp>
#include <ltc/fitting/table_writer.hpp>
#include <ltc/config.hpp>
#include <ltc/detail/math.hpp>
#include <ltc/tables/ltc_table.hpp>
