// The session the workbench shows, as one observable value: every edit goes through update(),
// which says which parts changed; the panels, the toolbar, the view and the isovalue job are
// kept in step with it by the main window's bindings, and undo, projects and the remembered
// settings read and replace it whole. The camera's live motion is the view's until it is
// captured. GUI thread.
#pragma once

#include <QFlags>
#include <QObject>
#include <functional>

#include "session/session_state.h"

namespace ensil::session {

enum class SessionPart {
    Data = 1 << 0,  // the data source and its choices
    Isovalue = 1 << 1,
    Clusters = 1 << 2,  // the number of clusters
    Linkage = 1 << 3,
    Rendering = 1 << 4,  // gl::RenderSettings without the plane
    Plane = 1 << 5,
    Exaggeration = 1 << 6,  // vertical exaggeration: the meshes' attributes depend on it
    Background = 1 << 7,
    Projection = 1 << 8,
    Camera = 1 << 9,       // angles and placement
    Visibility = 1 << 10,  // hidden members and clusters
    Selection = 1 << 11,
    Layout = 1 << 12,
    Sections = 1 << 13,  // the Sections dock's places and fill
};
Q_DECLARE_FLAGS(SessionParts, SessionPart)
Q_DECLARE_OPERATORS_FOR_FLAGS(SessionParts)

// Which parts differ between two sessions.
SessionParts differences(const SessionState& a, const SessionState& b);

class SessionModel : public QObject {
    Q_OBJECT
public:
    explicit SessionModel(QObject* parent = nullptr) : QObject(parent) {}

    [[nodiscard]] const SessionState& state() const { return m_state; }
    // Applies the edit; emits changed() with the parts that now differ (nothing when none).
    void update(const std::function<void(SessionState&)>& edit);
    void replace(const SessionState& state) {
        update([&](SessionState& s) { s = state; });
    }

signals:
    void changed(ensil::session::SessionParts parts);

private:
    SessionState m_state;
};

}  // namespace ensil::session
