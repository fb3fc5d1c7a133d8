// Holds every thread of the jobs' pool (workbench::jobThreadPool()), as a full build beside a time
// step's motion meshes or the reading ahead can hold them (one a core), until release() or the
// end of the scope: a test then sees what runs without them (a preview, on its own thread) and
// decides when the jobs queued meanwhile may run.
#pragma once

#include <QSemaphore>
#include <QThreadPool>
#include <memory>

#include "workbench/background_job.h"

namespace ensil::test {

class HeldJobThreads {
public:
    // Waits until every thread runs a holder, up to timeoutMs (a job already running keeps its
    // thread until it ends); held() says whether they all came.
    explicit HeldJobThreads(int timeoutMs = 30000)
        : m_threads(workbench::jobThreadPool()->maxThreadCount()) {
        for (int t = 0; t < m_threads; ++t) {
            // The semaphores are shared with the holders, which may still be leaving acquire()
            // when this object is gone.
            workbench::jobThreadPool()->start([holding = m_holding, released = m_released] {
                holding->release();
                released->acquire();
            });
        }
        m_held = m_holding->tryAcquire(m_threads, timeoutMs);
    }
    HeldJobThreads(const HeldJobThreads&) = delete;
    HeldJobThreads& operator=(const HeldJobThreads&) = delete;
    // A thread still held would hang the process's exit.
    ~HeldJobThreads() { release(); }

    [[nodiscard]] bool held() const { return m_held; }
    void release() {
        if (!m_releasedAlready) m_released->release(m_threads);
        m_releasedAlready = true;
    }

private:
    int m_threads;
    std::shared_ptr<QSemaphore> m_holding = std::make_shared<QSemaphore>();
    std::shared_ptr<QSemaphore> m_released = std::make_shared<QSemaphore>();
    bool m_held = false;
    bool m_releasedAlready = false;
};

}  // namespace ensil::test
