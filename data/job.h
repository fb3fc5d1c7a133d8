// The contract every long-running step follows, in every layer that links no Qt: it takes a
// std::stop_token and a progress callback, checks the token often enough to notice a cancel
// within ~100 ms, and then throws Cancelled so nothing half-done escapes. Progress is a fraction
// in [0, 1], reported monotonically from the worker thread running the step (the callback must
// be thread-safe).
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <stop_token>
#include <vector>

namespace ensil::data {

using Progress = std::function<void(double fraction)>;

class Cancelled : public std::runtime_error {
public:
    Cancelled() : std::runtime_error("cancelled") {}
};

inline void throwIfStopped(const std::stop_token& stop) {
    if (stop.stop_requested()) throw Cancelled();
}

inline void report(const Progress& progress, double fraction) {
    if (progress) progress(fraction);
}

// Progress of work done in parts on several threads at once: each part that finishes moves the
// fraction from `from` toward `to` by its share. Counted and reported under one lock, so the
// fractions stay monotonic whatever order the threads finish in.
class PartsProgress {
public:
    PartsProgress(Progress progress, std::size_t parts, double from = 0.0, double to = 1.0)
        : m_progress(std::move(progress)), m_parts(parts), m_from(from), m_to(to) {}
    void partDone() {
        const std::lock_guard lock(m_mutex);
        ++m_done;
        report(m_progress, m_from + (m_to - m_from) * static_cast<double>(m_done) /
                                        static_cast<double>(m_parts == 0 ? 1 : m_parts));
    }

private:
    Progress m_progress;
    std::size_t m_parts;
    double m_from, m_to;
    std::size_t m_done = 0;
    std::mutex m_mutex;
};

// Progress of parts that run at the same time, each reporting its own fraction: the whole is
// their sum weighted by each part's share of the work, reported under one lock and never
// backwards (a part may report while another's larger sum is being reported).
class WeightedPartsProgress {
public:
    WeightedPartsProgress(Progress progress, std::vector<double> weights)
        : m_progress(std::move(progress)),
          m_weights(std::move(weights)),
          m_fractions(m_weights.size(), 0.0) {
        for (const double w : m_weights) m_total += w;
    }
    // The Progress of part i (0 .. 1); valid while this object lives.
    Progress part(std::size_t i) {
        return [this, i](double fraction) { partAt(i, fraction); };
    }

private:
    void partAt(std::size_t i, double fraction) {
        const std::lock_guard lock(m_mutex);
        m_fractions[i] = std::max(m_fractions[i], fraction);
        double sum = 0.0;
        for (std::size_t k = 0; k < m_weights.size(); ++k) sum += m_weights[k] * m_fractions[k];
        const double whole = m_total > 0.0 ? sum / m_total : 1.0;
        if (whole <= m_reported) return;
        m_reported = whole;
        report(m_progress, whole);
    }

    Progress m_progress;
    std::vector<double> m_weights, m_fractions;
    double m_total = 0.0, m_reported = -1.0;
    std::mutex m_mutex;
};

}  // namespace ensil::data
