// ltc_export -- writes the shipped GGX tables as the files GPU renderers load: the paper's two RGBA
// textures (ltc_1: the inverse matrix, ltc_2: magnitude and Fresnel) as DDS float32 and float16,
// as raw little-endian float32 with a JSON descriptor, as GLSL and HLSL constant arrays, as a
// three.js module and as the C/C++ arrays of Blender's EEVEE:
//
//   ltc_export --out build/ltc_textures
//
// The conversion is ltc/tables/export.hpp's (to_paper_textures, write_dds, write_raw_float32,
// raw_descriptor_json, shader_constants, threejs_module, eevee_lut_source); texture x = roughness
// node, y = sqrt(1 - cos theta_v) node.
#include "common/cli.hpp"

#include <ltc/shading/ggx_fetch.hpp>
#include <ltc/tables/export.hpp>
#include <ltc/tables/ggx_cosine_lobe.hpp>
#include <ltc/tables/ggx_two_lobe.hpp>
#include <ltc/tables/ltc_table.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace {

const char* const usage_text =
    "usage: ltc_export [--table ggx|two_lobe|cosine_lobe|all] [--formats LIST] [--out DIR] [--quiet]\n"
    "\n"
    "Writes a shipped GGX table as the paper's two RGBA textures, 4 floats per texel,\n"
    "texture x = roughness node (roughness = x / (w - 1)), y = u node (sqrt(1 - cos theta_v) = y / (h - 1)):\n"
    "  ltc_1 = (m_inv[0][0], m_inv[0][2], m_inv[2][0], m_inv[2][2]) (GLM/GLSL m[column][row], m_inv[1][1] = 1):\n"
    "          mInv = mat3(vec3(t1.x, 0, t1.y), vec3(0, 1, 0), vec3(t1.z, 0, t1.w))\n"
    "  ltc_2 = (magnitude, fresnel, 0, 0)\n"
    "sampled at uv = (roughness, sqrt(1 - cos theta_v)) * (n - 1) / n + 0.5 / n.\n"
    "\n"
    "  --table T      ggx (default): the one-lobe 64 x 64 table, the paper's layout (files ggx_*);\n"
    "                 two_lobe: each lobe of the 2 x 32 x 32 table as its own pair (ggx_two_lobe_1_*, _2_*),\n"
    "                 magnitude and fresnel times the lobe's share; cosine_lobe: the same for the cosine\n"
    "                 and LTC table (lobe 1's m_inv is the identity; lobe 2's ltc_1 is premultiplied by\n"
    "                 its ltc_2.x: divide after the fetch); all: the three\n"
    "  --formats L    comma-separated, default all of: dds32 (<name>_ltc_1.dds, DXGI R32G32B32A32_FLOAT),\n"
    "                 dds16 (<name>_ltc_1_f16.dds, R16G16B16A16_FLOAT; left out where a value overflows\n"
    "                 half), raw (<name>_ltc_1.f32 and its <name>_ltc_1.json), glsl (<name>.glsl),\n"
    "                 hlsl (<name>.hlsl): the textures as constant arrays, texel (x, y) at [y * w + x];\n"
    "                 threejs (<name>_threejs.js): an ES module shaped as three.js's RectAreaLightTexturesLib\n"
    "                 (float and half textures; left out where a value overflows half);\n"
    "                 blender (<name>_eevee_lut.cc, <name>_eevee_lut_vecbase.cc, <name>_eevee_lut.c): the\n"
    "                 definitions of EEVEE's ltc_mat_ggx and ltc_mag_ggx for the three ways Blender's\n"
    "                 eevee_lut.hh / .h declare them (float[64][64][4], VecBase<float, 4>[64][64], C\n"
    "                 float[64 * 64 * 4]); 64 x 64 tables only, as EEVEE's; left out where a value\n"
    "                 overflows half (EEVEE's utility texture is RGBA16F)\n"
    "  --out DIR      the output directory (created; default .)\n"
    "  --quiet        no report; also -q\n"
    "  --help         this text; also -h\n";

