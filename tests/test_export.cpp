// Tests of ltc/tables/export.hpp: float_to_half against every half and every midpoint between two,
// the exported textures and files read back texel by texel the way a shader reads them, and the
// paper's table through the same writer against the paper's reference DDS files
// (../shared/peers/ggx/, skipped with a warning where that folder is absent).
#include <catch2/catch.hpp>

#include <ltc/shading/ggx_fetch.hpp>
#include <ltc/tables/export.hpp>
#include <ltc/tables/ggx_cosine_lobe.hpp>
#include <ltc/tables/ggx_two_lobe.hpp>
#include <ltc/tables/ltc_table.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#ifndef LTC_TEST_PEERS_DIR
#define LTC_TEST_PEERS_DIR "../shared/peers"
#endif

namespace ltc_test_export {  // the file's own names, apart from the other files of a unity batch

namespace {

using bytes = std::vector<unsigned char>;

std::uint32_t u32_at(const bytes& b, std::size_t at) {
    return std::uint32_t(b[at]) | std::uint32_t(b[at + 1]) << 8 | std::uint32_t(b[at + 2]) << 16 |
           std::uint32_t(b[at + 3]) << 24;
}

float f32_of(std::uint32_t u) {
    float f;
    std::memcpy(&f, &u, sizeof f);
    return f;
}

std::uint32_t bits_of(float f) {
    std::uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    return u;
}

/// A DDS file as a shader sees it: texel (x, y), channel c, half floats widened to float.
struct dds_view {
    const bytes* b = nullptr;
    std::size_t data = 0;
    std::uint32_t width = 0, height = 0;
    bool half = false;

