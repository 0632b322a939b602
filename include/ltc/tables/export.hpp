// ltc/tables/export.hpp -- a table (ltc/tables/ltc_table.hpp) in the formats GPU engines load: the
// paper's two RGBA textures, IEEE half floats, DDS files, raw floats with a JSON descriptor,
// GLSL/HLSL constant arrays, a three.js module and the C/C++ arrays Blender's EEVEE compiles.
//
//   const ltc::paper_textures tex = ltc::to_paper_textures(ltc::ggx::table);
//   std::vector<unsigned char> dds = ltc::write_dds(tex.ltc_1, ltc::dds_format::rgba16_float);
//   std::vector<unsigned char> raw = ltc::write_raw_float32(tex.ltc_2);
//   std::string json = ltc::raw_descriptor_json(tex.ltc_2, "ltc_2.bin");
//
// Conventions: texel (x, y) of a texture is texels[(y * width + x) * 4 + channel], x fastest, the
// first row first (the order DDS and glTexImage2D take); x = roughness node, y = u node. All
// multi-byte values are written little-endian whatever the host's byte order. Degenerate cases:
// an empty table gives empty textures; float_to_half maps NaN to a quiet NaN.
#pragma once

#include <ltc/config.hpp>

#include <ltc/tables/ltc_table.hpp>

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

LTC_NAMESPACE_BEGIN

/// A 2D texture of 4 float channels, texel (x, y) at texels[(y * width + x) * 4 + c].
struct rgba_texture {
    int width = 0;
    int height = 0;
    std::vector<float> texels;
    std::array<const char*, 4> channel_names{{"r", "g", "b", "a"}};

    float texel(int x, int y, int c) const {
        return texels[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) *
                          4 +
                      static_cast<std::size_t>(c)];
    }
};

/// The paper's two textures (the reference code's ltc_1 and ltc_2, the layout its shaders and the
/// engines that took them read), each height() x width() texels of a table: texture x = roughness
/// node a (x = a, roughness = x / (w - 1)), y = u node t (u = sqrt(1 - cos theta_v) = y / (h - 1)),
/// i.e. the table transposed. The shaders sample them at
///   uv = (roughness, sqrt(1 - cos theta_v)) * (n - 1) / n + 0.5 / n      (LUT_SCALE, LUT_BIAS)
/// and read
///   ltc_1 = (m_inv[0][0], m_inv[0][2], m_inv[2][0], m_inv[2][2])   (table channels 0..3)
///   m_inv = mat3(vec3(t1.x, 0, t1.y), vec3(0, 1, 0), vec3(t1.z, 0, t1.w))   (GLSL columns)
///   ltc_2 = (magnitude, fresnel, 0, 0)
/// The reference code's ltc_2.w holds a sphere-light term of its own parameterization, which this
/// library does not tabulate: it is 0 here.
struct paper_textures {
    rgba_texture ltc_1;
    rgba_texture ltc_2;
};

inline paper_textures to_paper_textures(const ltc_table& table) {
    paper_textures p;
    const int w = table.height();  // texture x: roughness
    const int h = table.width();   // texture y: u
    for (rgba_texture* t : {&p.ltc_1, &p.ltc_2}) {
        t->width = w > 0 && h > 0 ? w : 0;
        t->height = w > 0 && h > 0 ? h : 0;
        t->texels.assign(static_cast<std::size_t>(t->width) * static_cast<std::size_t>(t->height) * 4, 0.0f);
    }
    p.ltc_1.channel_names = {{"m_inv[0][0]", "m_inv[0][2]", "m_inv[2][0]", "m_inv[2][2]"}};
    p.ltc_2.channel_names = {{"magnitude", "fresnel", "zero", "zero (the reference code's sphere term)"}};
    for (int y = 0; y < p.ltc_1.height; ++y) {
        for (int x = 0; x < p.ltc_1.width; ++x) {
            const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)) * 4;
            for (int c = 0; c < 4; ++c) p.ltc_1.texels[i + static_cast<std::size_t>(c)] = table.node(y, x, c);
            p.ltc_2.texels[i + 0] = table.node(y, x, channel::magnitude);
            p.ltc_2.texels[i + 1] = table.node(y, x, channel::fresnel);
        }
    }
    return p;
}