struct arguments {
    std::string table = "ggx";
    std::vector<std::string> formats{"dds32", "dds16", "raw", "glsl", "hlsl", "threejs", "blender"};
    std::string out = ".";
    bool quiet = false;
};

[[noreturn]] void fail(const std::string& message) {
    std::cerr << "ltc_export: " << message << "\n(ltc_export --help for usage)\n";
    std::exit(2);
}

std::vector<std::string> split(const std::string& s) {
    std::vector<std::string> r;
    std::size_t start = 0;
    for (;;) {
        const std::size_t comma = s.find(',', start);
        r.push_back(s.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        if (comma == std::string::npos) return r;
        start = comma + 1;
    }
}

arguments parse(int argc, char** argv) {
    using ltc_examples::option_status;
    arguments a;
    const auto help = [](const char*) { std::cout << usage_text; };
    const auto flag = ltc_examples::quiet_flag(a.quiet);
    const auto option = [&](const std::string& name, const ltc_examples::option_value& v) {
        if (name == "--table") {
            const std::string t = v.text;
            if (t != "ggx" && t != "two_lobe" && t != "cosine_lobe" && t != "all") return option_status::bad;
            a.table = t;
        } else if (name == "--formats") {
            a.formats = split(v.text);
            for (const std::string& f : a.formats)
                if (f != "dds32" && f != "dds16" && f != "raw" && f != "glsl" && f != "hlsl" && f != "threejs" &&
                    f != "blender")
                    return option_status::bad;
        } else if (name == "--out") {
            a.out = v.text;
            if (a.out.empty()) return option_status::bad;
        } else {
            return option_status::unknown;
        }
        return option_status::taken;
    };
    if (const int r = ltc_examples::parse_options(argc, argv, help, flag, option); r != 0) std::exit(r == 1 ? 0 : 2);
    return a;
}

bool wants(const arguments& a, const char* format) {
    return std::find(a.formats.begin(), a.formats.end(), format) != a.formats.end();
}

void write_bytes(const std::filesystem::path& path, const void* data, std::size_t size, bool quiet) {
    std::ofstream out(path, std::ios::binary);
    out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!out) {
        std::cerr << "ltc_export: cannot write " << path.string() << "\n";
        std::exit(1);
    }
    if (!quiet) std::cout << "  " << path.string() << " (" << size << " bytes)\n";
}

/// The largest float16 rounding of a texture's values: relative in half's normal range, absolute
/// below it.
void half_rounding(const ltc::rgba_texture& t, double& relative, double& absolute) {
    for (float v : t.texels) {
        const double e = std::abs(double(ltc::half_to_float(ltc::float_to_half(v))) - double(v));
        if (std::abs(v) >= std::ldexp(1.0f, -14)) relative = std::max(relative, e / std::abs(double(v)));
        else absolute = std::max(absolute, e);
    }
}