    std::uint16_t half_at(std::uint32_t x, std::uint32_t y, int c) const {
        const std::size_t at = data + ((std::size_t(y) * width + x) * 4 + std::size_t(c)) * 2;
        return static_cast<std::uint16_t>((*b)[at] | (*b)[at + 1] << 8);
    }
    float texel(std::uint32_t x, std::uint32_t y, int c) const {
        if (half) return ltc::half_to_float(half_at(x, y, c));
        return f32_of(u32_at(*b, data + ((std::size_t(y) * width + x) * 4 + std::size_t(c)) * 4));
    }
};

/// Parses the header the way a loader does (DX10 extension or legacy FourCC 113/116).
dds_view parse_dds(const bytes& b) {
    dds_view v;
    REQUIRE(b.size() >= 128);
    REQUIRE(std::string(b.begin(), b.begin() + 4) == "DDS ");
    REQUIRE(u32_at(b, 4) == 124);
    v.b = &b;
    v.height = u32_at(b, 12);
    v.width = u32_at(b, 16);
    const std::uint32_t fourcc = u32_at(b, 84);
    if (fourcc == 0x30315844u) {  // "DX10"
        REQUIRE(b.size() >= 148);
        const std::uint32_t dxgi = u32_at(b, 128);
        REQUIRE((dxgi == 2 || dxgi == 10));
        CHECK(u32_at(b, 132) == 3);  // TEXTURE2D
        CHECK(u32_at(b, 140) == 1);  // array size
        v.half = dxgi == 10;
        v.data = 148;
    } else {
        REQUIRE((fourcc == 113 || fourcc == 116));
        v.half = fourcc == 113;
        v.data = 128;
    }
    CHECK(u32_at(b, 20) == v.width * (v.half ? 8u : 16u));  // pitch
    REQUIRE(b.size() == v.data + std::size_t(v.width) * v.height * (v.half ? 8u : 16u));
    return v;
}

/// Half's rounding bound: 2^-11 relative in the normal range, 2^-25 absolute below it.
bool within_half_rounding(float h, float v) {
    return std::abs(double(h) - double(v)) <= std::max(std::ldexp(std::abs(double(v)), -11), std::ldexp(1.0, -25));
}

bytes read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// The numbers between `open` (e.g. "const LTC_MAT_1 = new Float32Array( [") and the next "]", as
/// a reader of the text parses them: each decimal to the nearest double (JavaScript's numbers,
/// strtod), then, for a float array, to the nearest float.
std::vector<double> numbers_after(const std::string& text, const std::string& open) {
    std::vector<double> out;
    const std::size_t at = text.find(open);
    REQUIRE(at != std::string::npos);
    const std::size_t end = text.find(']', at + open.size());
    REQUIRE(end != std::string::npos);
    const std::string body = text.substr(at + open.size(), end - at - open.size());
    const char* p = body.c_str();
    for (;;) {
        while (*p == ' ' || *p == '\t' || *p == '\n' || *p == ',') ++p;
        if (*p == 0) break;
        char* next = nullptr;
        out.push_back(std::strtod(p, &next));
        REQUIRE(next != p);
        p = next;
    }
    return out;
}

/// A GLSL/HLSL constant array's texels: the four numbers of each "vec4(" (or "float4(") after `open`.
std::vector<float> shader_texels(const std::string& text, const std::string& open, const std::string& vec) {
    std::vector<float> out;
    std::size_t at = text.find(open);
    REQUIRE(at != std::string::npos);
    at += open.size();
    const std::size_t end = text.find(';', at);
    for (std::size_t k = text.find(vec + "(", at); k < end; k = text.find(vec + "(", k)) {
        const char* p = text.c_str() + k + vec.size() + 1;
        for (int c = 0; c < 4; ++c) {
            char* next = nullptr;
            out.push_back(std::strtof(p, &next));
            REQUIRE(next != p);
            p = next;
            while (*p == ',' || *p == ' ') ++p;
        }
        k = std::size_t(p - text.c_str());
    }
    return out;
}

/// The floats of a C/C++ array definition (e.g. "const float ltc_mat_ggx[64][64][4] = {") up to
/// its "};", each literal parsed as the compiler does (to the nearest float); `braces` counts the
/// "{" inside, the nesting of the initializer.
std::vector<float> c_array(const std::string& text, const std::string& open, int& braces) {
    std::vector<float> out;
    const std::size_t at = text.find(open);
    REQUIRE(at != std::string::npos);
    const std::size_t end = text.find("};", at + open.size());
    REQUIRE(end != std::string::npos);
    const std::string body = text.substr(at + open.size(), end - at - open.size());
    braces = 0;
    const char* p = body.c_str();
    for (;;) {
        while (*p == ' ' || *p == '\n' || *p == ',' || *p == '{' || *p == '}') braces += *p++ == '{';
        if (*p == 0) break;
        char* next = nullptr;
        out.push_back(std::strtof(p, &next));
        REQUIRE(next != p);
        REQUIRE(*next == 'f');  // a float literal, not a double narrowed by the initializer
        p = next + 1;
    }
    return out;
}

}  // namespace

TEST_CASE("float_to_half: the edge cases", "[export]") {
    using ltc::float_to_half;
    const float inf = std::numeric_limits<float>::infinity();
    CHECK(float_to_half(0.0f) == 0x0000);
    CHECK(float_to_half(-0.0f) == 0x8000);
    CHECK(float_to_half(1.0f) == 0x3c00);
    CHECK(float_to_half(-2.0f) == 0xc000);
    CHECK(float_to_half(65504.0f) == 0x7bff);                      // the largest half
    CHECK(float_to_half(std::nextafter(65520.0f, 0.0f)) == 0x7bff);  // just below the tie
    CHECK(float_to_half(65520.0f) == 0x7c00);                      // the tie rounds to the even: inf
    CHECK(float_to_half(-65520.0f) == 0xfc00);
    CHECK(float_to_half(1e10f) == 0x7c00);
    CHECK(float_to_half(std::numeric_limits<float>::max()) == 0x7c00);
    CHECK(float_to_half(inf) == 0x7c00);
    CHECK(float_to_half(-inf) == 0xfc00);
    CHECK(float_to_half(std::ldexp(1.0f, -14)) == 0x0400);                            // least normal
    CHECK(float_to_half(std::ldexp(1.0f, -14) - std::ldexp(1.0f, -25)) == 0x0400);  // tie 0x3ff|0x400
    CHECK(float_to_half(std::ldexp(1.0f, -24)) == 0x0001);                            // least subnormal
    CHECK(float_to_half(std::ldexp(1.0f, -25)) == 0x0000);                            // tie 0|1: even 0
    CHECK(float_to_half(-std::ldexp(1.0f, -25)) == 0x8000);
    CHECK(float_to_half(std::nextafter(std::ldexp(1.0f, -25), 1.0f)) == 0x0001);
    CHECK(float_to_half(3 * std::ldexp(1.0f, -25)) == 0x0002);  // tie 1|2: even 2
    CHECK(float_to_half(5 * std::ldexp(1.0f, -25)) == 0x0002);  // tie 2|3: even 2
    CHECK(float_to_half(std::numeric_limits<float>::min()) == 0x0000);
    CHECK(float_to_half(std::numeric_limits<float>::denorm_min()) == 0x0000);
    CHECK(float_to_half(-std::numeric_limits<float>::denorm_min()) == 0x8000);
    CHECK(float_to_half(1.0f + std::ldexp(1.0f, -11)) == 0x3c00);  // tie: even
    CHECK(float_to_half(1.0f + 3 * std::ldexp(1.0f, -11)) == 0x3c02);
    // NaN stays NaN (quiet), whatever its payload; a signalling NaN whose payload sits in the bits
    // that are dropped must not become infinity.
    for (std::uint32_t nan : {0x7fc00000u, 0xffc00000u, 0x7f800001u, 0x7fbfffffu, 0xff800001u, 0x7fffffffu}) {
        const std::uint16_t h = float_to_half(f32_of(nan));
        CHECK((h & 0x7c00) == 0x7c00);
        CHECK((h & 0x0200) != 0);
        CHECK((h & 0x8000) == ((nan >> 16) & 0x8000));
        CHECK(std::isnan(ltc::half_to_float(h)));
    }
}

TEST_CASE("float_to_half: every half round-trips and every midpoint rounds to even", "[export]") {
    int failures = 0;
    for (std::uint32_t h = 0; h < 0x10000u; ++h) {
        const auto hh = static_cast<std::uint16_t>(h);
        const float f = ltc::half_to_float(hh);
        if ((h & 0x7c00u) == 0x7c00u && (h & 0x3ffu) != 0) {
            failures += !std::isnan(f);
            continue;
        }
        failures += ltc::float_to_half(f) != hh;
        if ((h & 0x7fffu) >= 0x7c00u) continue;  // inf: no upper neighbour
        // The midpoint between h and the next half away from zero (12 significant bits: a float),
        // and the floats on either side of it.
        const auto up = static_cast<std::uint16_t>(h + 1);
        const float g = (h & 0x7fffu) == 0x7bffu ? std::copysign(65536.0f, f) : ltc::half_to_float(up);
        const float mid = f + (g - f) / 2;
        const std::uint16_t even = (h & 1u) ? up : hh;
        failures += ltc::float_to_half(mid) != even;
        failures += ltc::float_to_half(std::nextafter(mid, f)) != hh;
        failures += ltc::float_to_half(std::nextafter(mid, g)) != up;
    }
    CHECK(failures == 0);
}

TEST_CASE("to_paper_textures: texel (x = roughness node, y = u node) as the paper's shader reads it", "[export]") {
    const ltc::ltc_table& table = ltc::ggx::table;
    const ltc::paper_textures p = ltc::to_paper_textures(table);
    const int n = table.width();
    REQUIRE(p.ltc_1.width == table.height());
    REQUIRE(p.ltc_1.height == n);
    REQUIRE(p.ltc_2.texels.size() == std::size_t(n) * std::size_t(n) * 4);
    int mismatches = 0;
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < table.height(); ++x) {
            // The shader: mInv = mat3(vec3(t1.x, 0, t1.y), vec3(0, 1, 0), vec3(t1.z, 0, t1.w)).
            const glm::mat3 m_inv(glm::vec3(p.ltc_1.texel(x, y, 0), 0, p.ltc_1.texel(x, y, 1)), glm::vec3(0, 1, 0),
                                  glm::vec3(p.ltc_1.texel(x, y, 2), 0, p.ltc_1.texel(x, y, 3)));
            const double u = double(y) / (n - 1), roughness = double(x) / (table.height() - 1);
            const ltc::ltc_coefficients<double> c = ltc::ggx::fetch(1 - u * u, roughness);
            for (int col = 0; col < 3; ++col)
                for (int row = 0; row < 3; ++row) mismatches += double(m_inv[col][row]) != c.m_inv[col][row];
            mismatches += double(p.ltc_2.texel(x, y, 0)) != c.magnitude;
            mismatches += double(p.ltc_2.texel(x, y, 1)) != c.fresnel;
            mismatches += p.ltc_2.texel(x, y, 2) != 0.0f || p.ltc_2.texel(x, y, 3) != 0.0f;
        }
    }
    CHECK(mismatches == 0);
}