/// IEEE 754 binary16 (half) from a float, rounded to nearest, ties to even, as the conversion
/// instructions (F16C's vcvtps2ph with rounding mode 0, CUDA's __float2half_rn) do: exact for
/// every input. Halves have 10 mantissa bits, exponents -14..15 (normal: 2^-14 <= |h| <= 65504),
/// subnormals k 2^-24 (k < 1024). |x| >= 65520 (65504 plus half its ulp) gives infinity, |x| <=
/// 2^-25 a zero of x's sign; NaN gives a quiet NaN with the top bits of x's payload.
/// Relative error at most 2^-11 in the normal range, absolute at most 2^-25 below it.
inline std::uint16_t float_to_half(float x) {
    std::uint32_t b;
    std::memcpy(&b, &x, sizeof b);
    const auto sign = static_cast<std::uint16_t>((b >> 16) & 0x8000u);
    const std::uint32_t a = b & 0x7fffffffu;
    if (a > 0x7f800000u) return static_cast<std::uint16_t>(sign | 0x7e00u | ((a >> 13) & 0x3ffu));  // NaN
    if (a >= 0x477ff000u) return static_cast<std::uint16_t>(sign | 0x7c00u);  // >= 65520, inf
    if (a < 0x38800000u) {                                                    // below 2^-14
        if (a <= 0x33000000u) return sign;  // <= 2^-25 (the tie rounds to the even 0)
        // |x| = m 2^(e - 150) with the implicit bit in m; the half's k = |x| 2^24 = m 2^(e - 126).
        const std::uint32_t e = a >> 23;                      // 102 .. 112
        const std::uint32_t m = (a & 0x7fffffu) | 0x800000u;  // 24 bits
        const std::uint32_t shift = 126u - e;                 // 14 .. 24
        std::uint32_t k = m >> shift;
        const std::uint32_t rest = m & ((1u << shift) - 1u), halfway = 1u << (shift - 1u);
        if (rest > halfway || (rest == halfway && (k & 1u))) ++k;  // k = 1024: the least normal
        return static_cast<std::uint16_t>(sign | k);
    }
    // Normal: rebias the exponent (127 -> 15), keep 10 of the 23 mantissa bits, round the other 13;
    // a carry out of the mantissa steps the exponent, which is right (below 65520 it stays finite).
    std::uint32_t h = (a >> 13) - (112u << 10);
    const std::uint32_t rest = a & 0x1fffu;
    if (rest > 0x1000u || (rest == 0x1000u && (h & 1u))) ++h;
    return static_cast<std::uint16_t>(sign | h);
}

/// How many of a texture's values float_to_half turns into infinity (|v| >= 65520; NaN not
/// counted): a float16 file of a texture with any holds infinities where the table has large
/// matrix entries (a lobe that is nearly a delta), which a shader would propagate.
inline std::size_t half_overflows(const rgba_texture& t) {
    std::size_t n = 0;
    for (float v : t.texels) n += (v >= 65520.0f || v <= -65520.0f) ? 1u : 0u;
    return n;
}

/// The float of a half (exact: every half is a float).
inline float half_to_float(std::uint16_t h) {
    const std::uint32_t sign = static_cast<std::uint32_t>(h & 0x8000u) << 16;
    const std::uint32_t e = (h >> 10) & 0x1fu;
    std::uint32_t m = h & 0x3ffu;
    std::uint32_t b;
    if (e == 0x1fu) {
        b = sign | 0x7f800000u | (m << 13);  // inf, NaN
    } else if (e != 0) {
        b = sign | ((e + 112u) << 23) | (m << 13);
    } else if (m == 0) {
        b = sign;
    } else {  // subnormal m 2^-24: normalize
        std::uint32_t ee = 113;
        while (!(m & 0x400u)) {
            m <<= 1;
            --ee;
        }
        b = sign | (ee << 23) | ((m & 0x3ffu) << 13);
    }
    float f;
    std::memcpy(&f, &b, sizeof f);
    return f;
}

