// Runs one job at a time on ensil's job threads (or a pool of its owner's) and hands its result
// back on the GUI thread. A job is a function (stop token, progress) -> T that captures its
// inputs by value. Starting a new job cancels the running one and drops its result (the user
// changed the isovalue meanwhile); cancel() asks the running job to stop. Jobs run at a lower
// priority than the GUI thread (workbench/worker_priority.h). Callbacks run on the GUI thread,
// through QFutureWatcher's queued signals; a failure hands on the job's own exception. GUI thread
// only; wait() before destroying what callbacks use.
#pragma once

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFutureWatcher>
#include <QPointer>
#include <QPromise>
#include <QThreadPool>
#include <QUnhandledException>
#include <QtConcurrent/QtConcurrentRun>
#include <exception>
#include <functional>
#include <memory>
#include <stop_token>

#include "data/job.h"
#include "workbench/worker_priority.h"

namespace ensil::workbench {

// The threads background jobs run on: ensil's own pool, a thread a core. Not Qt's global pool:
// Qt's raster painting hands parts of a paint to that one and waits for them, so with its
// threads all held by jobs a widget's repaint waited for a job to end (a test that held every
// one of them hung in QHeaderView::paintEvent).
// The pool is the application object's child, so its threads end before main() returns, as
// Qt's global pool's do: a thread still alive when the libraries' exit handlers run keeps
// state they free for live threads only (OpenSSL's per-thread error state, allocated when
// netCDF opens a file on a job thread, was then reported lost by LeakSanitizer). GUI thread.
inline QThreadPool* jobThreadPool() {
    static QPointer<QThreadPool> pool;
    if (pool.isNull()) pool = new QThreadPool(QCoreApplication::instance());
    return pool.data();
}

// The job's own exception: QtConcurrent wraps one it does not know (any but a QException) in
// QUnhandledException, whose what() says only "std::exception".
inline std::exception_ptr unwrapJobError(const std::exception_ptr& error) {
    try {
        std::rethrow_exception(error);
    } catch (const QUnhandledException& e) {
        return e.exception() ? unwrapJobError(e.exception()) : error;
    } catch (...) {
        return error;
    }
}

template <typename T>
class BackgroundJob {
public:
    using Work = std::function<T(const std::stop_token&, const data::Progress&)>;
    using Done = std::function<void(T)>;
    using Failed = std::function<void(std::exception_ptr error, bool cancelled)>;
    using Progressed = std::function<void(double)>;
    static constexpr int kSteps = 1000;
    // A progress bar step repaints the whole window, tens of ms with a software OpenGL; Qt
    // reports up to 25 steps a second, which kept the GUI thread busy most of the time.
    static constexpr int kProgressIntervalMs = 200;

    // What destroying a running job does. Wait: blocks until it returns (its work may use what
    // the owner destroys next). Abandon: it runs on unheard and its outcome is dropped; only for
    // work that captures nothing but values (a probe of files for a dialog being closed).
    enum class WhenDestroyed { Wait, Abandon };

    // `pool`, when given, runs the jobs instead of jobThreadPool() (which has as many threads as
    // cores, so a job started while every one is busy waits for one); it must outlive this.
    explicit BackgroundJob(QObject* context, WhenDestroyed whenDestroyed = WhenDestroyed::Wait,
                           QThreadPool* pool = nullptr)
        : m_whenDestroyed(whenDestroyed), m_pool(pool != nullptr ? pool : jobThreadPool()) {
        QObject::connect(&m_watcher, &QFutureWatcher<T>::progressValueChanged, context,
                         [this](int value) {
                             if (!m_progressed || !progressDue()) return;
                             m_progressed(static_cast<double>(value) / kSteps);
                         });
        QObject::connect(&m_watcher, &QFutureWatcher<T>::finished, context, [this] { finish(); });
    }
    BackgroundJob(const BackgroundJob&) = delete;
    BackgroundJob& operator=(const BackgroundJob&) = delete;
    ~BackgroundJob() {
        cancel();
        if (m_whenDestroyed == WhenDestroyed::Wait) wait();
    }

    void start(Work work, Done done, Failed failed, Progressed progressed = {}) {
        cancel();
        m_done = std::move(done);
        m_failed = std::move(failed);
        m_progressed = std::move(progressed);
        auto stop = std::make_shared<std::stop_source>();
        m_stop = stop;
        m_watcher.setFuture(
            QtConcurrent::run(m_pool, [work = std::move(work), stop](QPromise<T>& promise) {
                lowerThisThreadPriority();  // the GUI thread must not wait for a core
                promise.setProgressRange(0, kSteps);
                promise.addResult(work(stop->get_token(), [&promise](double f) {
                    promise.setProgressValue(static_cast<int>(f * kSteps));
                }));
            }));
    }

    void cancel() {
        if (m_stop) m_stop->request_stop();
    }
    [[nodiscard]] bool isRunning() const { return m_watcher.isRunning(); }
    // Blocks until the job has returned; its outcome is still delivered by the event loop.
    void wait() {
        try {
            m_watcher.waitForFinished();
        } catch (...) {  // the outcome is reported by finish()
        }
    }

private:
    // True at most once every kProgressIntervalMs.
    bool progressDue() {
        if (m_progressClock.isValid() && m_progressClock.elapsed() < kProgressIntervalMs) {
            return false;
        }
        m_progressClock.start();
        return true;
    }

    void finish() {
        QFuture<T> future = m_watcher.future();
        const bool cancelled = m_stop && m_stop->stop_requested();
        try {
            future.waitForFinished();  // rethrows the job's exception
            if (future.resultCount() == 1 && !cancelled) {
                if (m_done) m_done(future.result());
                return;
            }
            if (m_failed) m_failed(nullptr, true);
        } catch (...) {
            if (m_failed) m_failed(unwrapJobError(std::current_exception()), cancelled);
        }
    }

    WhenDestroyed m_whenDestroyed;
    QThreadPool* m_pool;
    QFutureWatcher<T> m_watcher;
    std::shared_ptr<std::stop_source> m_stop;
    Done m_done;
    Failed m_failed;
    Progressed m_progressed;
    QElapsedTimer m_progressClock;
};

}  // namespace ensil::workbench
