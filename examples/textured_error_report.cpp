// examples/textured_error_report.cpp -- how good is the textured-light approximation of the
// paper's sections 5.2-5.4 (I = I_D I_L with I_L one prefiltered fetch)? Prints relative
// errors against Monte Carlo ground truth (ltc/reference/textured_ground_truth.hpp) and the prefilter's
// timing for a 1024 x 1024 image.
//
// Configurations (all combinations; the shading point at the origin, N = +z, V = (sin theta_v,
// 0, cos theta_v)):
//   lobe          the clamped cosine (diffuse, M = I) and GGX at roughness 0.1, 0.25, 0.5, 1
//                 (alpha = roughness^2; the shipped table's M^-1)
//   view angle    theta_v = 0, 30, 60, 80 degrees
//   light         a 1 x 1 square whose centre is at distance 0.5, 1.5 or 4 in the direction of
//                 elevation 45 deg on the mirror side (azimuth 180 deg), facing the shading
//                 point, tilted by 60 deg about its horizontal axis, or vertical (normal
//                 horizontal, pointing to the shading point's side)
//   texture       64 x 64 texels: "gradient" (u, v, 1 - u v), "checker" (4 x 4-texel cells,
//                 0.05 and 1, 256 cells: high frequency), "bright detail" (0.02 background,
//                 a 3 x 3-texel patch of 100 at uv ~ (0.7, 0.35): 17% of the energy in 0.2% of
//                 the area)
// Errors (configurations whose exact I_D >= 1e-4 only; RGB summed before the ratio):
//   texture   |I_D I_L - MC[int L D]| / MC[int L D]: the approximation of eq. (12) alone
//             (D is the LTC itself, so the fit of the BRDF plays no part)
//   shading   |magnitude I_D I_L - MC[int L rho cos]| / MC[...]: what a renderer gets (GGX fit
//             error included; for the diffuse lobe the two are the same)
//   fit only  the same with the constant texture 1 (the untextured LTC error, for scale)
// MC: 2^15 iterations each (lobe sampling + area sampling proportional to the texture's
// luminance, mixed with uniform; MIS); the mean relative standard
// error is printed next to the table so that the errors can be told from noise.
#include <ltc/fitting/brdf/ggx.hpp>
#include <ltc/shading/ggx_fetch.hpp>
#include <ltc/shading/light_texture.hpp>
#include <ltc/shading/textured_light.hpp>
#include <ltc/reference/textured_ground_truth.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

using dvec3 = glm::dvec3;
constexpr double pi = 3.141592653589793;

struct image {
    std::string name;
    int w = 64, h = 64;
    std::vector<dvec3> px;
};

image make_texture(int which) {
    image im;
    im.px.resize(std::size_t(im.w) * im.h);
    for (int y = 0; y < im.h; ++y)
        for (int x = 0; x < im.w; ++x) {
            const double u = (x + 0.5) / im.w, v = (y + 0.5) / im.h;
            dvec3 c;
            if (which == 0) {
                c = dvec3(u, v, 1 - u * v);
            } else if (which == 1) {
                c = dvec3(((x / 4 + y / 4) % 2) ? 1.0 : 0.05);
            } else {
                c = dvec3(0.02);
                if (x >= 44 && x < 47 && y >= 21 && y < 24) c = dvec3(100.0, 80.0, 60.0);
            }
            im.px[std::size_t(y) * im.w + x] = c;
        }
    im.name = which == 0 ? "gradient" : which == 1 ? "checker" : "bright detail";
    return im;
}

struct stats {
    std::vector<double> v;
    void add(double x) { v.push_back(x); }
    double mean() const {
        double s = 0;
        for (double x : v) s += x;
        return v.empty() ? 0 : s / v.size();
    }
    double pct(double p) const {
        if (v.empty()) return 0;
        std::vector<double> s = v;
        std::sort(s.begin(), s.end());
        return s[std::min(s.size() - 1, std::size_t(p * (s.size() - 1) + 0.5))];
    }
    double max() const { return v.empty() ? 0 : *std::max_element(v.begin(), v.end()); }
};

double sum(const dvec3& c) { return c.x + c.y + c.z; }

struct worst {
    double err;
    std::string what;
};

}  // namespace