/// The texel formats of write_dds: DXGI_FORMAT_R32G32B32A32_FLOAT (2; legacy D3DFMT_A32B32G32R32F,
/// 116) and DXGI_FORMAT_R16G16B16A16_FLOAT (10; legacy D3DFMT_A16B16G16R16F, 113).
enum class dds_format { rgba32_float, rgba16_float };

/// The header kind: dx10 (FourCC "DX10" and the DDS_HEADER_DXT10 extension, which names the DXGI
/// format; what current loaders expect) or legacy (the D3DFMT number as FourCC, no extension; what
/// the paper's reference code writes, which older loaders read).
enum class dds_header { dx10, legacy };

namespace detail {
inline void put_u32(std::vector<unsigned char>& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<unsigned char>((v >> (8 * i)) & 0xffu));
}
inline void put_f32(std::vector<unsigned char>& out, float f) {
    std::uint32_t b;
    std::memcpy(&b, &f, sizeof b);
    put_u32(out, b);
}
inline void put_u16(std::vector<unsigned char>& out, std::uint16_t v) {
    out.push_back(static_cast<unsigned char>(v & 0xffu));
    out.push_back(static_cast<unsigned char>(v >> 8));
}
}  // namespace detail

/// A DDS file (Microsoft's "DDS" format: magic "DDS ", the 124-byte DDS_HEADER, with dx10 the
/// 20-byte DDS_HEADER_DXT10, then the texels row after row) of one 2D texture, one mip level:
///   flags = CAPS | HEIGHT | WIDTH | PITCH | PIXELFORMAT (0x100f), pitch = width * texel bytes,
///   depth = 1, mip count = 1, pixel format flags = FOURCC (4), caps = TEXTURE (0x1000);
///   DXT10: dxgiFormat 2 or 10, resource dimension TEXTURE2D (3), array size 1, alpha mode
///   CUSTOM (4: the fourth channel is data, not opacity).
/// Texels in the order of rgba_texture (row y = 0 first), channels r, g, b, a; rgba16_float
/// rounds with float_to_half. The texture's data start at byte 148 (dx10) or 128 (legacy).
inline std::vector<unsigned char> write_dds(const rgba_texture& t, dds_format format,
                                            dds_header header = dds_header::dx10) {
    const bool half = format == dds_format::rgba16_float;
    const std::uint32_t texel_bytes = half ? 8u : 16u;
    const auto w = static_cast<std::uint32_t>(t.width), h = static_cast<std::uint32_t>(t.height);
    std::vector<unsigned char> out;
    out.reserve(148 + static_cast<std::size_t>(w) * h * texel_bytes);
    for (char c : {'D', 'D', 'S', ' '}) out.push_back(static_cast<unsigned char>(c));
    detail::put_u32(out, 124);      // dwSize
    detail::put_u32(out, 0x100fu);  // dwFlags
    detail::put_u32(out, h);
    detail::put_u32(out, w);
    detail::put_u32(out, w * texel_bytes);  // dwPitchOrLinearSize
    detail::put_u32(out, 1);                // dwDepth
    detail::put_u32(out, 1);                // dwMipMapCount
    for (int i = 0; i < 11; ++i) detail::put_u32(out, 0);  // dwReserved1
    detail::put_u32(out, 32);                              // ddspf.dwSize
    detail::put_u32(out, 4);                               // ddspf.dwFlags: DDPF_FOURCC
    detail::put_u32(out, header == dds_header::dx10 ? 0x30315844u /* "DX10" */ : (half ? 113u : 116u));
    for (int i = 0; i < 5; ++i) detail::put_u32(out, 0);  // bit count, masks
    detail::put_u32(out, 0x1000u);                        // dwCaps: DDSCAPS_TEXTURE
    for (int i = 0; i < 4; ++i) detail::put_u32(out, 0);  // dwCaps2..4, dwReserved2
    if (header == dds_header::dx10) {
        detail::put_u32(out, half ? 10u : 2u);  // dxgiFormat
        detail::put_u32(out, 3);                // D3D10_RESOURCE_DIMENSION_TEXTURE2D
        detail::put_u32(out, 0);                // miscFlag
        detail::put_u32(out, 1);                // arraySize
        detail::put_u32(out, 4);                // miscFlags2: DDS_ALPHA_MODE_CUSTOM
    }
    for (float v : t.texels) {
        if (half)
            detail::put_u16(out, float_to_half(v));
        else
            detail::put_f32(out, v);
    }
    return out;
}

