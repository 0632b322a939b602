// anisotropic_error_report -- how far LTC shading of anisotropic GGX is from the real integral over
// polygonal lights: this library's table (ltc::ggx_anisotropic::fetch) against the published 8^4
// table of Kt, Heitz, Dupuy and Narayanan 2022 ("Bringing Linearly Transformed Cosines to
// Anisotropic GGX"), and on the diagonal alpha_x == alpha_y against the isotropic table
// (ltc::ggx::fetch rotated by phi_v).
//
//   anisotropic_error_report [--peers DIR] [--samples N] [--threads K] [--at-nodes] [--list]
//
// Direct build (as examples/CMakeLists.txt does):
//   g++ -std=gnu++17 -O2 -DNDEBUG -Iinclude -Iexamples tools/anisotropic_error_report/main.cpp
//       -o anisotropic_error_report -pthread   (one line)
//
// Grid (local frame: N = +z, tangent +x, V = (sin t cos p, sin t sin p, cos t)): alpha_x, alpha_y
// in {0.05, 0.1, 0.2, 0.35, 0.5, 0.8} (all 36 pairs, mostly between the 8^4 grid's nodes at i / 7;
// 0.05 and 0.1 between its two smoothest nodes, 1e-4 and 1/7, where the lobe changes fastest),
// theta_v in {15, 40, 65} deg, phi_v in {0, 25, 70, 130, 250} deg (all four quadrants), and 8
// squares (half-width 0.2 and 0.6 at distance 1, facing the point) centred on: the mirror
// direction of V (elevation at least 20 deg), the zenith, azimuth phi_v + 90 deg at elevation
// 40 deg, and the tangent (azimuth 0) at elevation 30 deg. Squares with a vertex below the
// horizon are left out (so that no horizon clipping enters the comparison).
//
// Truth: ltc::ground_truth::integrate (MIS of the BRDF's sampler and the polygon's, --samples
// iterations, seed = the configuration's index). Estimates: magnitude * I_ltc (F0 = 1, no
// Fresnel, as the truth), I_ltc the two-sided integral of the LTC over the square. The published
// table stores no magnitude: its estimates use this library's magnitude, so that the two differ
// only by the matrix. Its matrices are read as published: M (not M^-1), 9 floats row-major per
// node, shape (8, 8, 8, 8, 3, 3) over (alpha_x = i / 7, alpha_y = j / 7, theta = k / 7 * 0.9999
// pi/2, phi = l / 7 * pi/2), each clamped to alpha >= 1e-4 as their fit did; interpolated
// quadrilinearly in M as their shader does (M, then the inverse), with their quadrant rules
// (phi in [pi/2, pi): pi - phi and the x mirror; [pi, 3 pi/2): phi - pi and the rotation by pi;
// [3 pi/2, 2 pi): 2 pi - phi and the y mirror), written here as F M^-1 F (the same distribution
// as their F M, without the change of winding that their shader makes for it).
//
// Errors: |estimate - truth| / truth over the significant configurations, those whose truth is at
// least 5% of the directional albedo (the BRDF's, by 128 x 128 quadrature): mean and p95, overall,
// by theta_v, by the anisotropy max(a) / min(a), by the smoother alpha and by the placement.
#include "common/error_summary.hpp"
#include "common/parallel_for.hpp"

#include <ltc/brdf/ggx_anisotropic.hpp>
#include <ltc/core/clamped_cosine.hpp>
#include <ltc/core/transformed.hpp>
#include <ltc/fitting/fit_anisotropic.hpp>  // compute_anisotropic_moments
#include <ltc/reference/ground_truth.hpp>
#include <ltc/shading/ggx_anisotropic_fetch.hpp>
#include <ltc/shading/ggx_fetch.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

