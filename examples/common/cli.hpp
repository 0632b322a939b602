// common/cli.hpp -- what the renderers' command lines (render, shadows) share: the image options
// (--width, --height, --threads, --out, --seed, --exposure), the parsing loop with its messages,
// and the output directory. An example's options derive from image_options (with its image size)
// and its parser hands parse_command_line its own options:
//
//   struct options : ltc_examples::image_options { options() : image_options(320, 200) {} int spp = 4; };
//   const auto option = [&](const std::string& name, const ltc_examples::option_value& v) {
//       if (name != "--spp") return ltc_examples::option_status::unknown;
//       if (!v.integer_in(1, 1e6)) return ltc_examples::option_status::bad;
//       o.spp = static_cast<int>(v.number);
//       return ltc_examples::option_status::taken;
//   };
//   return ltc_examples::parse_command_line(argc, argv, o, print_help, no_flags, option);  // 0, 1, 2
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>
#include <thread>

namespace ltc_examples {

/// A whole, finite number: false for anything else (trailing characters included).
inline bool parse_number(const char* s, double& v) {
    char* end = nullptr;
    v = std::strtod(s, &end);
    return end != s && *end == '\0' && std::isfinite(v);
}

/// The options every renderer takes; each example's options derive from these, with its image size.
struct image_options {
    image_options(int default_width, int default_height) : width(default_width), height(default_height) {}
    int width, height;
    unsigned threads = 0;  // --threads; 0 (left out): all hardware threads, resolved by the parser
    std::string out = ".";
    std::uint64_t seed = 1;
    double exposure = 1.0;
};

/// The value that follows an option's name, as text and, where it reads as one, as a number.
struct option_value {
    const char* text = "";
    double number = 0;
    bool is_number = false, is_integer = false;

    bool integer_in(double lo, double hi) const { return is_integer && number >= lo && number <= hi; }
};

enum class option_status { taken, bad, unknown };

/// --width, --height (1 .. 16384), --threads (1 .. 1024), --seed (0 .. 9e15), --exposure (> 0), --out.
inline option_status parse_image_option(const std::string& name, const option_value& v, image_options& o) {
    if (name == "--width" || name == "--height") {
        if (!v.integer_in(1, 16384)) return option_status::bad;
        (name == "--width" ? o.width : o.height) = static_cast<int>(v.number);
    } else if (name == "--threads") {
        if (!v.integer_in(1, 1024)) return option_status::bad;
        o.threads = static_cast<unsigned>(v.number);
    } else if (name == "--seed") {
        if (!v.integer_in(0, 9e15)) return option_status::bad;
        o.seed = static_cast<std::uint64_t>(v.number);
    } else if (name == "--exposure") {
        if (!v.is_number || !(v.number > 0)) return option_status::bad;
        o.exposure = v.number;
    } else if (name == "--out") {
        o.out = v.text;
    } else {
        return option_status::unknown;
    }
    return option_status::taken;
}

/// Parses argv into o: --help or -h calls help(argv[0]) and returns 1; flag(name) takes an
/// option without a value (and says whether it did); any other option is "--name value", one of
/// parse_image_option's, else given to option(name, value) (an option_status). A missing, bad or
/// unknown option prints its message on stderr and returns 2. Returns 0 on success, with
/// o.threads resolved (0: the hardware's thread count).
template <typename Help, typename Flag, typename Option>
int parse_command_line(int argc, char** argv, image_options& o, Help&& help, Flag&& flag, Option&& option) {
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--help" || a == "-h") {
            help(argv[0]);
            return 1;
        }
        if (flag(a)) continue;
        if (i + 1 >= argc) {
            std::fprintf(stderr, "%s: unknown option or missing value: %s (see --help)\n", argv[0], a.c_str());
            return 2;
        }
        option_value v;
        v.text = argv[++i];
        v.is_number = parse_number(v.text, v.number);
        v.is_integer = v.is_number && v.number == std::floor(v.number);
        option_status status = parse_image_option(a, v, o);
        if (status == option_status::unknown) status = option(a, v);
        if (status == option_status::bad) {
            std::fprintf(stderr, "%s: bad value for %s: %s\n", argv[0], a.c_str(), v.text);
            return 2;
        }
        if (status == option_status::unknown) {
            std::fprintf(stderr, "%s: unknown option: %s (see --help)\n", argv[0], a.c_str());
            return 2;
        }
    }
    if (o.threads == 0) o.threads = std::max(1u, std::thread::hardware_concurrency());
    return 0;
}

/// Creates the output directory (and its parents) if needed; false, with a message, if it is not
/// a directory afterwards.
inline bool create_output_directory(const std::filesystem::path& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (std::filesystem::is_directory(dir, ec)) return true;
    std::fprintf(stderr, "error: cannot create the output directory %s\n", dir.string().c_str());
    return false;
}

}  // namespace ltc_examples
