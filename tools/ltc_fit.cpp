// ltc_fit -- fits a table of Linearly Transformed Cosines to a BRDF and writes it as a C++
// header (the shipped include/ltc/tables/ggx.hpp is this program's output):
//
//   ltc_fit --brdf ggx --out include/ltc/tables/ggx.hpp
//   ltc_fit --brdf ggx_anisotropic --out include/ltc/tables/ggx_anisotropic.hpp
//
// (and the others: the command in each table's own header comment, or ltc_fit --help)
//
// The fit is ltc::fit::fit_table (include/ltc/fitting/fit_table.hpp; ltc/fitting/fit.hpp gives an
// overview of the method) and the text is ltc::fit::table_header_text (ltc/fitting/table_writer.hpp);
// for ggx_anisotropic, ltc::fit::fit_anisotropic_table and anisotropic_table_header_text
// (ltc/fitting/fit_anisotropic.hpp);
// the output depends only on the options that change the fit (--brdf, --size, --objective), never
// on --threads: the same binary writes the same bytes with any thread count.
#include "common/cli.hpp"
#include "common/progress.hpp"

#include <ltc/brdf/beckmann.hpp>
#include <ltc/brdf/charlie.hpp>
#include <ltc/brdf/ggx.hpp>
#include <ltc/brdf/ggx_anisotropic.hpp>
#include <ltc/fitting/fit.hpp>
#include <ltc/fitting/fit_anisotropic.hpp>
#include <ltc/fitting/table_writer.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <thread>