/// Raw little-endian float32 texels, nothing else: width * height * 4 * 4 bytes in the order of
/// rgba_texture (what glTexImage2D(..., GL_RGBA32F, w, h, 0, GL_RGBA, GL_FLOAT, p) and
/// DXGI_FORMAT_R32G32B32A32_FLOAT uploads take on a little-endian machine).
inline std::vector<unsigned char> write_raw_float32(const rgba_texture& t) {
    std::vector<unsigned char> out;
    out.reserve(t.texels.size() * 4);
    for (float v : t.texels) detail::put_f32(out, v);
    return out;
}

/// The JSON descriptor of write_raw_float32's file `file`: its size, channels, texel order,
/// parameterization and the paper's shaders' LUT scale and bias per axis ((n - 1) / n, 0.5 / n,
/// which map a node coordinate in [0, 1] to the centre of its texel), as one JSON object.
inline std::string raw_descriptor_json(const rgba_texture& t, const std::string& file) {
    const auto num = [](double v) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.9g", v);
        return std::string(buf);
    };
    const auto str = [](const char* s) {
        std::string r = "\"";
        for (const char* p = s; *p; ++p) {
            if (*p == '"' || *p == '\\') r += '\\';
            r += *p;
        }
        return r + "\"";
    };
    const double w = t.width, h = t.height;
    std::string j = "{\n";
    j += "  \"file\": " + str(file.c_str()) + ",\n";
    j += "  \"format\": \"float32, little-endian, 4 channels, no header\",\n";
    j += "  \"width\": " + std::to_string(t.width) + ",\n";
    j += "  \"height\": " + std::to_string(t.height) + ",\n";
    j += "  \"channels\": 4,\n";
    j += "  \"bytes\": " + std::to_string(t.texels.size() * 4) + ",\n";
    j += "  \"channel_names\": [";
    for (int c = 0; c < 4; ++c) j += (c ? ", " : "") + str(t.channel_names[static_cast<std::size_t>(c)]);
    j += "],\n";
    j += "  \"texel_order\": \"row-major: texel (x, y) at float index (y * width + x) * 4 + channel\",\n";
    j += "  \"x\": \"roughness = x / (width - 1), alpha = roughness^2\",\n";
    j += "  \"y\": \"sqrt(1 - cos theta_v) = y / (height - 1)\",\n";
    j += "  \"uv\": \"(roughness, sqrt(1 - cos theta_v)) * lut_scale + lut_bias\",\n";
    j += "  \"lut_scale\": [" + num(w > 0 ? (w - 1) / w : 0) + ", " + num(h > 0 ? (h - 1) / h : 0) + "],\n";
    j += "  \"lut_bias\": [" + num(w > 0 ? 0.5 / w : 0) + ", " + num(h > 0 ? 0.5 / h : 0) + "]\n";
    j += "}\n";
    return j;
}

namespace detail {

/// A float as a decimal literal that reads back to the same float: 9 significant digits, the
/// closest such decimal, so that a reader that rounds it to double first (JavaScript, then
/// Float32Array) lands on the same float too; with ".0" where it would look like an integer.
inline std::string float_literal(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(v));
    std::string s = buf;
    if (s.find_first_of(".en") == std::string::npos) s += ".0";
    return s;
}

inline std::string texture_comment(const paper_textures& p, const std::string& prefix) {
    const std::string w = std::to_string(p.ltc_1.width), h = std::to_string(p.ltc_1.height);
    std::string s = prefix + "Texel (x, y) at [y * " + w + " + x]; x = roughness node (roughness = x / " +
                    std::to_string(p.ltc_1.width - 1) + "), y = u node (sqrt(1 - cos theta_v) = y / " +
                    std::to_string(p.ltc_1.height - 1) + ").\n";
    s += prefix + "ltc_1 = (m_inv[0][0], m_inv[0][2], m_inv[2][0], m_inv[2][2]), column-major, m_inv[1][1] = 1;\n";
    s += prefix + "ltc_2 = (magnitude, fresnel, 0, 0).\n";
    return s;
}

}  // namespace detail

