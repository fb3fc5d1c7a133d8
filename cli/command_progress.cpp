#include "cli/command_progress.h"

#include <algorithm>
#include <cmath>

#include "data/platform.h"

namespace ensil::cli {
namespace {
// A person reads a figure that changes once a second; a quicker run needs none.
constexpr auto kInterval = std::chrono::seconds(1);
}  // namespace

CommandProgress::CommandProgress(QTextStream& err, QString command, bool shown, Clock clock)
    : m_err(err), m_command(std::move(command)), m_shown(shown), m_clock(std::move(clock)) {
    m_start = m_clock();
    m_lastWritten = m_start;
}

CommandProgress::~CommandProgress() { endLine(); }

QCommandLineOption CommandProgress::quietOption() {
    return {QStringLiteral("quiet"),
            QStringLiteral("Print no progress. Progress is printed on stderr only when it is a "
                           "terminal and the run lasts over a second.")};
}

bool CommandProgress::shownOnThisTerminal(bool quiet) {
    return !quiet && data::standardErrorIsTerminal();
}

void CommandProgress::report(const QString& stage, double fraction) {
    if (!m_shown || !std::isfinite(fraction)) return;
    const int percent = static_cast<int>(std::floor(std::clamp(fraction, 0.0, 1.0) * 100.0));
    const std::scoped_lock lock(m_mutex);
    const auto now = m_clock();
    const bool sameStage = stage == m_lastStage;
    if ((sameStage && percent == m_lastPercent) || now - m_start < kInterval ||
        (sameStage && m_lineOpen && now - m_lastWritten < kInterval && percent < 100)) {
        return;
    }
    // Padded so that a shorter text covers a longer one written before it.
    const QString text = QStringLiteral("%1: %2, %3 %").arg(m_command, stage).arg(percent);
    m_err << "\r" << text.leftJustified(m_lineWidth) << Qt::flush;
    m_lineWidth = std::max(m_lineWidth, static_cast<int>(text.size()));
    m_lastWritten = now;
    m_lastStage = stage;
    m_lastPercent = percent;
    m_lineOpen = true;
}

data::Progress CommandProgress::callback(const QString& stage) {
    if (!m_shown) return {};
    return [this, stage](double fraction) { report(stage, fraction); };
}

void CommandProgress::endLine() {
    const std::scoped_lock lock(m_mutex);
    if (!m_lineOpen) return;
    m_err << "\n" << Qt::flush;
    m_lineOpen = false;
    m_lineWidth = 0;
}

}  // namespace ensil::cli
