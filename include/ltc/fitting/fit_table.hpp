// ltc/fitting/fit_table.hpp -- fitting a whole N x N table of LTCs (fit_table, on std::threads),
// its parts (fit_normal_incidence, fit_row) and the result (table; packed() gives the layout of
// ltc/tables/ltc_table.hpp). The shipped 64 x 64 GGX table (ltc/tables/ggx.hpp) is
// fit_table<ltc::brdf::ggx>(options{}), written out by ltc/fitting/table_writer.hpp.
//
// Order. As in the paper's code, the normal-incidence nodes (t = 0; the coordinates of node
// (t, a) are in ltc/fitting/options.hpp) are fitted first, from roughness 1 (started at the
// cosine, M = I) down to roughness 0, each started from the previous one; then each row of
// constant roughness is fitted from its normal-incidence node towards grazing angles, each node
// started from its neighbour. Rows are independent work items handed to std::threads, so the
// result does not depend on the number of threads. The stored inverse matrix is divided by its
// middle element m_inv[1][1] (= 1 / m22 > 0, so the distribution is unchanged).
#pragma once

#include <ltc/config.hpp>

#include <ltc/fitting/fit_node.hpp>
#include <ltc/fitting/options.hpp>
#include <ltc/tables/ltc_table.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

LTC_NAMESPACE_BEGIN
namespace fit {

/// Called on the thread that runs fit_table() (or fit_two_lobe_table(), ltc/fitting/fit_two_lobes.hpp),
/// about every options::progress_interval seconds and once at the end: `done` of `total` nodes
/// are fitted.
using progress_callback = std::function<void(std::size_t done, std::size_t total)>;

struct table {
    int size = 0;
    std::vector<node_result> nodes;  ///< nodes[a * size + t]: a along roughness, t along x

    const node_result& at(int t, int a) const { return nodes[std::size_t(a) * std::size_t(size) + std::size_t(t)]; }
    node_result& at(int t, int a) { return nodes[std::size_t(a) * std::size_t(size) + std::size_t(t)]; }