namespace {

using glm::dmat3;
using glm::dvec3;
constexpr double pi = 3.141592653589793;
constexpr double deg = pi / 180.0;

double alphas[] = {0.05, 0.1, 0.2, 0.35, 0.5, 0.8};
constexpr int alpha_count = 6;
double thetas[] = {15, 40, 65};
double phis[] = {0, 25, 70, 130, 250};
const double half_widths[] = {0.2, 0.6};
const char* const placement_names[] = {"mirror", "zenith", "side", "tangent"};

struct config {
    int ax, ay, theta, phi, placement, size;
    std::vector<dvec3> vertices;
    double albedo = 0;
    ltc::ground_truth::estimate gt;
    double ours = 0, published = 0, isotropic = 0;
};

dvec3 direction(double azimuth, double elevation) {
    return dvec3(std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
}

/// A square of half-width s centred at distance 1 along c, facing the origin.
std::vector<dvec3> square(const dvec3& c, double s) {
    const dvec3 e1 = glm::normalize(std::abs(c.z) < 0.9 ? glm::cross(dvec3(0, 0, 1), c) : glm::cross(dvec3(1, 0, 0), c));
    const dvec3 e2 = glm::cross(c, e1);
    std::vector<dvec3> v = {c - s * e1 - s * e2, c + s * e1 - s * e2, c + s * e1 + s * e2, c - s * e1 + s * e2};
    if (glm::dot(v[0], glm::cross(v[1] - v[0], v[2] - v[0])) < 0) std::reverse(v.begin(), v.end());
    return v;
}

dvec3 view_of(const config& c) {
    const double t = thetas[c.theta] * deg, p = phis[c.phi] * deg;
    return dvec3(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
}

double ltc_integral(const dmat3& m_inv, const std::vector<dvec3>& v) {
    return ltc::transformed<ltc::clamped_cosine<double>>::from_inverse(m_inv).integrate(v.data(), v.size());
}

/// The published table (the file comment): 8^4 x 9 floats, M row-major.
struct published_table {
    std::vector<float> m;
    bool load(const std::string& path, std::string& why) {
        std::ifstream f(path, std::ios::binary);
        if (!f) return why = "cannot open " + path, false;
        char magic[8];
        f.read(magic, 8);
        if (!f || std::memcmp(magic, "\x93NUMPY", 6) != 0 || magic[6] != 1) return why = "not a version-1 .npy file", false;
        unsigned char len[2];
        f.read(reinterpret_cast<char*>(len), 2);
        std::string header(std::size_t(len[0] | (len[1] << 8)), ' ');
        f.read(&header[0], std::streamsize(header.size()));
        if (header.find("'descr': '<f4'") == std::string::npos || header.find("'fortran_order': False") == std::string::npos ||
            header.find("'shape': (8, 8, 8, 8, 3, 3)") == std::string::npos)
            return why = "unexpected header " + header, false;
        m.resize(8 * 8 * 8 * 8 * 9);
        f.read(reinterpret_cast<char*>(m.data()), std::streamsize(m.size() * sizeof(float)));
        if (!f) return why = "short file", false;
        return true;
    }
    dmat3 node(int i, int j, int k, int l) const {  // GLM M[column][row]
        const float* p = &m[std::size_t((((i * 8 + j) * 8 + k) * 8 + l) * 9)];
        dmat3 M;
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) M[c][r] = p[3 * r + c];
        return M;
    }
    /// m_inv in this library's convention (the file comment).
    dmat3 m_inv(double cos_theta, double phi, double ax, double ay) const {
        const double theta = std::acos(std::clamp(cos_theta, 0.0, 1.0));
        double p = std::fmod(phi, 2 * pi);
        if (p < 0) p += 2 * pi;
        bool fx = false, fy = false;
        if (p >= 1.5 * pi) p = 2 * pi - p, fy = true;
        else if (p >= pi) p = p - pi, fx = fy = true;
        else if (p >= 0.5 * pi) p = pi - p, fx = true;
        const double s[4] = {std::clamp(ax, 0.0, 1.0) * 7, std::clamp(ay, 0.0, 1.0) * 7,
                             std::clamp(theta / (0.9999 * pi / 2), 0.0, 1.0) * 7, std::clamp(p / (pi / 2), 0.0, 1.0) * 7};
        int i0[4];
        double f[4];
        for (int d = 0; d < 4; ++d) {
            i0[d] = std::min(int(s[d]), 6);
            f[d] = s[d] - i0[d];
        }
        dmat3 M(0.0);
        for (int b = 0; b < 16; ++b) {
            double w = 1;
            int idx[4];
            for (int d = 0; d < 4; ++d) {
                const int bit = (b >> (3 - d)) & 1;
                idx[d] = i0[d] + bit;
                w *= bit ? f[d] : 1 - f[d];
            }
            M += w * node(idx[0], idx[1], idx[2], idx[3]);
        }
        return ltc::detail::mirror(glm::inverse(M), fx, fy);
    }
};

/// The isotropic table at alpha, rotated by phi: m_inv(phi) = m_inv(0) R_z(-phi).
dmat3 isotropic_m_inv(double cos_theta, double phi, double alpha, double& magnitude) {
    const auto c = ltc::ggx::fetch(cos_theta, std::sqrt(alpha));
    magnitude = c.magnitude;
    const dmat3 R(dvec3(std::cos(phi), -std::sin(phi), 0), dvec3(std::sin(phi), std::cos(phi), 0), dvec3(0, 0, 1));
    return c.m_inv * R;  // R = R_z(-phi) in GLM's column order
}

}  // namespace

int main(int argc, char** argv) {
    std::string peers = "../shared/peers/anisotropic";
    unsigned long long samples = 1u << 15;
    unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    bool list = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if ((a == "--peers") && i + 1 < argc) peers = argv[++i];
        else if (a == "--samples" && i + 1 < argc) samples = std::strtoull(argv[++i], nullptr, 10);
        else if ((a == "--threads" || a == "-j") && i + 1 < argc) threads = unsigned(std::max(1, std::atoi(argv[++i])));
        else if (a == "--list") list = true;
        else if (a == "--at-nodes") {
            const double an[] = {1, 2, 3, 4, 5, 6}, tn[] = {1, 3, 5}, pn[] = {0, 2, 5, 9, 19};
            for (int k = 0; k < alpha_count; ++k) alphas[k] = an[k] / 7;
            for (int k = 0; k < 3; ++k) thetas[k] = tn[k] / 7 * 0.9999 * 90;
            for (int k = 0; k < 5; ++k) phis[k] = pn[k] / 7 * 90;
        }
        else if (a == "--help" || a == "-h") {
            std::cout << "usage: anisotropic_error_report [--peers DIR] [--samples N] [--threads K] [--at-nodes] [--list]\n"
                         "\n"
                         "LTC shading of anisotropic GGX over squares against Monte Carlo: ltc::ggx_anisotropic::fetch,\n"
                         "the published 8^4 table of Kt et al. 2022 and, on the diagonal, ltc::ggx::fetch rotated by phi_v\n"
                         "(the grid and the method: the comment at the top of tools/anisotropic_error_report/main.cpp).\n"
                         "\n"
                         "  --peers DIR   where kt2022_alphax_alphay_theta_phi.npy is (default ../shared/peers/anisotropic,\n"
                         "                from the repository root); without it the published column is skipped\n"
                         "  --samples N   Monte Carlo iterations per configuration (default 32768)\n"
                         "  --threads K   worker threads (default: all cores); also -j K\n"
                         "  --at-nodes    the grid moved onto the 8^4 grid's nodes (the fit alone, no interpolation)\n"
                         "  --list        every configuration's truth and estimates\n"
                         "  --help        this text; also -h\n";
            return 0;
        } else {
            std::cerr << "anisotropic_error_report: unknown option " << a << "\n";
            return 2;
        }
    }
    published_table kt;
    std::string why;
    const bool have_kt = kt.load(peers + "/kt2022_alphax_alphay_theta_phi.npy", why);

