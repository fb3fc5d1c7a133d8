#include "workbench/event_loop_stall_monitor.h"

#include <algorithm>
#include <cmath>

namespace ensil::workbench {

EventLoopStallMonitor::EventLoopStallMonitor(int intervalMs, QObject* parent)
    : QObject(parent), m_intervalMs(intervalMs) {
    // A coarse timer may legally fire up to 5 % late; that would read as a stall.
    m_timer.setTimerType(Qt::PreciseTimer);
    m_timer.setInterval(m_intervalMs);
    connect(&m_timer, &QTimer::timeout, this, &EventLoopStallMonitor::tick);
}

void EventLoopStallMonitor::start() {
    m_lateness.clear();
    m_clock.start();
    m_lastNs = 0;
    m_timer.start();
}

void EventLoopStallMonitor::stop() { m_timer.stop(); }

void EventLoopStallMonitor::tick() {
    const qint64 now = m_clock.nsecsElapsed();
    const double gapMs = static_cast<double>(now - m_lastNs) * 1e-6;
    m_lastNs = now;
    m_lateness.push_back(std::max(0.0, gapMs - m_intervalMs));
}

StallSummary EventLoopStallMonitor::summary() const {
    StallSummary s;
    s.samples = m_lateness.size();
    if (m_lateness.empty()) return s;
    s.longestMs = *std::max_element(m_lateness.begin(), m_lateness.end());
    s.percentile99Ms = percentile(m_lateness, 99.0);
    s.medianMs = percentile(m_lateness, 50.0);
    return s;
}

double percentile(std::vector<double> samples, double p) {
    if (samples.empty()) return 0.0;
    const auto n = static_cast<double>(samples.size());
    const auto rank = static_cast<std::size_t>(std::clamp(std::ceil(p / 100.0 * n), 1.0, n));
    std::nth_element(samples.begin(), samples.begin() + static_cast<std::ptrdiff_t>(rank - 1),
                     samples.end());
    return samples[rank - 1];
}

}  // namespace ensil::workbench