    /// The size * size * 6 floats of ltc/tables/ltc_table.hpp.
    std::vector<float> packed() const {
        std::vector<float> d;
        d.reserve(nodes.size() * channel::count);
        for (const node_result& n : nodes) {
            d.push_back(float(n.m_inv[0][0]));
            d.push_back(float(n.m_inv[0][2]));
            d.push_back(float(n.m_inv[2][0]));
            d.push_back(float(n.m_inv[2][2]));
            d.push_back(float(n.magnitude));
            d.push_back(float(n.fresnel));
        }
        return d;
    }
};

/// The normal-incidence nodes (t = 0) of every row, fitted in sequence from roughness 1 (started
/// at the cosine) down to roughness 0, each started from the previous one. result[a] is row a's.
template <template <typename> class Brdf>
std::vector<node_result> fit_normal_incidence(const options& opt) {
    const int n = opt.size;
    std::vector<node_result> r(std::size_t(std::max(n, 0)));
    ltc_parameters start;
    for (int a = n - 1; a >= 0; --a) {
        r[std::size_t(a)] = fit_node<Brdf>(node_cos_theta(0, n, opt.cos_theta_min), node_alpha(a, n, opt.alpha_min),
                                           start, opt);
        start = r[std::size_t(a)].parameters;
    }
    return r;
}

/// Row a (constant roughness), t = 1 .. size - 1, each node started from its neighbour t - 1;
/// `normal_incidence` is the row's node t = 0. on_node(t) is called after each node.
template <template <typename> class Brdf, typename OnNode>
void fit_row(int a, const node_result& normal_incidence, const options& opt, node_result* row, OnNode&& on_node) {
    const int n = opt.size;
    row[0] = normal_incidence;
    const double alpha = node_alpha(a, n, opt.alpha_min);
    for (int t = 1; t < n; ++t) {
        row[t] = fit_node<Brdf>(node_cos_theta(t, n, opt.cos_theta_min), alpha, row[t - 1].parameters, opt);
        on_node(t);
    }
}

template <template <typename> class Brdf>
std::vector<node_result> fit_row(int a, const node_result& normal_incidence, const options& opt) {
    std::vector<node_result> row(std::size_t(std::max(opt.size, 1)));
    fit_row<Brdf>(a, normal_incidence, opt, row.data(), [](int) {});
    return row;
}

namespace detail {

/// The fitters' threads: runs body(i) on each of min(options::threads or the hardware's, max_threads)
/// threads while the calling thread calls progress(done, total) about every
/// options::progress_interval seconds, and once more after joining them. The first exception
/// stops the fit: body catches its own and passes them to fail() (which records the current
/// exception and tells the other threads to stop), as do a thread that cannot be started and a
/// throwing progress callback; failed() says whether one was recorded (then progress is no longer
/// called). The caller rethrows the recorded exception.
template <typename Body, typename Fail, typename Failed>
void run_fit_threads(const options& opt, int max_threads, const Body& body, const progress_callback& progress,
                     const std::atomic<std::size_t>& done, std::size_t total, const Fail& fail, const Failed& failed) {
    unsigned threads = opt.threads ? opt.threads : std::max(1u, std::thread::hardware_concurrency());
    threads = std::min<unsigned>(threads, unsigned(std::max(max_threads, 1)));
    std::mutex mutex;
    std::condition_variable finished;
    int running = 0;  // threads started and not yet returned
    const auto report = [&] {
        if (!progress || failed()) return;
        try {
            progress(done.load(), total);
        } catch (...) {
            fail();
        }
    };
    const auto thread_body = [&](unsigned i) {
        body(i);
        std::lock_guard<std::mutex> lock(mutex);
        --running;
        finished.notify_all();
    };
    std::vector<std::thread> pool;
    pool.reserve(threads);
    for (unsigned i = 0; i < threads; ++i) {
        {
            std::lock_guard<std::mutex> lock(mutex);
            ++running;
        }
        try {
            pool.emplace_back(thread_body, i);
        } catch (...) {  // not started: stop the others, which are waited for below
            {
                std::lock_guard<std::mutex> lock(mutex);
                --running;
            }
            fail();
            break;
        }
    }
    {
        std::unique_lock<std::mutex> lock(mutex);
        const auto interval = std::chrono::duration<double>(std::max(opt.progress_interval, 0.001));
        while (running > 0) {
            finished.wait_for(lock, interval);
            if (running == 0) break;
            lock.unlock();
            report();
            lock.lock();
        }
    }
    for (std::thread& t : pool) t.join();
    report();
}

}  // namespace detail

/// Fits the whole size x size table on options::threads threads (see the file comment).
template <template <typename> class Brdf>
table fit_table(const options& opt, const progress_callback& progress = {}) {
    if (opt.size < 2) throw std::invalid_argument("ltc::fit::fit_table: size must be at least 2");
    const int n = opt.size;
    table tab;
    tab.size = n;
    tab.nodes.resize(std::size_t(n) * std::size_t(n));
    const std::size_t total = tab.nodes.size();

    std::atomic<std::size_t> done{0};
    std::atomic<int> next_row{0};
    std::mutex mutex;
    std::exception_ptr failure;
    // The first exception stops the rows after the current ones (detail::run_fit_threads).
    const auto fail = [&] {
        std::lock_guard<std::mutex> lock(mutex);
        if (!failure) failure = std::current_exception();
        next_row.store(n);
    };
    const auto failed = [&] {
        std::lock_guard<std::mutex> lock(mutex);
        return failure != nullptr;
    };

    // Phase 1, sequential: the normal-incidence chain (one-parameter fits, cheap).
    const std::vector<node_result> normal = fit_normal_incidence<Brdf>(opt);
    done += std::size_t(n);
    if (progress) progress(done.load(), total);

    // Phase 2: rows in parallel, each a deterministic function of its normal-incidence node.
    const auto worker = [&](unsigned) {
        try {
            for (;;) {
                const int a = next_row.fetch_add(1);
                if (a >= n) break;
                node_result* row = &tab.nodes[std::size_t(a) * std::size_t(n)];
                fit_row<Brdf>(a, normal[std::size_t(a)], opt, row, [&](int) { done.fetch_add(1); });
            }
        } catch (...) {
            fail();
        }
    };
    detail::run_fit_threads(opt, n, worker, progress, done, total, fail, failed);
    if (failure) std::rethrow_exception(failure);
    return tab;
}

}  // namespace fit
LTC_NAMESPACE_END
