#include "widgets/session/session_model.h"

namespace ensil::session {
namespace {
bool samePlane(const gl::CuttingPlane& a, const gl::CuttingPlane& b) {
    return a.enabled == b.enabled && a.normal == b.normal && a.offset == b.offset &&
           a.thickness == b.thickness;
}

bool sameRendering(gl::RenderSettings a, const gl::RenderSettings& b) {
    a.plane = b.plane;
    return a.mode == b.mode && a.thickness == b.thickness && a.surfaceAlpha == b.surfaceAlpha &&
           a.showMean == b.showMean && a.removal == b.removal && a.removalMin == b.removalMin &&
           a.removalMax == b.removalMax && a.groupSize == b.groupSize && a.showAxes == b.showAxes &&
           a.showLegend == b.showLegend && a.silhouetteCulling == b.silhouetteCulling;
}

bool sameData(const SessionState& a, const SessionState& b) {
    const auto& p = a.demoParams;
    const auto& q = b.demoParams;
    return a.demo == b.demo && p.members == q.members && p.nx == q.nx && p.ny == q.ny &&
           p.nz == q.nz && p.seed == q.seed && a.data.paths == b.data.paths &&
           a.data.variable == b.data.variable && a.data.memberDimension == b.data.memberDimension &&
           a.data.timeIndex == b.data.timeIndex;
}

bool sameCamera(const CameraState& a, const CameraState& b) {
    const bool samePlacement = a.placement.has_value() == b.placement.has_value() &&
                               (!a.placement || (a.placement->distance == b.placement->distance &&
                                                 a.placement->target == b.placement->target));
    return a.azimuth == b.azimuth && a.elevation == b.elevation && samePlacement;
}
}  // namespace

SessionParts differences(const SessionState& a, const SessionState& b) {
    SessionParts parts;
    if (!sameData(a, b)) parts |= SessionPart::Data;
    if (a.isovalue != b.isovalue) parts |= SessionPart::Isovalue;
    if (a.clusters != b.clusters) parts |= SessionPart::Clusters;
    if (a.linkage != b.linkage) parts |= SessionPart::Linkage;
    if (!sameRendering(a.render, b.render)) parts |= SessionPart::Rendering;
    if (!samePlane(a.render.plane, b.render.plane)) parts |= SessionPart::Plane;
    if (a.verticalExaggeration != b.verticalExaggeration) parts |= SessionPart::Exaggeration;
    if (a.background != b.background) parts |= SessionPart::Background;
    if (a.camera.orthographic != b.camera.orthographic) parts |= SessionPart::Projection;
    if (!sameCamera(a.camera, b.camera)) parts |= SessionPart::Camera;
    if (a.hiddenMembers != b.hiddenMembers || a.hiddenClusters != b.hiddenClusters) {
        parts |= SessionPart::Visibility;
    }
    if (a.selection != b.selection) parts |= SessionPart::Selection;
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