enum class shading_language { glsl, hlsl };

/// Both textures as constant arrays of a shading language, texel (x, y) at [y * width + x]:
///   GLSL: const vec4 <name>_ltc_1[N] = vec4[N](...);   HLSL: static const float4 <name>_ltc_1[N] = {...};
/// with <NAME>_WIDTH and <NAME>_HEIGHT defined; `note` (if any) becomes one more comment line.
/// The shader interpolates the four nearest texels itself, as a texture unit would.
inline std::string shader_constants(const paper_textures& p, const std::string& name, shading_language language,
                                    const std::string& note = "") {
    const bool glsl = language == shading_language::glsl;
    const char* vec = glsl ? "vec4" : "float4";
    std::string s = "// " + name + ": the paper's LTC textures as constant arrays (written by ltc_export).\n";
    s += detail::texture_comment(p, "// ");
    s += "// Interpolate between the four nearest texels as a texture would.\n";
    if (!note.empty()) s += "// " + note + "\n";
    std::string upper = name;
    for (char& c : upper) c = (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
    s += "#define " + upper + "_WIDTH " + std::to_string(p.ltc_1.width) + "\n";
    s += "#define " + upper + "_HEIGHT " + std::to_string(p.ltc_1.height) + "\n";
    const std::size_t count = p.ltc_1.texels.size() / 4;
    const std::string n = std::to_string(count);
    for (const rgba_texture* t : {&p.ltc_1, &p.ltc_2}) {
        s += std::string(glsl ? "const " : "static const ") + vec + " " + name + (t == &p.ltc_1 ? "_ltc_1" : "_ltc_2") +
             "[" + n + "] = " + (glsl ? std::string(vec) + "[" + n + "](\n" : "{\n");
        for (std::size_t i = 0; i < count; ++i) {
            s += std::string("    ") + vec + "(";
            for (std::size_t c = 0; c < 4; ++c) s += (c ? ", " : "") + detail::float_literal(t->texels[4 * i + c]);
            s += i + 1 < count ? "),\n" : ")\n";
        }
        s += glsl ? ");\n" : "};\n";
    }
    return s;
}

/// An ES module in the shape of three.js's RectAreaLightTexturesLib (the object its
/// RectAreaLightUniformsLib and RectAreaLightNode read): `RectAreaLightTexturesLib.init()` builds
/// and returns `{ LTC_FLOAT_1, LTC_FLOAT_2, LTC_HALF_1, LTC_HALF_2 }`, DataTextures of
/// width x height RGBA texels (FloatType, and HalfFloatType from halves rounded here by
/// float_to_half), linear magnification, nearest minification, clamped. three.js samples them as
/// the paper's shaders do: uv = (roughness, sqrt(1 - N.V)) * LUT_SCALE + LUT_BIAS,
/// mInv = mat3(vec3(t1.x, 0, t1.y), vec3(0, 1, 0), vec3(t1.z, 0, t1.w)), specular colour
/// F0 * t2.x + (F90 - F0) * t2.y. The texels are those of to_paper_textures: the float arrays as
/// decimal literals that read back to the same floats, the half arrays as their bit patterns.
/// Precondition: no value beyond float16's range (half_overflows is 0 for both textures).
inline std::string threejs_module(const paper_textures& p, const std::string& name, const std::string& note = "") {
    std::string s = "// " + name + ": LTC textures in the layout of three.js's RectAreaLightTexturesLib (written by ltc_export).\n";
    s += detail::texture_comment(p, "// ");
    s += "// Use: import this module in place of three/addons/lights/RectAreaLightTexturesLib.js (an alias in\n";
    s += "// the bundler or the import map), or after RectAreaLightUniformsLib.init() assign\n";
    s += "// UniformsLib.LTC_FLOAT_1 = RectAreaLightTexturesLib.init().LTC_FLOAT_1, and so on for the other three.\n";
    if (!note.empty()) s += "// " + note + "\n";
    s += "import { ClampToEdgeWrapping, DataTexture, FloatType, HalfFloatType, LinearFilter, NearestFilter, "
         "RGBAFormat, UVMapping } from 'three';\n\n";
    // One typed array of a texture's texels, four to a line, each value written by `value`.
    const auto array = [&](const char* var, const char* type, const rgba_texture& t, auto value) {
        s += std::string("const ") + var + " = new " + type + "( [\n";
        for (std::size_t i = 0; i < t.texels.size(); i += 4) {
            s += "\t";
            for (std::size_t c = 0; c < 4; ++c) s += value(t.texels[i + c]) + (c < 3 ? ", " : "");
            s += i + 4 < t.texels.size() ? ",\n" : "\n";
        }
        s += "] );\n\n";
    };
    const auto decimal = [](float v) { return detail::float_literal(v); };
    const auto half_bits = [](float v) { return std::to_string(float_to_half(v)); };
    array("LTC_MAT_1", "Float32Array", p.ltc_1, decimal);
    array("LTC_MAT_2", "Float32Array", p.ltc_2, decimal);
    array("LTC_HALF_MAT_1", "Uint16Array", p.ltc_1, half_bits);
    array("LTC_HALF_MAT_2", "Uint16Array", p.ltc_2, half_bits);
    const std::string w = std::to_string(p.ltc_1.width), h = std::to_string(p.ltc_1.height);
    s += "function ltcTexture( data, type ) {\n";
    s += "\tconst texture = new DataTexture( data, " + w + ", " + h +
         ", RGBAFormat, type, UVMapping, ClampToEdgeWrapping, ClampToEdgeWrapping, LinearFilter, NearestFilter, 1 );\n";
    s += "\ttexture.needsUpdate = true;\n";
    s += "\treturn texture;\n";
    s += "}\n\n";
    s += "const RectAreaLightTexturesLib = {\n";
    s += "\tLTC_HALF_1: null,\n\tLTC_HALF_2: null,\n\tLTC_FLOAT_1: null,\n\tLTC_FLOAT_2: null,\n";
    s += "\tinit() {\n";
    s += "\t\tif ( this.LTC_FLOAT_1 === null ) {\n";
    s += "\t\t\tthis.LTC_FLOAT_1 = ltcTexture( LTC_MAT_1, FloatType );\n";
    s += "\t\t\tthis.LTC_FLOAT_2 = ltcTexture( LTC_MAT_2, FloatType );\n";
    s += "\t\t\tthis.LTC_HALF_1 = ltcTexture( LTC_HALF_MAT_1, HalfFloatType );\n";
    s += "\t\t\tthis.LTC_HALF_2 = ltcTexture( LTC_HALF_MAT_2, HalfFloatType );\n";
    s += "\t\t}\n";
    s += "\t\treturn this;\n";
    s += "\t}\n";
    s += "};\n\n";
    s += "export { RectAreaLightTexturesLib };\n";
    return s;
}

/// How the Blender tree at hand declares EEVEE's LTC arrays (eevee_lut.hh or eevee_lut.h); the
/// definitions must match it, and all three hold the same floats in the same order.
enum class eevee_declaration {
    float_arrays,  ///< namespace blender::eevee::lut { const float ltc_mat_ggx[64][64][4]; ltc_mag_ggx[64][64][2] }
    vec_base,      ///< namespace blender::eevee::lut { const VecBase<float, 4> ltc_mat_ggx[64][64]; VecBase<float, 2> ... }
    flat_c         ///< no namespace (C, or C++ under eevee_lut.h's extern "C"): const float ltc_mat_ggx[64 * 64 * 4]; ...
};

/// The definitions of EEVEE's two LTC arrays (Blender's source/blender/draw/engines/eevee*/
/// eevee_lut.cc or .c) holding the textures' texels, for a 64 x 64 table (EEVEE's UTIL_TEX_SIZE):
///   ltc_mat_ggx[y][x] = ltc_1 texel (x, y) = (m_inv[0][0], m_inv[0][2], m_inv[2][0], m_inv[2][2])
///   ltc_mag_ggx[y][x] = (ltc_2 texel (x, y).r, .g) = (magnitude, fresnel)
/// (flat_c: [(y * 64 + x) * 4 + c], the same order), x = roughness node, y = sqrt(1 - cos theta_v)
/// node: EEVEE copies them row by row into layers of its utility texture, samples at
/// uv = (roughness, sqrt(1 - cos theta_v)) * 63 / 64 + 0.5 / 64 and builds
/// M^-1 = mat3(vec3(t.x, 0, t.y), vec3(0, 1, 0), vec3(t.z, 0, t.w)), the paper's layout, and its
/// ltc_mag_ggx is the paper's ltc_2.xy. Each float is written as a literal that reads back to it.
/// The text reopens its namespace, so it can be appended to eevee_lut.cc once the two arrays'
/// old definitions are deleted there.
inline std::string eevee_lut_source(const paper_textures& p, eevee_declaration declaration,
                                    const std::string& note = "") {
    const bool flat = declaration == eevee_declaration::flat_c;
    const std::string w = std::to_string(p.ltc_1.width), h = std::to_string(p.ltc_1.height);
    std::string s = "/* EEVEE's LTC arrays ltc_mat_ggx and ltc_mag_ggx, written by ltc_export from the ltc library's\n";
    s += std::string(" * table, in place of the definitions in ") + (flat ? "eevee_lut.c or eevee_lut.cc" : "eevee_lut.cc") +
         " (delete those, append this).\n";
    s += " * [y][x]: x = roughness node (roughness = x / " + std::to_string(p.ltc_1.width - 1) +
         "), y = sqrt(1 - cos theta_v) node (y / " + std::to_string(p.ltc_1.height - 1) + ").\n";
    s += " * ltc_mat_ggx = (m_inv[0][0], m_inv[0][2], m_inv[2][0], m_inv[2][2]) of M^-1 / M^-1[1][1], column-major;\n";
    s += " * ltc_mag_ggx = (magnitude, fresnel): int rho cos, int rho cos (1 - V.H)^5. */\n";
    if (!note.empty()) s += "/* " + note + " */\n";
    if (!flat) s += "\nnamespace blender::eevee::lut {\n";
    // One array: `per_line` texels a line; nested, each row of texels and each texel in braces.
    const auto array = [&](const char* declarator, const rgba_texture& t, std::size_t channels, int per_line) {
        s += std::string("\n") + declarator + " = {\n";
        for (int y = 0; y < t.height; ++y) {
            if (!flat) s += "    {";
            for (int x = 0; x < t.width; ++x) {
                const bool line_start = x % per_line == 0;
                s += line_start ? (flat ? "    " : x == 0 ? "" : "\n     ") : " ";
                if (!flat) s += "{";
                for (std::size_t c = 0; c < channels; ++c) {
                    s += detail::float_literal(t.texel(x, y, static_cast<int>(c))) + "f";
                    if (c + 1 < channels) s += ", ";
                }
                if (!flat) s += "}";
                const bool last = x + 1 == t.width;
                if (!last || flat) s += ",";
                if (flat && (last || (x + 1) % per_line == 0)) s += "\n";
            }
            if (!flat) s += y + 1 < t.height ? "},\n" : "}\n";
        }
        s += "};\n";
    };
    std::string mat, mag;
    switch (declaration) {
        case eevee_declaration::float_arrays:
            mat = "const float ltc_mat_ggx[" + h + "][" + w + "][4]";
            mag = "const float ltc_mag_ggx[" + h + "][" + w + "][2]";
            break;
        case eevee_declaration::vec_base:
            mat = "const VecBase<float, 4> ltc_mat_ggx[" + h + "][" + w + "]";
            mag = "const VecBase<float, 2> ltc_mag_ggx[" + h + "][" + w + "]";
            break;
        case eevee_declaration::flat_c:
            mat = "const float ltc_mat_ggx[" + h + " * " + w + " * 4]";
            mag = "const float ltc_mag_ggx[" + h + " * " + w + " * 2]";
            break;
    }
    array(mat.c_str(), p.ltc_1, 4, 2);
    array(mag.c_str(), p.ltc_2, 2, 4);
    if (!flat) s += "\n}  // namespace blender::eevee::lut\n";
    return s;
}

LTC_NAMESPACE_END
