// common/cli.hpp -- the examples' command lines: parse_options, the loop every example's parser
// runs (--help and -h, options with a value as "--name value" or "--name=value", the error
// messages), and for the renderers (render, shadows) the image options they share (--width,
// --height, --threads, --out, --seed, --exposure), parse_command_line, and the output directory.
// A parser hands parse_options its flags (options without a value) and its other options:
//
//   const auto flag = [&](const std::string& name) {
//       if (name != "--list") return false;
//       list = true;
//       return true;
//   };
//   const auto option = [&](const std::string& name, const ltc_examples::option_value& v) {
//       if (name != "--spp") return ltc_examples::option_status::unknown;
//       if (!v.integer_in(1, 1e6)) return ltc_examples::option_status::bad;
//       spp = static_cast<int>(v.number);
//       return ltc_examples::option_status::taken;
//   };
//   return ltc_examples::parse_options(argc, argv, print_help, flag, option);  // 0, 1 (--help), 2
//
// The renderers' options derive from image_options (with its image size) and call
// parse_command_line(argc, argv, o, print_help, flag, option) instead, which adds the image options.
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

/// The flag argument of parse_options for a program whose only flag is --quiet (or -q): sets quiet.
inline auto quiet_flag(bool& quiet) {
    return [&quiet](const std::string& name) {
        if (name != "--quiet" && name != "-q") return false;
        quiet = true;
        return true;
    };
}

/// Parses argv: --help or -h calls help(argv[0]) (which prints on stdout) and returns 1;
/// flag(name) takes an option without a value (and says whether it did); any other option is
/// "--name value" or "--name=value", given to option(name, value) (an option_status; where the
/// value is missing, asked with "" to tell an unknown name from a missing value). A missing, bad
/// or unknown option prints its message on stderr and returns 2. Returns 0 on success.
template <typename Help, typename Flag, typename Option>
int parse_options(int argc, char** argv, Help&& help, Flag&& flag, Option&& option) {
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        if (a == "--help" || a == "-h") {
            help(argv[0]);
            return 1;
        }
        if (flag(a)) continue;
        option_value v;
        std::string attached;  // the value of "--name=value"
        const std::size_t eq = a.rfind("--", 0) == 0 ? a.find('=') : std::string::npos;
        const bool has_value = eq != std::string::npos || i + 1 < argc;
        if (eq != std::string::npos) {
            attached = a.substr(eq + 1);
            a.resize(eq);
            if (flag(a)) {
                std::fprintf(stderr, "%s: %s takes no value (see --help)\n", argv[0], a.c_str());
                return 2;
            }
            v.text = attached.c_str();
        } else if (has_value) {
            v.text = argv[++i];
        }
        v.is_number = parse_number(v.text, v.number);
        v.is_integer = v.is_number && v.number == std::floor(v.number);
        const option_status status = option(a, v);
        if (status == option_status::unknown) {
            std::fprintf(stderr, "%s: unknown option: %s (see --help)\n", argv[0], a.c_str());
            return 2;
        }
        if (!has_value) {
            std::fprintf(stderr, "%s: missing value for %s (see --help)\n", argv[0], a.c_str());
            return 2;
        }
        if (status == option_status::bad) {
            std::fprintf(stderr, "%s: bad value for %s: %s (see --help)\n", argv[0], a.c_str(), v.text);
            return 2;
        }
    }
    return 0;
}

/// parse_options with the image options (parse_image_option's) taken first; on success,
/// o.threads resolved (0: the hardware's thread count).
template <typename Help, typename Flag, typename Option>
int parse_command_line(int argc, char** argv, image_options& o, Help&& help, Flag&& flag, Option&& option) {
    const int r = parse_options(argc, argv, help, flag, [&](const std::string& name, const option_value& v) {
        const option_status status = parse_image_option(name, v, o);
        return status == option_status::unknown ? option(name, v) : status;
    });
    if (r == 0 && o.threads == 0) o.threads = std::max(1u, std::thread::hardware_concurrency());
    return r;
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