TEST_CASE("DDS and raw files read back texel by texel: float32 exactly, float16 within its rounding", "[export]") {
    using ltc::two_lobe_layout_table;
    const ltc::ltc_table tables[] = {
        ltc::ggx::table,
        two_lobe_layout_table(ltc::tables::ggx_two_lobe_data, ltc::tables::ggx_two_lobe_size, 0),
        two_lobe_layout_table(ltc::tables::ggx_two_lobe_data, ltc::tables::ggx_two_lobe_size, 1),
        two_lobe_layout_table(ltc::tables::ggx_cosine_lobe_data, ltc::tables::ggx_cosine_lobe_size, 0),
        two_lobe_layout_table(ltc::tables::ggx_cosine_lobe_data, ltc::tables::ggx_cosine_lobe_size, 1)};
    for (const ltc::ltc_table& table : tables) {
        const ltc::paper_textures p = ltc::to_paper_textures(table);
        int bad32 = 0, bad16 = 0, bad_raw = 0;
        std::size_t overflows = 0;
        for (const ltc::rgba_texture* tex : {&p.ltc_1, &p.ltc_2}) {
            for (ltc::dds_header kind : {ltc::dds_header::dx10, ltc::dds_header::legacy}) {
                const bytes f32 = ltc::write_dds(*tex, ltc::dds_format::rgba32_float, kind);
                const bytes f16 = ltc::write_dds(*tex, ltc::dds_format::rgba16_float, kind);
                const dds_view v32 = parse_dds(f32), v16 = parse_dds(f16);
                REQUIRE(v32.width == std::uint32_t(table.height()));
                REQUIRE(v32.height == std::uint32_t(table.width()));
                REQUIRE(!v32.half);
                REQUIRE(v16.half);
                for (int t = 0; t < table.width(); ++t) {
                    for (int a = 0; a < table.height(); ++a) {
                        for (int c = 0; c < 4; ++c) {
                            const float want = tex == &p.ltc_1 ? table.node(t, a, c)
                                               : c < 2         ? table.node(t, a, ltc::channel::magnitude + c)
                                                               : 0.0f;
                            const auto x = std::uint32_t(a), y = std::uint32_t(t);
                            bad32 += bits_of(v32.texel(x, y, c)) != bits_of(want);
                            const float got = v16.texel(x, y, c);
                            if (std::abs(want) >= 65520.0f) {  // beyond half's range: inf, counted
                                ++overflows;
                                bad16 += got != std::copysign(std::numeric_limits<float>::infinity(), want);
                            } else {
                                bad16 += v16.half_at(x, y, c) != ltc::float_to_half(want) ||
                                         !within_half_rounding(got, want);
                            }
                        }
                    }
                }
            }
            const bytes raw = ltc::write_raw_float32(*tex);
            REQUIRE(raw.size() == tex->texels.size() * 4);
            for (std::size_t i = 0; i < tex->texels.size(); ++i)
                bad_raw += bits_of(f32_of(u32_at(raw, 4 * i))) != bits_of(tex->texels[i]);
        }
        CHECK(bad32 == 0);
        CHECK(bad16 == 0);
        CHECK(bad_raw == 0);
        // Each texture was written twice (the two header kinds).
        CHECK(overflows == 2 * (ltc::half_overflows(p.ltc_1) + ltc::half_overflows(p.ltc_2)));
    }
    // The paper's one-lobe table fits in halves; the two-lobe table's second lobe does not
    // everywhere (a nearly specular lobe's matrix entries beyond 65504).
    const ltc::paper_textures one_lobe = ltc::to_paper_textures(ltc::ggx::table);
    CHECK(ltc::half_overflows(one_lobe.ltc_1) + ltc::half_overflows(one_lobe.ltc_2) == 0);
}

