// ltc/shading/batch_lobe_set.hpp -- what the batch kernels of ltc::batch::shade
// (ltc/shading/batch_shade.hpp) know of a material model's lobe set, read from the type of its
// coefficients (ltc/shading/lobes.hpp): one trait, lobe_set<Coefficients>, for the point kernel
// (which tables the lanes read and how their lobes add up) and for the lights kernel (the lobes'
// coefficients once per point).
//
//   using set = ltc::batch::lobe_set<ltc::lobes::two<float>>;
//   set::tables == 2, set::cosine == false, set::ltc_count == 2;
//   const auto ltcs = set::ltcs(c);           // the LTCs of c, one integral each (eq. 3)
//
// Each point's specular term is sum over lobes (F0 magnitude + (1 - F0) fresnel) I_lobe, lobe by
// lobe in the order of the model's tables, as ltc::shade_lobes forms it (lobe_set: the order and
// layout of the tables).
#pragma once

#include <ltc/config.hpp>
#include <ltc/shading/lobes.hpp>
#include <ltc/tables/ltc_table.hpp>

#include <array>

LTC_NAMESPACE_BEGIN
namespace batch {

/// The batch kernels' view of a lobe set (file comment); defined for the three of lobes.hpp.
/// The tables of a model (ltc::batch::model_tables, ltc/shading/batch_shade.hpp) come in the
/// order and layout the trait names:
///   lobes::one            1 table: the LTC
///   lobes::ltc_and_cosine 2 tables: the clamped cosine's (its magnitude and Fresnel term; its
///                         integral is the form factor E, eq. 11), then the LTC's with its four
///                         M^-1 channels premultiplied by its magnitude (the layout of
///                         ltc/fitting/fit_two_lobes.hpp's packed() for this model, divided out
///                         as ggx_cosine_lobe::unpremultiplied does)
///   lobes::two            2 tables: one LTC each
/// and each point's specular term adds the lobes' terms in that order.
template <typename Coefficients>
struct lobe_set;

template <typename T>
struct lobe_set<lobes::one<T>> {
    static constexpr int tables = 1;             ///< tables the lanes read
    static constexpr bool cosine = false;        ///< table 0 is the clamped cosine's
    static constexpr bool premultiplied = false; ///< the LTCs' M^-1 stored times their magnitude
    static constexpr int ltc_count = 1;          ///< LTC integrals per point
    static std::array<ltc_coefficients<T>, 1> ltcs(const lobes::one<T>& c) { return {c.ltc}; }
};

template <typename T>
struct lobe_set<lobes::ltc_and_cosine<T>> {
    static constexpr int tables = 2;
    static constexpr bool cosine = true;
    static constexpr bool premultiplied = true;
    static constexpr int ltc_count = 1;
    static std::array<ltc_coefficients<T>, 1> ltcs(const lobes::ltc_and_cosine<T>& c) { return {c.ltc}; }
    /// The cosine's magnitude and Fresnel term (its integral is E).
    static const ltc_coefficients<T>& cosine_lobe(const lobes::ltc_and_cosine<T>& c) { return c.cosine; }
};

template <typename T>
struct lobe_set<lobes::two<T>> {
    static constexpr int tables = 2;
    static constexpr bool cosine = false;
    static constexpr bool premultiplied = false;
    static constexpr int ltc_count = 2;
    static std::array<ltc_coefficients<T>, 2> ltcs(const lobes::two<T>& c) { return {c.first, c.second}; }
};

}  // namespace batch
LTC_NAMESPACE_END
