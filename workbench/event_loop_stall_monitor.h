// Measures how long the event loop of the thread it lives on (the GUI thread) is kept from
// running: a precise timer fires every few milliseconds and notes how late each timeout comes.
// Lateness = time since the previous timeout minus the interval; a handler that blocks the loop
// for 80 ms shows up as one sample of about 80 ms. Used by the GUI stall benchmark, and cheap
// enough to leave running in a session. Lives on, and is called from, one thread.
#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>
#include <cstddef>
#include <vector>

namespace ensil::workbench {

struct StallSummary {
    std::size_t samples = 0;
    double longestMs = 0.0;
    double percentile99Ms = 0.0;
    double medianMs = 0.0;
};

class EventLoopStallMonitor : public QObject {
    Q_OBJECT
public:
    explicit EventLoopStallMonitor(int intervalMs = 5, QObject* parent = nullptr);

    void start();  // forgets earlier samples
    void stop();
    [[nodiscard]] bool isRunning() const { return m_timer.isActive(); }
    [[nodiscard]] int intervalMs() const { return m_intervalMs; }
    // Lateness of every timeout since start(), in ms, in order.
    [[nodiscard]] const std::vector<double>& latenessMs() const { return m_lateness; }
    [[nodiscard]] StallSummary summary() const;

private:
    void tick();

    int m_intervalMs;
    QTimer m_timer;
    QElapsedTimer m_clock;
    qint64 m_lastNs = 0;
    std::vector<double> m_lateness;
};

// The p-th percentile (0..100) of the samples, by the nearest-rank method; 0 for no samples.
double percentile(std::vector<double> samples, double p);

}  // namespace ensil::workbench