TEST_CASE("raw_descriptor_json: size, channels and the LUT scale and bias", "[export]") {
    const ltc::paper_textures p = ltc::to_paper_textures(ltc::ggx::table);
    const std::string j = ltc::raw_descriptor_json(p.ltc_1, "ggx_ltc_1.f32");
    CHECK(j.find("\"file\": \"ggx_ltc_1.f32\"") != std::string::npos);
    CHECK(j.find("\"width\": 64,") != std::string::npos);
    CHECK(j.find("\"height\": 64,") != std::string::npos);
    CHECK(j.find("\"channels\": 4,") != std::string::npos);
    CHECK(j.find("\"bytes\": 65536,") != std::string::npos);
    CHECK(j.find("\"channel_names\": [\"m_inv[0][0]\", \"m_inv[0][2]\", \"m_inv[2][0]\", \"m_inv[2][2]\"]") !=
          std::string::npos);
    CHECK(j.find("\"lut_scale\": [0.984375, 0.984375]") != std::string::npos);  // 63 / 64
    CHECK(j.find("\"lut_bias\": [0.0078125, 0.0078125]") != std::string::npos);  // 0.5 / 64
    CHECK(j.front() == '{');
    CHECK(j.find_last_of('}') == j.size() - 2);
}

TEST_CASE("the paper's table through write_dds gives the reference code's DDS files", "[export]") {
    const std::string dir = std::string(LTC_TEST_PEERS_DIR) + "/ggx/";
    const bytes ref_1 = read_file(dir + "ltc_code_ltc_1.dds"), ref_2 = read_file(dir + "ltc_code_ltc_2.dds");
    std::ifstream text(dir + "ltc_code_ggx.txt");
    if (ref_1.empty() || ref_2.empty() || !text) {
        WARN("no reference files in " << dir << ": the comparison with the paper's DDS files is skipped");
        return;
    }
    // The text's columns: t a m00 m02 m20 m22 magnitude, the normalized inverse row-major
    // [[m00, 0, m02], [0, 1, 0], [m20, 0, m22]]: m20 (row 2, column 0) is GLM's m_inv[0][2].
    const int n = 64;
    std::vector<float> data(std::size_t(n) * n * ltc::channel::count, 0.0f);
    int rows = 0;
    for (std::string line; std::getline(text, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream in(line);
        int t = -1, a = -1;
        float m00, m02, m20, m22, magnitude;
        in >> t >> a >> m00 >> m02 >> m20 >> m22 >> magnitude;
        REQUIRE(in);
        REQUIRE((t >= 0 && t < n && a >= 0 && a < n));
        float* node = &data[(std::size_t(a) * n + std::size_t(t)) * ltc::channel::count];
        node[ltc::channel::m_inv_00] = m00;
        node[ltc::channel::m_inv_02] = m20;
        node[ltc::channel::m_inv_20] = m02;
        node[ltc::channel::m_inv_22] = m22;
        node[ltc::channel::magnitude] = magnitude;
        ++rows;
    }
    REQUIRE(rows == n * n);
    const ltc::paper_textures p = ltc::to_paper_textures(ltc::ltc_table(data.data(), n, n));
    const bytes legacy_1 = ltc::write_dds(p.ltc_1, ltc::dds_format::rgba16_float, ltc::dds_header::legacy);
    const bytes legacy_2 = ltc::write_dds(p.ltc_2, ltc::dds_format::rgba16_float, ltc::dds_header::legacy);
    const bytes dx10_1 = ltc::write_dds(p.ltc_1, ltc::dds_format::rgba16_float);
    REQUIRE(legacy_1.size() == ref_1.size());
    REQUIRE(legacy_2.size() == ref_2.size());
    // The headers: byte for byte with the legacy FourCC (the reference code's), and the same
    // fields but the pixel format's FourCC with the DX10 extension.
    CHECK(std::equal(ref_1.begin(), ref_1.begin() + 128, legacy_1.begin()));
    CHECK(std::equal(ref_2.begin(), ref_2.begin() + 128, legacy_2.begin()));
    for (std::size_t at = 0; at < 128; at += 4)
        if (at != 84) CHECK(u32_at(dx10_1, at) == u32_at(ref_1, at));
    CHECK(u32_at(dx10_1, 128) == 10);  // DXGI_FORMAT_R16G16B16A16_FLOAT
    // The texels: ltc_1's four channels and ltc_2's magnitude and zero (the text holds neither the
    // Fresnel term nor the sphere term). The text's six significant digits round a few values to
    // the neighbouring half: at most one step of the last bit, anywhere.
    const dds_view r1 = parse_dds(ref_1), r2 = parse_dds(ref_2), o1 = parse_dds(legacy_1), o2 = parse_dds(legacy_2);
    int differ = 0, far = 0, compared = 0;
    const auto compare = [&](const dds_view& ours, const dds_view& ref, std::uint32_t x, std::uint32_t y, int c) {
        const int d = int(ours.half_at(x, y, c)) - int(ref.half_at(x, y, c));
        ++compared;
        differ += d != 0;
        far += d < -1 || d > 1;
    };
    for (std::uint32_t y = 0; y < std::uint32_t(n); ++y) {
        for (std::uint32_t x = 0; x < std::uint32_t(n); ++x) {
            for (int c = 0; c < 4; ++c) compare(o1, r1, x, y, c);
            compare(o2, r2, x, y, 0);
            compare(o2, r2, x, y, 2);
        }
    }
    WARN(differ << " of " << compared << " reference texel channels differ in the last bit of the half");
    CHECK(far == 0);
    CHECK(differ * 100 <= compared);  // at most one in a hundred
}

TEST_CASE("threejs_module: three.js's RectAreaLightTexturesLib layout, sampled as its shader does, is the table at every node",
          "[export]") {
    const ltc::ltc_table& table = ltc::ggx::table;
    const ltc::paper_textures p = ltc::to_paper_textures(table);
    const std::string js = ltc::threejs_module(p, "ggx");
    const int n = table.width(), m = table.height();  // u nodes (texture y), roughness nodes (texture x)
    const std::vector<double> mat_1 = numbers_after(js, "const LTC_MAT_1 = new Float32Array( [");
    const std::vector<double> mat_2 = numbers_after(js, "const LTC_MAT_2 = new Float32Array( [");
    const std::vector<double> half_1 = numbers_after(js, "const LTC_HALF_MAT_1 = new Uint16Array( [");
    const std::vector<double> half_2 = numbers_after(js, "const LTC_HALF_MAT_2 = new Uint16Array( [");
    const std::size_t texels = std::size_t(n) * std::size_t(m);
    for (const auto* a : {&mat_1, &mat_2, &half_1, &half_2}) REQUIRE(a->size() == texels * 4);
    CHECK(js.find("new DataTexture( data, " + std::to_string(m) + ", " + std::to_string(n) +
                  ", RGBAFormat, type, UVMapping, ClampToEdgeWrapping, ClampToEdgeWrapping, LinearFilter, NearestFilter, 1 )") !=
          std::string::npos);
    CHECK(js.find("export { RectAreaLightTexturesLib };") != std::string::npos);
    for (const char* texture : {"LTC_FLOAT_1", "LTC_FLOAT_2", "LTC_HALF_1", "LTC_HALF_2"})
        CHECK(js.find(std::string("this.") + texture + " = ltcTexture(") != std::string::npos);
    int mismatches = 0, half_mismatches = 0, off_node = 0;
    for (int t = 0; t < n; ++t) {
        for (int a = 0; a < m; ++a) {
            // three.js's LTC_Uv: uv = (roughness, sqrt(1 - dotNV)) * LUT_SCALE + LUT_BIAS, which
            // lands on the centre of texel (a, t); nearest texel = the bilinear lookup there.
            const double roughness = double(a) / (m - 1), u = double(t) / (n - 1);
            const double uv_x = roughness * (m - 1) / m + 0.5 / m, uv_y = u * (n - 1) / n + 0.5 / n;
            const double x = uv_x * m - 0.5, y = uv_y * n - 0.5;
            off_node += std::abs(x - a) > 1e-9 || std::abs(y - t) > 1e-9;
            const std::size_t i = (std::size_t(t) * std::size_t(m) + std::size_t(a)) * 4;
            const auto f = [&](const std::vector<double>& v, std::size_t c) { return float(v[i + c]); };
            // mInv = mat3( vec3( t1.x, 0, t1.y ), vec3( 0, 1, 0 ), vec3( t1.z, 0, t1.w ) ) (columns)
            const glm::mat3 m_inv(glm::vec3(f(mat_1, 0), 0, f(mat_1, 1)), glm::vec3(0, 1, 0),
                                  glm::vec3(f(mat_1, 2), 0, f(mat_1, 3)));
            const ltc::ltc_coefficients<double> c = ltc::ggx::fetch(1 - u * u, roughness);
            for (int col = 0; col < 3; ++col)
                for (int row = 0; row < 3; ++row) mismatches += double(m_inv[col][row]) != c.m_inv[col][row];
            // fresnel = specularColor * t2.x + ( specularF90 - specularColor ) * t2.y
            mismatches += double(f(mat_2, 0)) != c.magnitude;
            mismatches += double(f(mat_2, 1)) != c.fresnel;
            mismatches += f(mat_2, 2) != 0.0f || f(mat_2, 3) != 0.0f;
            // The half textures: each value the float's half, rounded to nearest even.
            for (std::size_t k = 0; k < 4; ++k) {
                half_mismatches += half_1[i + k] != double(ltc::float_to_half(f(mat_1, k)));
                half_mismatches += half_2[i + k] != double(ltc::float_to_half(f(mat_2, k)));
                half_mismatches += !within_half_rounding(ltc::half_to_float(std::uint16_t(half_1[i + k])), f(mat_1, k));
            }
        }
    }
    CHECK(off_node == 0);
    CHECK(mismatches == 0);
    CHECK(half_mismatches == 0);
}

TEST_CASE("shader_constants: the GLSL and HLSL arrays hold every texel, reading back to the same floats", "[export]") {
    const ltc::paper_textures p =
        ltc::to_paper_textures(ltc::two_lobe_layout_table(ltc::tables::ggx_two_lobe_data, ltc::tables::ggx_two_lobe_size, 1));
    for (const auto language : {ltc::shading_language::glsl, ltc::shading_language::hlsl}) {
        const bool glsl = language == ltc::shading_language::glsl;
        const std::string vec = glsl ? "vec4" : "float4";
        const std::string text = ltc::shader_constants(p, "lobe", language, "a note");
        const std::string count = std::to_string(p.ltc_1.texels.size() / 4);
        CHECK(text.find("#define LOBE_WIDTH " + std::to_string(p.ltc_1.width) + "\n") != std::string::npos);
        CHECK(text.find("#define LOBE_HEIGHT " + std::to_string(p.ltc_1.height) + "\n") != std::string::npos);
        CHECK(text.find("// a note\n") != std::string::npos);
        for (const ltc::rgba_texture* t : {&p.ltc_1, &p.ltc_2}) {
            const std::string open = std::string(glsl ? "const " : "static const ") + vec + " lobe" +
                                     (t == &p.ltc_1 ? "_ltc_1" : "_ltc_2") + "[" + count + "] = ";
            const std::vector<float> texels = shader_texels(text, open, vec);
            REQUIRE(texels.size() == t->texels.size());
            int mismatches = 0;
            for (std::size_t k = 0; k < texels.size(); ++k) mismatches += bits_of(texels[k]) != bits_of(t->texels[k]);
            CHECK(mismatches == 0);
        }
    }
}

TEST_CASE("eevee_lut_source: EEVEE's ltc_mat_ggx and ltc_mag_ggx, sampled as its shaders do, are the table at every node",
          "[export]") {
    const ltc::ltc_table& table = ltc::ggx::table;
    const ltc::paper_textures p = ltc::to_paper_textures(table);
    const int n = table.width(), m = table.height();  // u nodes (EEVEE's rows), roughness nodes (its columns)
    REQUIRE(n == 64);  // EEVEE's UTIL_TEX_SIZE
    REQUIRE(m == 64);
    const std::string rows = std::to_string(n), columns = std::to_string(m);
    using ltc::eevee_declaration;
    for (const eevee_declaration declaration :
         {eevee_declaration::float_arrays, eevee_declaration::vec_base, eevee_declaration::flat_c}) {
        const std::string text = ltc::eevee_lut_source(p, declaration, "a note");
        const bool flat = declaration == eevee_declaration::flat_c;
        std::string mat_open, mag_open;
        switch (declaration) {
            case eevee_declaration::float_arrays:
                mat_open = "const float ltc_mat_ggx[" + rows + "][" + columns + "][4] = {";
                mag_open = "const float ltc_mag_ggx[" + rows + "][" + columns + "][2] = {";
                break;
            case eevee_declaration::vec_base:
                mat_open = "const VecBase<float, 4> ltc_mat_ggx[" + rows + "][" + columns + "] = {";
                mag_open = "const VecBase<float, 2> ltc_mag_ggx[" + rows + "][" + columns + "] = {";
                break;
            case eevee_declaration::flat_c:
                mat_open = "const float ltc_mat_ggx[" + rows + " * " + columns + " * 4] = {";
                mag_open = "const float ltc_mag_ggx[" + rows + " * " + columns + " * 2] = {";
                break;
        }
        int mat_braces = 0, mag_braces = 0;
        const std::vector<float> mat = c_array(text, mat_open, mat_braces);
        const std::vector<float> mag = c_array(text, mag_open, mag_braces);
        const std::size_t texels = std::size_t(n) * std::size_t(m);
        REQUIRE(mat.size() == texels * 4);
        REQUIRE(mag.size() == texels * 2);
        // Nested: a brace for each row and each texel (what float[64][64][4] and VecBase<float, 4>[64][64]
        // both take); flat: none inside.
        CHECK(mat_braces == (flat ? 0 : n + n * m));
        CHECK(mag_braces == (flat ? 0 : n + n * m));
        CHECK((text.find("namespace blender::eevee::lut {") != std::string::npos) == !flat);
        CHECK(text.find("/* a note */") != std::string::npos);
        int mismatches = 0, off_node = 0, beyond_half = 0;
        for (int t = 0; t < n; ++t) {
            for (int a = 0; a < m; ++a) {
                // utility_tx_sample_lut: uv = (roughness, sqrt(clamp(1 - cos_theta, 0, 1))) *
                // UTIL_TEX_UV_SCALE + UTIL_TEX_UV_BIAS, (64 - 1) / 64 and 0.5 / 64: the centre of texel (a, t).
                const double roughness = double(a) / (m - 1), u = double(t) / (n - 1), cos_theta = 1 - u * u;
                const double uv_x = roughness * (m - 1) / m + 0.5 / m;
                const double uv_y = std::sqrt(std::min(std::max(1 - cos_theta, 0.0), 1.0)) * (n - 1) / n + 0.5 / n;
                off_node += std::abs(uv_x * m - 0.5 - a) > 1e-9 || std::abs(uv_y * n - 0.5 - t) > 1e-9;
                // The layer is the array copied row by row: texel (x, y) = ltc_mat_ggx[y][x].
                const std::size_t i = std::size_t(t) * std::size_t(m) + std::size_t(a);
                const auto v = [&](std::size_t c) { return mat[4 * i + c]; };
                // ltc::unpack: float3x3(float3(v.x, 0, v.y), float3(0, 1, 0), float3(v.z, 0, v.w)) (columns).
                const glm::mat3 m_inv(glm::vec3(v(0), 0, v(1)), glm::vec3(0, 1, 0), glm::vec3(v(2), 0, v(3)));
                const ltc::ltc_coefficients<double> c = ltc::ggx::fetch(cos_theta, roughness);
                for (int col = 0; col < 3; ++col)
                    for (int row = 0; row < 3; ++row) mismatches += double(m_inv[col][row]) != c.m_inv[col][row];
                mismatches += double(mag[2 * i]) != c.magnitude;
                mismatches += double(mag[2 * i + 1]) != c.fresnel;
                // EEVEE uploads its utility texture as RGBA16F.
                for (std::size_t k = 0; k < 4; ++k) beyond_half += std::abs(v(k)) >= 65520.0f;
                beyond_half += std::abs(mag[2 * i]) >= 65520.0f || std::abs(mag[2 * i + 1]) >= 65520.0f;
            }
        }
        CHECK(off_node == 0);
        CHECK(mismatches == 0);
        CHECK(beyond_half == 0);
    }
}

}  // namespace ltc_test_export
