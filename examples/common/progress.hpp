// common/progress.hpp -- the progress of a long run on stderr, shared by the examples. On a
// terminal, a bar redrawn in place with '\r' and erased at the end (the terminal then shows what
// the program printed, as in a file); otherwise (a log file, a pipe) plain lines, one per tenth
// of the work done (and one every 30 s for a slow tenth) and a last one, so that logs stay readable:
//
//   ltc_examples::progress p("reference", "pixels");
//   for (...) p.update(done, total);  // from one thread; the last call, done == total, ends it
//
// watch() draws it for workers that count their finished items in an atomic.
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <string>
#include <thread>
#include <utility>

#if defined(_WIN32)
#include <io.h>
#else
#include <unistd.h>
#endif

namespace ltc_examples {

inline bool stderr_is_terminal() {
#if defined(_WIN32)
    return _isatty(_fileno(stderr)) != 0;
#else
    return isatty(fileno(stderr)) != 0;
#endif
}

enum class progress_style { none, bar, lines };

/// A bar on a terminal, lines elsewhere; none with `quiet`.
inline progress_style progress_on_stderr(bool quiet = false) {
    return quiet ? progress_style::none : stderr_is_terminal() ? progress_style::bar : progress_style::lines;
}

class progress {
  public:
    /// label: what runs ("reference"); unit: what is counted ("pixels"), or "" to show no counts.
    explicit progress(std::string label, std::string unit = "", progress_style style = progress_on_stderr())
        : label_(std::move(label)), unit_(std::move(unit)), style_(style), start_(clock::now()) {
        if (style_ != progress_style::none) std::fflush(stdout);  // what the program printed comes first
    }

    /// done of total items, from one thread, as often as one likes (the bar is redrawn at most
    /// every 0.1 s); the call with done >= total ends it, and later calls do nothing.
    void update(std::size_t done, std::size_t total) {
        if (style_ == progress_style::none || finished_) return;
        const double t = seconds();
        finished_ = done >= total;
        const double f = finished_ ? 1.0 : static_cast<double>(done) / static_cast<double>(total);
        const int tenth = static_cast<int>(10 * f);
        if (style_ == progress_style::bar) {
            if (finished_) {
                if (width_ > 0) std::fprintf(stderr, "\r%*s\r", width_, "");
            } else if (width_ == 0 || t - last_ >= 0.1) {
                draw_bar(done, total, f, t);
            }
        } else if (finished_) {
            std::fprintf(stderr, "%s: done%s%s in %.1f s\n", label_.c_str(), unit_.empty() ? "" : ", ",
                         count(done, total).c_str(), t);
        } else if ((tenth > last_tenth_ && t - last_ >= 1) || t - last_ >= 30) {  // not more than a line a second
            std::fprintf(stderr, "%s: %3d%%%s%s%s, %.1f s, %s\n", label_.c_str(), static_cast<int>(100 * f),
                         unit_.empty() ? "" : " (", count(done, total).c_str(), unit_.empty() ? "" : ")", t,
                         time_left(f, t).c_str());
            last_ = t, last_tenth_ = tenth;
        }
        std::fflush(stderr);
    }

    double seconds() const { return std::chrono::duration<double>(clock::now() - start_).count(); }

  private:
    using clock = std::chrono::steady_clock;

    std::string count(std::size_t done, std::size_t total) const {
        return unit_.empty() ? "" : std::to_string(done) + "/" + std::to_string(total) + " " + unit_;
    }

    static std::string time_left(double f, double t) {
        if (f <= 0) return "time left unknown";
        char s[40];
        std::snprintf(s, sizeof s, "about %.0f s left", t * (1 / f - 1));
        return s;
    }

    void draw_bar(std::size_t done, std::size_t total, double f, double t) {
        constexpr int width = 30;
        const int filled = static_cast<int>(f * width);
        // Trailing spaces cover what a longer previous line left on the terminal.
        const int n = std::fprintf(stderr, "\r%s [%.*s%.*s] %3d%%%s%s  %.1f s, %-20s", label_.c_str(), filled,
                                   "##############################", width - filled, "..............................",
                                   static_cast<int>(100 * f), unit_.empty() ? "" : "  ", count(done, total).c_str(),
                                   t, time_left(f, t).c_str());
        width_ = std::max(width_, n - 1);  // what the erasing covers
        last_ = t;
    }

    std::string label_, unit_;
    progress_style style_;
    clock::time_point start_;
    double last_ = 0;     // when the bar or the last line was drawn
    int last_tenth_ = 0;  // the tenth of the last line
    int width_ = 0;       // the widest bar drawn (0: none yet)
    bool finished_ = false;
};

/// Updates p from the calling thread until `done` (counted by workers) reaches total, then ends it.
inline void watch(progress& p, const std::atomic<std::size_t>& done, std::size_t total) {
    for (std::size_t d; (d = done.load()) < total;) {
        p.update(d, total);
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    p.update(total, total);
}

}  // namespace ltc_examples
