#include "session/session_model.h"

namespace ensil::session {
namespace {
// The rendering settings apart from the plane, which is a part of its own.
bool sameRendering(gl::RenderSettings a, const gl::RenderSettings& b) {
    a.plane = b.plane;
    return a == b;
}

bool sameData(const SessionState& a, const SessionState& b) {
    return a.demo == b.demo && a.demoParams == b.demoParams && a.data == b.data;
}

// The angles and the place; the projection is a part of its own.
bool sameCamera(const CameraState& a, const CameraState& b) {
    return a.azimuth == b.azimuth && a.elevation == b.elevation && a.placement == b.placement;
}
}  // namespace

SessionParts differences(const SessionState& a, const SessionState& b) {
    SessionParts parts;
    if (!sameData(a, b)) parts |= SessionPart::Data;
    if (a.isovalue != b.isovalue) parts |= SessionPart::Isovalue;
    if (a.clusters != b.clusters) parts |= SessionPart::Clusters;
    if (a.linkage != b.linkage) parts |= SessionPart::Linkage;
    if (!sameRendering(a.render, b.render)) parts |= SessionPart::Rendering;
    if (a.render.plane != b.render.plane) parts |= SessionPart::Plane;
    if (a.verticalExaggeration != b.verticalExaggeration) parts |= SessionPart::Exaggeration;
    if (a.background != b.background) parts |= SessionPart::Background;
    if (a.camera.orthographic != b.camera.orthographic) parts |= SessionPart::Projection;
    if (!sameCamera(a.camera, b.camera)) parts |= SessionPart::Camera;
    if (a.hiddenMembers != b.hiddenMembers || a.hiddenClusters != b.hiddenClusters) {
        parts |= SessionPart::Visibility;
    }
    if (a.selection != b.selection) parts |= SessionPart::Selection;
    if (a.sections != b.sections || a.sectionsFill != b.sectionsFill ||
        a.sectionsColours != b.sectionsColours) {
        parts |= SessionPart::Sections;
    }
    if (a.windowGeometry != b.windowGeometry || a.windowState != b.windowState) {
        parts |= SessionPart::Layout;
    }
    return parts;
}

void SessionModel::update(const std::function<void(SessionState&)>& edit) {
    SessionState next = m_state;
    edit(next);
    const SessionParts parts = differences(m_state, next);
    if (!parts) return;
    m_state = std::move(next);
    emit changed(parts);
}

}  // namespace ensil::session