namespace {

const char* const usage_text =
    "usage: ltc_fit --brdf ggx|beckmann|charlie|ggx_anisotropic --out FILE [--size N] [--objective O] [--lobes 1|2|cosine] [--threads K] [--quiet]\n"
    "\n"
    "Fits a table of Linearly Transformed Cosines (Heitz et al. 2016) to the BRDF, with the\n"
    "method of ltc/fitting/fit.hpp, and writes it to FILE as a C++ header defining\n"
    "ltc::tables::<brdf>_size and ltc::tables::<brdf>_data (N x N nodes x 6 floats: the\n"
    "normalized inverse matrix m_inv[0][0], m_inv[0][2], m_inv[2][0], m_inv[2][2], the\n"
    "magnitude and the Fresnel term; layout in ltc/tables/ltc_table.hpp).\n"
    "\n"
    "  --brdf NAME    ggx (GGX, Smith height-correlated), beckmann, or charlie (the sheen of\n"
    "                 KHR_materials_sheen, ltc/brdf/charlie.hpp); alpha = roughness^2 (required);\n"
    "                 or ggx_anisotropic: an N^4 table over (alpha_x, alpha_y, theta_v, phi_v) of\n"
    "                 full-matrix LTCs (ltc/fitting/fit_anisotropic.hpp; default size 8; 11 floats per\n"
    "                 node, layout in ltc/tables/anisotropic_table.hpp; --objective l3 and --lobes 1 only)\n"
    "  --out FILE     the header to write ('-' for standard output; required); also -o FILE\n"
    "  --size N       nodes per axis (default 64 with one lobe, 32 with two; at least 2)\n"
    "  --objective O  l3 (default: the paper's, the shipped tables), integrals, combined,\n"
    "                 integrals+mag or combined+mag (opt-in, ltc/fitting/integral_objective.hpp)\n"
    "  --lobes 1      one LTC per node (the default)\n"
    "  --lobes 2      a sum of two LTCs per node (ltc/fitting/fit_two_lobes.hpp; writes\n"
    "                 ltc::tables::<brdf>_two_lobe_size and _data, two such tables; --objective\n"
    "                 does not apply)\n"
    "  --lobes cosine one LTC and the clamped cosine about the normal per node (the model\n"
    "                 ltc_and_cosine of fit_two_lobes.hpp, its integrals over the spiral\n"
    "                 family; writes <brdf>_cosine_lobe_size and _data, the two-lobe layout\n"
    "                 with lobe 1 the cosine; default size 32)\n"
    "  --threads K    worker threads (default: all cores); the output does not depend on it; also -j K\n"
    "  --quiet        no progress on standard error (default, with any --lobes: a bar on a\n"
    "                 terminal, else a line per tenth of the nodes); also -q\n"
    "  --help         this text; also -h\n"
    "\n"
    "At the end it prints the time taken and the fit error (relative L1 and L3 distances\n"
    "between rho*cos and magnitude * LTC, as estimated by the fit) to standard output.\n"
    "\n"
    "Regenerate the shipped table:\n"
    "  ltc_fit --brdf ggx --out include/ltc/tables/ggx.hpp\n"
    "  ltc_fit --brdf ggx --lobes 2 --out include/ltc/tables/ggx_two_lobe.hpp\n"
    "  ltc_fit --brdf ggx --lobes cosine --out include/ltc/tables/ggx_cosine_lobe.hpp\n"
    "  ltc_fit --brdf charlie --objective combined --out include/ltc/tables/charlie.hpp\n"
    "  ltc_fit --brdf ggx_anisotropic --out include/ltc/tables/ggx_anisotropic.hpp\n";

struct arguments {
    std::string brdf;
    std::string out;
    int size = 0;  // 0: the default of the lobe count
    int lobes = 1;
    ltc::fit::two_lobe_model model = ltc::fit::two_lobe_model::two_ltcs;  // with lobes = 2
    ltc::fit::objective goal = ltc::fit::objective::l3;
    bool fit_magnitude = false;
    unsigned threads = 0;
    bool quiet = false;
};

[[noreturn]] void fail(const std::string& message) {
    std::cerr << "ltc_fit: " << message << "\n(ltc_fit --help for usage)\n";
    std::exit(2);
}

/// The options (common/cli.hpp's loop and messages), then the checks across them.
arguments parse(int argc, char** argv) {
    using ltc_examples::option_status;
    arguments a;
    const auto help = [](const char*) { std::cout << usage_text; };
    const auto flag = ltc_examples::quiet_flag(a.quiet);
    const auto option = [&](const std::string& name, const ltc_examples::option_value& v) {
        if (name == "--brdf") {
            a.brdf = v.text;
        } else if (name == "--out" || name == "-o") {
            a.out = v.text;
        } else if (name == "--size") {
            if (!v.integer_in(2, 4096)) return option_status::bad;
            a.size = int(v.number);
        } else if (name == "--objective") {
            const std::string o = v.text;
            a.fit_magnitude = o.size() > 4 && o.compare(o.size() - 4, 4, "+mag") == 0;
            const std::string base = a.fit_magnitude ? o.substr(0, o.size() - 4) : o;
            if (base == "l3" && !a.fit_magnitude) a.goal = ltc::fit::objective::l3;
            else if (base == "integrals") a.goal = ltc::fit::objective::integrals;
            else if (base == "combined") a.goal = ltc::fit::objective::combined;
            else return option_status::bad;
        } else if (name == "--lobes") {
            if (std::string(v.text) == "cosine") a.lobes = 2, a.model = ltc::fit::two_lobe_model::ltc_and_cosine;
            else if (v.integer_in(1, 2)) a.lobes = int(v.number), a.model = ltc::fit::two_lobe_model::two_ltcs;
            else return option_status::bad;
        } else if (name == "--threads" || name == "-j") {
            if (!v.integer_in(1, 4096)) return option_status::bad;
            a.threads = unsigned(v.number);
        } else {
            return option_status::unknown;
        }
        return option_status::taken;
    };
    if (const int r = ltc_examples::parse_options(argc, argv, help, flag, option); r != 0) std::exit(r == 1 ? 0 : 2);
    if (a.brdf.empty()) fail("--brdf is required");
    if (a.brdf != "ggx" && a.brdf != "beckmann" && a.brdf != "charlie" && a.brdf != "ggx_anisotropic")
        fail("unknown BRDF '" + a.brdf + "' (ggx, beckmann, charlie or ggx_anisotropic)");
    if (a.out.empty()) fail("--out is required");
    if (a.lobes == 2 && a.goal != ltc::fit::objective::l3) fail("--objective does not apply to --lobes 2 or cosine");
    if (a.brdf == "ggx_anisotropic" && (a.lobes != 1 || a.goal != ltc::fit::objective::l3))
        fail("ggx_anisotropic fits one lobe with --objective l3");
    if (a.brdf == "ggx_anisotropic" && a.size > 64) fail("--size is at most 64 with ggx_anisotropic");
    if (a.size == 0 && a.brdf == "ggx_anisotropic") a.size = ltc::fit::anisotropic_options{}.size;
    if (a.size == 0) a.size = a.lobes == 2 ? ltc::fit::two_lobe_default_size : ltc::fit::options{}.size;
    return a;
}

/// Writes the header text to `out` ('-': standard output); false (with a message) if it cannot.
bool write_text(const std::string& out, const std::string& text) {
    if (out == "-") {
        std::cout << text;
        return true;
    }
    std::ofstream file(out, std::ios::binary);
    file << text;
    file.close();
    if (!file) std::cerr << "ltc_fit: cannot write '" << out << "'\n";
    return bool(file);
}

template <template <typename> class Brdf>
int run(const arguments& args, const char* description) {
    ltc::fit::options opt;
    opt.size = args.size;
    opt.threads = args.threads;
    opt.goal = args.goal;
    opt.fit_magnitude = args.fit_magnitude;
    ltc_examples::progress bar("fit", "nodes", ltc_examples::progress_on_stderr(args.quiet));
    if (args.lobes == 2) {
        const ltc::fit::two_lobe_table tab = ltc::fit::fit_two_lobe_table<Brdf>(
            opt, args.model, [&](std::size_t done, std::size_t total) { bar.update(done, total); });
        const double seconds = bar.seconds();
        if (!write_text(args.out, ltc::fit::two_lobe_table_header_text(args.brdf, description, tab, opt)))
            return 1;
        const unsigned threads = opt.threads ? opt.threads : std::max(1u, std::thread::hardware_concurrency());
        std::fprintf(args.out == "-" ? stderr : stdout, "ltc_fit: %s, %s, %d x %d nodes in %.2f s on %u thread%s%s%s\n",
                     args.brdf.c_str(), args.model == ltc::fit::two_lobe_model::ltc_and_cosine ? "an LTC and the cosine" : "two lobes",
                     tab.size, tab.size, seconds, threads, threads == 1 ? "" : "s",
                     args.out == "-" ? "" : "; wrote ", args.out == "-" ? "" : args.out.c_str());
        return 0;
    }
    const ltc::fit::table tab = ltc::fit::fit_table<Brdf>(opt, [&](std::size_t done, std::size_t total) { bar.update(done, total); });
    const double seconds = bar.seconds();
    const ltc::fit::error_summary err = ltc::fit::summarize_error(tab);
    if (!write_text(args.out, ltc::fit::table_header_text(args.brdf, description, tab, opt))) return 1;
    const unsigned threads = opt.threads ? opt.threads : std::max(1u, std::thread::hardware_concurrency());
    std::FILE* summary = args.out == "-" ? stderr : stdout;
    std::fprintf(summary,
                 "ltc_fit: %s, %d x %d nodes in %.2f s on %u thread%s; fit error (relative) L1 mean %.4f max %.4f, "
                 "L3 mean %.4f max %.4f%s%s\n",
                 args.brdf.c_str(), tab.size, tab.size, seconds, threads, threads == 1 ? "" : "s", err.mean_l1,
                 err.max_l1, err.mean_l3, err.max_l3, args.out == "-" ? "" : "; wrote ",
                 args.out == "-" ? "" : args.out.c_str());
    return 0;
}

/// The anisotropic table (fit_anisotropic_table).
int run_anisotropic(const arguments& args) {
    ltc::fit::anisotropic_options opt;
    opt.size = args.size;
    opt.threads = args.threads;
    ltc_examples::progress bar("fit", "nodes", ltc_examples::progress_on_stderr(args.quiet));
    const ltc::fit::anisotropic_table_fit tab = ltc::fit::fit_anisotropic_table<ltc::brdf::ggx_anisotropic>(
        opt, [&](std::size_t done, std::size_t total) { bar.update(done, total); });
    const double seconds = bar.seconds();
    const ltc::fit::anisotropic_error_summary err = ltc::fit::summarize_error(tab);
    const char* description =
        "anisotropic GGX microfacet NDF (alpha_x along the tangent +x, alpha_y along +y), Smith height-correlated "
        "masking-shadowing,\n// no Fresnel (factored out, see the fresnel channel)";
    if (!write_text(args.out, ltc::fit::anisotropic_table_header_text(args.brdf, description, tab, opt))) return 1;
    const unsigned threads = opt.threads ? opt.threads : std::max(1u, std::thread::hardware_concurrency());
    std::fprintf(args.out == "-" ? stderr : stdout,
                 "ltc_fit: %s, %d^4 nodes in %.2f s on %u thread%s; fit error (relative) L1 mean %.4f max %.4f, "
                 "L3 mean %.4f max %.4f%s%s\n",
                 args.brdf.c_str(), tab.size, seconds, threads, threads == 1 ? "" : "s", err.mean_l1, err.max_l1,
                 err.mean_l3, err.max_l3, args.out == "-" ? "" : "; wrote ", args.out == "-" ? "" : args.out.c_str());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const arguments args = parse(argc, argv);
    try {
        if (args.brdf == "ggx_anisotropic") return run_anisotropic(args);
        if (args.brdf == "ggx") return run<ltc::brdf::ggx>(args, "GGX microfacet NDF, Smith height-correlated masking-shadowing");
        if (args.brdf == "charlie")
            return run<ltc::brdf::charlie>(args, "Charlie sheen of KHR_materials_sheen (Estevez and Kulla 2017), without the sheen colour");
        return run<ltc::brdf::beckmann>(args, "Beckmann microfacet NDF, Smith height-correlated masking-shadowing");
    } catch (const std::exception& e) {
        std::cerr << "ltc_fit: " << e.what() << "\n";
        return 1;
    }
}