    std::vector<config> grid;
    for (int ax = 0; ax < alpha_count; ++ax)
        for (int ay = 0; ay < alpha_count; ++ay)
            for (int t = 0; t < 3; ++t)
                for (int p = 0; p < 5; ++p)
                    for (int pl = 0; pl < 4; ++pl)
                        for (int sz = 0; sz < 2; ++sz) {
                            config c{ax, ay, t, p, pl, sz, {}, 0, {}, 0, 0, 0};
                            const double phi = phis[p] * deg, theta = thetas[t] * deg;
                            dvec3 d;
                            if (pl == 0) d = direction(phi + pi, std::max(pi / 2 - theta, 20 * deg));
                            else if (pl == 1) d = dvec3(0, 0, 1);
                            else if (pl == 2) d = direction(phi + pi / 2, 40 * deg);
                            else d = direction(0, 30 * deg);
                            c.vertices = square(d, half_widths[sz]);
                            bool above = true;
                            for (const dvec3& v : c.vertices) above = above && v.z > 0;
                            if (above) grid.push_back(std::move(c));
                        }

    const auto t0 = std::chrono::steady_clock::now();
    ltc_examples::parallel_for(grid.size(), threads, [&](std::size_t i) {
        config& c = grid[i];
        const dvec3 V = view_of(c);
        const ltc::brdf::anisotropic_alpha<double> a{alphas[c.ax], alphas[c.ay]};
        c.albedo = ltc::fit::compute_anisotropic_moments<ltc::brdf::ggx_anisotropic>(V, a, 128).magnitude;
        ltc::ground_truth::options opt;
        opt.samples = samples;
        opt.seed = 1 + i;
        c.gt = ltc::ground_truth::integrate(ltc::brdf::ggx_anisotropic<double>{}, V, a, c.vertices.data(),
                                            c.vertices.size(), opt);
        const double phi = phis[c.phi] * deg;
        const auto ours = ltc::ggx_anisotropic::fetch(V.z, phi, a.x, a.y);
        c.ours = ours.magnitude * ltc_integral(ours.m_inv, c.vertices);
        if (have_kt) c.published = ours.magnitude * ltc_integral(kt.m_inv(V.z, phi, a.x, a.y), c.vertices);
        if (c.ax == c.ay) {
            double m = 0;
            const dmat3 mi = isotropic_m_inv(V.z, phi, a.x, m);
            c.isotropic = m * ltc_integral(mi, c.vertices);
        }
    });
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    std::printf("Anisotropic GGX: LTC shading of squares vs Monte Carlo (F0 = 1)\n"
                "grid: alpha_x, alpha_y {0.05,0.1,0.2,0.35,0.5,0.8} x theta_v {15,40,65} x phi_v {0,25,70,130,250} deg x 8 squares\n"
                "      (mirror / zenith / side / tangent, half-width 0.2 / 0.6), %zu above the horizon; %llu MC iterations\n"
                "evaluated in %.1f s on %u thread%s\n",
                grid.size(), samples, seconds, threads, threads == 1 ? "" : "s");
    if (!have_kt) std::printf("published table: skipped (%s)\n", why.c_str());
    std::vector<std::size_t> sig;
    std::vector<double> se;
    for (std::size_t i = 0; i < grid.size(); ++i)
        if (grid[i].gt.mean >= 0.05 * grid[i].albedo) {
            sig.push_back(i);
            se.push_back(grid[i].gt.standard_error / grid[i].gt.mean);
        }
    const auto sse = ltc_examples::summarize(se);
    std::printf("significant (truth >= 5%% of the albedo): %zu; MC relative standard error mean %.3f%%, max %.3f%%\n\n",
                sig.size(), 100 * sse.mean, 100 * sse.max);
    const auto row = [&](const char* label, const std::vector<std::size_t>& idx, bool iso) {
        std::vector<double> o, k, s;
        for (std::size_t i : idx) {
            const config& c = grid[i];
            o.push_back(std::abs(c.ours - c.gt.mean) / c.gt.mean);
            k.push_back(std::abs(c.published - c.gt.mean) / c.gt.mean);
            s.push_back(std::abs(c.isotropic - c.gt.mean) / c.gt.mean);
        }
        if (o.empty()) return;
        const auto so = ltc_examples::summarize(o), sk = ltc_examples::summarize(k), ss = ltc_examples::summarize(s);
        std::printf("  %-22s %4zu | %7.2f%% %7.2f%% |", label, idx.size(), 100 * so.mean, 100 * so.p95);
        if (have_kt) std::printf(" %7.2f%% %7.2f%% |", 100 * sk.mean, 100 * sk.p95);
        else std::printf("       -        - |");
        if (iso) std::printf(" %7.2f%% %7.2f%%", 100 * ss.mean, 100 * ss.p95);
        std::printf("\n");
    };
    std::printf("|estimate - MC| / MC          n | this library     | published (Kt 2022) | isotropic table\n"
                "                                |    mean      p95 |    mean      p95 |    mean      p95\n");
    row("all", sig, false);
    for (int t = 0; t < 3; ++t) {
        std::vector<std::size_t> idx;
        for (std::size_t i : sig) if (grid[i].theta == t) idx.push_back(i);
        char label[32];
        std::snprintf(label, sizeof label, "theta_v %.0f", thetas[t]);
        row(label, idx, false);
    }
    const double ratios[][2] = {{1, 1}, {1.01, 2}, {2.01, 5}, {5.01, 100}};
    const char* ratio_names[] = {"isotropic (ax == ay)", "anisotropy <= 2", "anisotropy 2.3 .. 4", "anisotropy 5 .. 16"};
    for (int r = 0; r < 4; ++r) {
        std::vector<std::size_t> idx;
        for (std::size_t i : sig) {
            const double q = std::max(alphas[grid[i].ax], alphas[grid[i].ay]) / std::min(alphas[grid[i].ax], alphas[grid[i].ay]);
            if (q >= ratios[r][0] && q <= ratios[r][1]) idx.push_back(i);
        }
        row(ratio_names[r], idx, r == 0);
    }
    for (int lo = 0; lo < 2; ++lo) {  // the smoother alpha: between the two smoothest nodes, or not
        std::vector<std::size_t> idx;
        for (std::size_t i : sig)
            if ((std::min(alphas[grid[i].ax], alphas[grid[i].ay]) < 1.0 / 7) == (lo == 0)) idx.push_back(i);
        row(lo == 0 ? "min(alpha) < 1/7" : "min(alpha) >= 1/7", idx, false);
    }
    for (int pl = 0; pl < 4; ++pl) {
        std::vector<std::size_t> idx;
        for (std::size_t i : sig) if (grid[i].placement == pl) idx.push_back(i);
        char label[32];
        std::snprintf(label, sizeof label, "placement %s", placement_names[pl]);
        row(label, idx, false);
    }
    if (list) {
        std::printf("\n  ax    ay   theta phi  placement  size   MC (+- se)            ours       published  isotropic\n");
        for (const config& c : grid)
            std::printf("  %.2f  %.2f  %3.0f  %3.0f  %-8s  %.1f  %.5f (%.5f)  %.5f  %.5f  %.5f%s\n", alphas[c.ax], alphas[c.ay],
                        thetas[c.theta], phis[c.phi], placement_names[c.placement], half_widths[c.size], c.gt.mean,
                        c.gt.standard_error, c.ours, c.published, c.isotropic, c.gt.mean >= 0.05 * c.albedo ? "" : "  (not significant)");
    }
    return 0;
}
