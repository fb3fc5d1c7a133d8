// Progress of a long command-line run, on stderr: "ensil preprocess: 42 %", rewritten in place
// on a terminal. Shown only where a person watches (stderr is a terminal, and --quiet was not
// given), only once the run has lasted a second, and at most once a second after that, so a
// quick run prints nothing and a log or a pipe never fills with carriage returns. Thread-safe:
// workers report through callback().
#pragma once

#include <QCommandLineOption>
#include <QString>
#include <QTextStream>
#include <chrono>
#include <functional>
#include <mutex>

#include "data/job.h"

namespace ensil::cli {

class CommandProgress {
public:
    using Clock = std::function<std::chrono::steady_clock::time_point()>;

    // `shown`: whether to write at all (see shownOnThisTerminal). `clock` is for tests.
    CommandProgress(QTextStream& err, QString command, bool shown,
                    Clock clock = &std::chrono::steady_clock::now);
    ~CommandProgress();  // ends the line, if one was written
    CommandProgress(const CommandProgress&) = delete;
    CommandProgress& operator=(const CommandProgress&) = delete;

    // Whether progress is shown for a run: stderr is a terminal and `quiet` is false.
    [[nodiscard]] static bool shownOnThisTerminal(bool quiet);
    // --quiet, the option every command that shows progress takes.
    [[nodiscard]] static QCommandLineOption quietOption();

    // `stage` names what runs ("reading", "preprocessing"); each stage runs from 0 to 1.
    void report(const QString& stage, double fraction);
    [[nodiscard]] data::Progress callback(const QString& stage);
    // Ends the progress line so that a message printed next starts on a line of its own.
    void endLine();

private:
    QTextStream& m_err;
    QString m_command;
    bool m_shown;
    Clock m_clock;
    std::mutex m_mutex;
    std::chrono::steady_clock::time_point m_start;
    std::chrono::steady_clock::time_point m_lastWritten;
    QString m_lastStage;
    int m_lastPercent = -1;
    bool m_lineOpen = false;
    int m_lineWidth = 0;
};

}  // namespace ensil::cli
