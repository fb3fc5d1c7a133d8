// Undo and redo of a session: each user edit (an isovalue, the clusters, the linkage, member
// visibility, any rendering setting, the cutting plane, a camera reset) becomes one named step
// ("Isovalue 35.6 -> 30", "Thickness τ 0.006 -> 0.01"), found by comparing the session before
// and after. Consecutive changes of the same number (a dragged slider, the dendrogram's cut
// line) merge into one step. The camera's own motion, the selection and the window layout are
// not steps, and undoing a step leaves them as they are. Who owns the session says how to read
// it (capture) and how to show one (apply). GUI thread.
#pragma once

#include <QObject>
#include <QString>
#include <QUndoStack>
#include <functional>
#include <optional>

#include "session/session_state.h"

namespace ensil::session {

// What changed between two sessions, as an undo step's name, and whether a following change of
// the same kind merges with it (mergeKey >= 0).
struct SessionChange {
    QString name;
    int mergeKey = -1;
};
// Nothing worth a step: none. `cameraCounts`: the camera's angles and place are part of it.
std::optional<SessionChange> describeChange(const SessionState& before, const SessionState& after,
                                            bool cameraCounts);

class SessionHistory : public QObject {
    Q_OBJECT
public:
    using Capture = std::function<SessionState()>;
    using Apply = std::function<void(const SessionState&)>;
    SessionHistory(Capture capture, Apply apply, QObject* parent = nullptr);

    // The session as it stands is the new starting point: nothing to undo (new data, a project).
    void reset();
    // The session changed by itself, not by the user (a new isovalue's outlyingness range moved
    // the removal thresholds): no step, and the next step starts from here.
    void absorb();
    // Records what changed since the last record as one step (or merges it into the last).
    // `cameraStep`: a camera reset or view preset, whose camera is part of the step, named
    // `cameraStepName` ("Map View (North Up)").
    void record(bool cameraStep = false, const QString& cameraStepName = {});
    [[nodiscard]] QUndoStack* stack() { return &m_stack; }
    // True while a step is being undone or redone (its own changes are not recorded).
    [[nodiscard]] bool applying() const { return m_applying; }

private:
    friend class SessionStep;
    void show(const SessionState& state, bool withCamera);

    Capture m_capture;
    Apply m_apply;
    QUndoStack m_stack;
    SessionState m_last;
    bool m_applying = false;
};

}  // namespace ensil::session
