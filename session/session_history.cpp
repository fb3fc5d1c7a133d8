#include "session/session_history.h"

#include <QUndoCommand>

#include "session/session_model.h"
#include "session/setting_table.h"

namespace ensil::session {
namespace {
QString qs(std::string_view text) {
    return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

bool isCameraSetting(const Setting& s) { return s.projectKey.starts_with("camera."); }

// Merge keys: a setting's index in the table, or one of these past its end.
constexpr int kPlaneKey = 1000;
constexpr int kTimeKey = 1001;  // steps in a row (playing) are one step back

}  // namespace

std::optional<SessionChange> describeChange(const SessionState& before, const SessionState& after,
                                            bool cameraCounts) {
    if (before.data.timeIndex != after.data.timeIndex && before.data.paths == after.data.paths) {
        return SessionChange{QStringLiteral("Time Step %1 -> %2")
                                 .arg(before.data.timeIndex + 1)
                                 .arg(after.data.timeIndex + 1),
                             kTimeKey};
    }
    if (before.isovalue != after.isovalue && after.isovalue) {
        return SessionChange{
            before.isovalue ? QStringLiteral("Isovalue %1 -> %2")
                                  .arg(double(*before.isovalue), 0, 'g', 6)
                                  .arg(double(*after.isovalue), 0, 'g', 6)
                            : QStringLiteral("Isovalue %1").arg(double(*after.isovalue), 0, 'g', 6),
            -1};
    }
    const auto table = settingTable();
    std::optional<SessionChange> change;
    int changed = 0;
    for (std::size_t i = 0; i < table.size(); ++i) {
        const Setting& s = table[i];
        if ((isCameraSetting(s) && s.id != "projection") && !cameraCounts) continue;
        const double from = s.get(before), to = s.get(after);
        if (from == to) continue;
        ++changed;
        const bool continuous = s.kind == SettingKind::Number || s.kind == SettingKind::Integer;
        change = SessionChange{QStringLiteral("%1 %2 -> %3")
                                   .arg(qs(s.label), QString::fromStdString(s.format(from)),
                                        QString::fromStdString(s.format(to))),
                               continuous ? static_cast<int>(i) : -1};
    }
    const SessionParts parts = differences(before, after);
    if (cameraCounts && parts.testFlag(SessionPart::Camera)) {
        return SessionChange{QStringLiteral("Reset Camera"), -1};
    }
    if (changed > 1) return SessionChange{QStringLiteral("Rendering Settings"), -1};
    if (change) return change;
    if (parts.testFlag(SessionPart::Plane)) {
        return SessionChange{QStringLiteral("Cutting Plane"), kPlaneKey};
    }
    if (parts.testFlag(SessionPart::Visibility)) {
        return SessionChange{QStringLiteral("Visibility"), -1};
    }
    if (parts.testFlag(SessionPart::Sections)) {
        // A place as typed; none: where the members' contours are.
        const auto place = [](const std::string& text) {
            return text.empty() ? QStringLiteral("default") : QString::fromStdString(text);
        };
        if (before.sections.level != after.sections.level) {
            return SessionChange{
                QStringLiteral("Map Level %1 -> %2")
                    .arg(place(before.sections.level), place(after.sections.level)),
                -1};
        }
        return SessionChange{QStringLiteral("Cross-Section %1 -> %2")
                                 .arg(place(before.sections.cross), place(after.sections.cross)),
                             -1};
    }
    return std::nullopt;
}

// One step: the session before and after it.
class SessionStep : public QUndoCommand {
public:
    SessionStep(SessionHistory& history, SessionState before, SessionState after,
                const SessionChange& change, bool cameraStep)
        : QUndoCommand(change.name),
          m_history(history),
          m_before(std::move(before)),
          m_after(std::move(after)),
          m_mergeKey(change.mergeKey),
          m_cameraStep(cameraStep) {}

    void undo() override { m_history.show(m_before, m_cameraStep); }
    void redo() override {
        // Pushed after the user made the change: the first redo has nothing to do.
        if (m_done) m_history.show(m_after, m_cameraStep);
        m_done = true;
    }
    [[nodiscard]] int id() const override { return m_mergeKey; }
    bool mergeWith(const QUndoCommand* other) override {
        const auto* next = dynamic_cast<const SessionStep*>(other);
        if (next == nullptr || next->m_mergeKey != m_mergeKey || m_mergeKey < 0) return false;
        m_after = next->m_after;
        const auto merged = describeChange(m_before, m_after, m_cameraStep);
        if (merged) setText(merged->name);
        return true;
    }

private:
    SessionHistory& m_history;
    SessionState m_before;
    SessionState m_after;
    int m_mergeKey;
    bool m_cameraStep;
    bool m_done = false;
};

SessionHistory::SessionHistory(Capture capture, Apply apply, QObject* parent)
    : QObject(parent), m_capture(std::move(capture)), m_apply(std::move(apply)) {}

void SessionHistory::reset() {
    m_stack.clear();
    m_last = m_capture();
}

void SessionHistory::absorb() {
    if (!m_applying) m_last = m_capture();
}

void SessionHistory::record(bool cameraStep, const QString& cameraStepName) {
    if (m_applying) return;
    SessionState now = m_capture();
    auto change = describeChange(m_last, now, cameraStep);
    if (change && cameraStep && !cameraStepName.isEmpty()) change->name = cameraStepName;
    if (change) m_stack.push(new SessionStep(*this, m_last, now, *change, cameraStep));
    m_last = std::move(now);
}

void SessionHistory::show(const SessionState& state, bool withCamera) {
    // What is not a step stays as it is now: the camera (unless the step moved it), the
    // selection and the window layout.
    const SessionState now = m_capture();
    SessionState shown = state;
    if (!withCamera) {
        shown.camera.azimuth = now.camera.azimuth;
        shown.camera.elevation = now.camera.elevation;
        shown.camera.placement = now.camera.placement;
    }
    shown.selection = now.selection;
    shown.windowGeometry = now.windowGeometry;
    shown.windowState = now.windowState;
    m_applying = true;
    m_apply(shown);
    m_applying = false;
    m_last = m_capture();
}

}  // namespace ensil::session