int main() {
    const double roughs[] = {-1, 0.1, 0.25, 0.5, 1.0};  // -1: the diffuse lobe (M = I)
    const double views[] = {0, 30, 60, 80};
    const double dists[] = {0.5, 1.5, 4};
    const char* orient_names[] = {"facing", "tilted 60", "vertical"};
    ltc::textured_ground_truth::options opt;
    opt.samples = 1 << 15;

    std::vector<image> textures;
    for (int t = 0; t < 3; ++t) textures.push_back(make_texture(t));
    std::vector<ltc::light_texture<double>> prefiltered;
    for (const auto& im : textures) prefiltered.emplace_back(im.w, im.h, im.px.data());
    // Area sampling proportional to the texels' luminance, dilated by one texel (the bilinear
    // radiance spreads each texel over its neighbours), mixed with uniform sampling.
    std::vector<ltc::textured_ground_truth::texel_distribution> densities;
    for (const auto& im : textures) {
        std::vector<double> wgt(im.px.size());
        for (int y = 0; y < im.h; ++y)
            for (int x = 0; x < im.w; ++x) {
                double m = 0;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int xx = std::min(std::max(x + dx, 0), im.w - 1), yy = std::min(std::max(y + dy, 0), im.h - 1);
                        m = std::max(m, sum(im.px[std::size_t(yy) * im.w + xx]));
                    }
                wgt[std::size_t(y) * im.w + x] = m;
            }
        densities.emplace_back(im.w, im.h, wgt.data());
    }

    // [texture][lobe] stats of the texture error; [texture][lobe] shading error.
    stats tex_err[3][5], shade_err[3][5], fit_err[5], by_dist[3][3], by_orient[3][3], by_view[3][4];
    stats rel_se, signed_err[3];
    std::vector<worst> worst_cases;
    int skipped = 0, total = 0;
    std::uint64_t seed = 1;
    for (int ri = 0; ri < 5; ++ri)
        for (int vi = 0; vi < 4; ++vi)
            for (int di = 0; di < 3; ++di)
                for (int oi = 0; oi < 3; ++oi) {
                    const double th = views[vi] * pi / 180;
                    const dvec3 V(std::sin(th), 0, std::cos(th));
                    const double el = 45 * pi / 180;
                    const dvec3 dir(-std::cos(el), 0, std::sin(el));
                    const dvec3 C = dists[di] * dir;
                    // Light frame: normal towards the shading point, rotated about the horizontal axis t (= y).
                    dvec3 n = -dir;
                    if (oi == 1) {
                        const double a = 60 * pi / 180;  // rotate n about y by 60 deg
                        n = dvec3(n.x * std::cos(a) + n.z * std::sin(a), 0, -n.x * std::sin(a) + n.z * std::cos(a));
                    } else if (oi == 2) {
                        n = dvec3(1, 0, 0);
                    }
                    const dvec3 t(0, 1, 0);
                    const dvec3 b = glm::normalize(glm::cross(n, t));
                    const dvec3 q[4] = {C - 0.5 * t - 0.5 * b, C + 0.5 * t - 0.5 * b, C + 0.5 * t + 0.5 * b,
                                        C - 0.5 * t + 0.5 * b};
                    const bool diffuse = roughs[ri] < 0;
                    const auto coeff = ltc::ggx::fetch<double>(std::cos(th), diffuse ? 0.5 : roughs[ri]);
                    const auto d = ltc::transformed<ltc::clamped_cosine<double>>::from_inverse(
                        diffuse ? glm::dmat3(1.0) : coeff.m_inv);
                    const double i_d = d.integrate(q, 4);
                    ++total;
                    if (!(i_d >= 1e-4)) {
                        ++skipped;
                        continue;
                    }
                    const double alpha = roughs[ri] * roughs[ri];
                    const ltc::textured_ground_truth::brdf_lobe<ltc::brdf::ggx<double>> brdf{V, alpha};
                    const ltc::textured_ground_truth::ltc_lobe lobe{d};
                    // Fit only (constant texture 1).
                    double gt_const = 0;
                    if (!diffuse) {
                        opt.seed = seed++;
                        const auto e = ltc::textured_ground_truth::integrate(
                            brdf, q, [](double, double) { return dvec3(1.0); }, opt);
                        gt_const = e.mean.x;
                        fit_err[ri].add(std::abs(coeff.magnitude * i_d - gt_const) / gt_const);
                    }
                    for (int ti = 0; ti < 3; ++ti) {
                        const image& im = textures[ti];
                        const auto L = [&](double u, double v) {
                            return ltc::bilinear_image_lookup(im.w, im.h, im.px.data(), u, v);
                        };
                        const dvec3 approx = ltc::integrate_textured_quad(d, q, prefiltered[ti]);
                        opt.seed = seed++;
                        const auto e = ltc::textured_ground_truth::integrate(lobe, q, L, opt, &densities[ti]);
                        const double err = std::abs(sum(approx) - sum(e.mean)) / sum(e.mean);
                        rel_se.add(sum(e.standard_error) / sum(e.mean));
                        tex_err[ti][ri].add(err);
                        signed_err[ti].add((sum(approx) - sum(e.mean)) / sum(e.mean));
                        by_dist[ti][di].add(err);
                        by_orient[ti][oi].add(err);
                        by_view[ti][vi].add(err);
                        char buf[256];
                        std::snprintf(buf, sizeof buf, "%-13s %-8s theta_v %2.0f dist %.1f %-9s: I_D %.3g, sigma %.3g",
                                      im.name.c_str(), diffuse ? "diffuse" : ("r " + std::to_string(roughs[ri]).substr(0, 4)).c_str(),
                                      views[vi], dists[di], orient_names[oi], i_d,
                                      double(ltc::fetch_parameters(d.inverse_matrix(), q).sigma));
                        worst_cases.push_back({err, buf});
                        if (diffuse) {
                            shade_err[ti][ri].add(err);
                        } else {
                            opt.seed = seed++;
                            const auto g = ltc::textured_ground_truth::integrate(brdf, q, L, opt, &densities[ti]);
                            shade_err[ti][ri].add(std::abs(coeff.magnitude * sum(approx) - sum(g.mean)) / sum(g.mean));
                        }
                    }
                }

    std::printf("Textured quad lights: I_D I_L (prefiltered fetch) against Monte Carlo\n");
    std::printf("%d configurations x 3 textures (%d skipped: I_D < 1e-4); MC mean relative standard error %.2f%%\n\n",
                total, skipped, 100 * rel_se.mean());
    const char* lobe_names[] = {"diffuse", "r 0.1", "r 0.25", "r 0.5", "r 1"};
    std::printf("%-14s %-8s | %-26s | %-26s | %s\n", "texture", "lobe", "texture error mean/p95/max",
                "shading error mean/p95/max", "fit only (const) mean/max");
    for (int ti = 0; ti < 3; ++ti)
        for (int ri = 0; ri < 5; ++ri)
            std::printf("%-14s %-8s | %6.2f%% %7.2f%% %8.2f%% | %6.2f%% %7.2f%% %8.2f%% | %6.2f%% %7.2f%%\n",
                        textures[ti].name.c_str(), lobe_names[ri], 100 * tex_err[ti][ri].mean(),
                        100 * tex_err[ti][ri].pct(0.95), 100 * tex_err[ti][ri].max(), 100 * shade_err[ti][ri].mean(),
                        100 * shade_err[ti][ri].pct(0.95), 100 * shade_err[ti][ri].max(), 100 * fit_err[ri].mean(),
                        100 * fit_err[ri].max());
    for (int ti = 0; ti < 3; ++ti)
        std::printf("%-14s mean signed texture error %+.2f%% (I_D I_L - MC) / MC\n", textures[ti].name.c_str(),
                    100 * signed_err[ti].mean());
    std::printf("\nTexture error (mean / p95) by distance, orientation and view angle:\n");
    for (int ti = 0; ti < 3; ++ti) {
        std::printf("%-14s", textures[ti].name.c_str());
        for (int di = 0; di < 3; ++di)
            std::printf(" d%.1f %5.2f/%5.2f%%", dists[di], 100 * by_dist[ti][di].mean(), 100 * by_dist[ti][di].pct(0.95));
        std::printf("\n%-14s", "");
        for (int oi = 0; oi < 3; ++oi)
            std::printf(" | %s %5.2f/%5.2f%%", orient_names[oi], 100 * by_orient[ti][oi].mean(),
                        100 * by_orient[ti][oi].pct(0.95));
        std::printf("\n%-14s", "");
        for (int vi = 0; vi < 4; ++vi)
            std::printf(" th%2.0f %5.2f/%5.2f%%", views[vi], 100 * by_view[ti][vi].mean(), 100 * by_view[ti][vi].pct(0.95));
        std::printf("\n");
    }
    std::sort(worst_cases.begin(), worst_cases.end(), [](const worst& a, const worst& b) { return a.err > b.err; });
    std::printf("\nWorst texture errors:\n");
    for (std::size_t i = 0; i < std::min<std::size_t>(12, worst_cases.size()); ++i)
        std::printf("  %7.2f%%  %s\n", 100 * worst_cases[i].err, worst_cases[i].what.c_str());

    // Prefilter timing.
    std::printf("\nPrefilter timing, 1024 x 1024 RGB (%u hardware threads):\n", std::thread::hardware_concurrency());
    std::vector<glm::vec3> big(std::size_t(1024) * 1024);
    for (std::size_t i = 0; i < big.size(); ++i)
        big[i] = glm::vec3(float(i % 1024) / 1024, float((i / 1024) % 7) / 7, float((i * 2654435761u) % 1000) / 1000);
    for (double margin : {ltc::light_texture<float>::default_margin, 0.25}) {
        const auto t0 = std::chrono::steady_clock::now();
        const ltc::light_texture<float> tex(1024, 1024, big.data(), margin);
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::size_t texels = 0;
        for (int k = 0; k < tex.level_count(); ++k) texels += tex.get_level(k).texels.size();
        std::printf("  margin %.3f: %d levels, %.1f MB, %.2f s\n", margin, tex.level_count(), texels * 12.0 / 1e6, s);
    }
    return 0;
}