void export_table(const arguments& a, const ltc::ltc_table& table, const std::string& name, const std::string& note = "") {
    const std::filesystem::path dir(a.out);
    const ltc::paper_textures p = ltc::to_paper_textures(table);
    if (!a.quiet)
        std::cout << name << ": " << p.ltc_1.width << " x " << p.ltc_1.height << " texels (x = roughness, y = u)\n";
    for (const auto& [tex, which] : {std::pair{&p.ltc_1, "_ltc_1"}, std::pair{&p.ltc_2, "_ltc_2"}}) {
        const std::string base = name + which;
        for (float v : tex->texels)
            if (!std::isfinite(v)) fail(base + ": the table holds a value that is not finite");
        if (wants(a, "dds32")) {
            const auto b = ltc::write_dds(*tex, ltc::dds_format::rgba32_float);
            write_bytes(dir / (base + ".dds"), b.data(), b.size(), a.quiet);
        }
        if (wants(a, "dds16")) {
            if (const std::size_t n = ltc::half_overflows(*tex); n > 0) {
                std::cerr << "ltc_export: " << base << "_f16.dds left out: " << n
                          << " value(s) beyond float16's range (65504)\n";
            } else {
                const auto b = ltc::write_dds(*tex, ltc::dds_format::rgba16_float);
                write_bytes(dir / (base + "_f16.dds"), b.data(), b.size(), a.quiet);
                double relative = 0, absolute = 0;
                half_rounding(*tex, relative, absolute);
                if (!a.quiet)
                    std::printf("    largest float16 rounding: %.3g relative (2^%.2f), %.3g absolute below 2^-14\n",
                                relative, relative > 0 ? std::log2(relative) : -INFINITY, absolute);
            }
        }
        if (wants(a, "raw")) {
            const auto b = ltc::write_raw_float32(*tex);
            write_bytes(dir / (base + ".f32"), b.data(), b.size(), a.quiet);
            const std::string j = ltc::raw_descriptor_json(*tex, base + ".f32");
            write_bytes(dir / (base + ".json"), j.data(), j.size(), a.quiet);
        }
    }
    for (const bool glsl : {true, false}) {
        if (!wants(a, glsl ? "glsl" : "hlsl")) continue;
        const std::string s =
            ltc::shader_constants(p, name, glsl ? ltc::shading_language::glsl : ltc::shading_language::hlsl, note);
        write_bytes(dir / (name + (glsl ? ".glsl" : ".hlsl")), s.data(), s.size(), a.quiet);
    }
    if (wants(a, "threejs")) {
        if (ltc::half_overflows(p.ltc_1) + ltc::half_overflows(p.ltc_2) > 0) {
            std::cerr << "ltc_export: " << name << "_threejs.js left out: its half-float textures would hold "
                      << "values beyond float16's range (65504)\n";
        } else {
            const std::string s = ltc::threejs_module(p, name, note);
            write_bytes(dir / (name + "_threejs.js"), s.data(), s.size(), a.quiet);
        }
    }
    if (wants(a, "blender")) {
        // EEVEE's arrays and its UTIL_TEX_SIZE are 64 x 64, and it uploads them as half floats.
        if (p.ltc_1.width != 64 || p.ltc_1.height != 64) {
            if (!a.quiet)
                std::cout << "  " << name << "_eevee_lut.* left out: EEVEE's tables are 64 x 64, this one is "
                          << p.ltc_1.width << " x " << p.ltc_1.height << "\n";
        } else if (ltc::half_overflows(p.ltc_1) + ltc::half_overflows(p.ltc_2) > 0) {
            std::cerr << "ltc_export: " << name << "_eevee_lut.* left out: EEVEE's RGBA16F utility texture would hold "
                      << "values beyond float16's range (65504)\n";
        } else {
            using ltc::eevee_declaration;
            for (const auto& [declaration, suffix] :
                 {std::pair{eevee_declaration::float_arrays, "_eevee_lut.cc"},
                  std::pair{eevee_declaration::vec_base, "_eevee_lut_vecbase.cc"},
                  std::pair{eevee_declaration::flat_c, "_eevee_lut.c"}}) {
                const std::string s = ltc::eevee_lut_source(p, declaration, note);
                write_bytes(dir / (name + suffix), s.data(), s.size(), a.quiet);
            }
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    const arguments a = parse(argc, argv);
    std::error_code ec;
    std::filesystem::create_directories(a.out, ec);
    if (ec) fail("cannot create " + a.out + ": " + ec.message());
    using ltc::two_lobe_layout_table;
    if (a.table == "ggx" || a.table == "all") export_table(a, ltc::ggx::table, "ggx");
    for (int l = 0; l < 2; ++l) {
        const std::string lobe = std::to_string(l + 1);
        if (a.table == "two_lobe" || a.table == "all")
            export_table(a, two_lobe_layout_table(ltc::tables::ggx_two_lobe_data, ltc::tables::ggx_two_lobe_size, l),
                         "ggx_two_lobe_" + lobe);
        if (a.table == "cosine_lobe" || a.table == "all")
            export_table(a,
                         two_lobe_layout_table(ltc::tables::ggx_cosine_lobe_data, ltc::tables::ggx_cosine_lobe_size, l),
                         "ggx_cosine_lobe_" + lobe,
                         l == 0 ? "The clamped cosine's lobe: m_inv is the identity."
                                : "ltc_1 is premultiplied by ltc_2.x: divide it by ltc_2.x after interpolating.");
    }
    return 0;
}
