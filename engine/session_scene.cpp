#include "engine/session_scene.h"

#include "engine/section_volume.h"
#include "session/member_appearance.h"

namespace ensil::engine {

gl::FloorMap sceneFloor(const SceneData& data, const gl::RenderSettings& settings) {
    if (data.ensemble == nullptr || data.mean == nullptr || data.columnMaxima == nullptr) return {};
    ColumnMaxima maxima = *data.columnMaxima;
    // The probability's floor belongs to the isovalue drawn.
    if (data.isovalue && data.exceedanceColumnMaximum != nullptr) {
        maxima.exceedance = *data.exceedanceColumnMaximum;
        maxima.isovalue = *data.isovalue;
    }
    gl::FloorMap floor = floorMapFor(*data.ensemble, *data.mean, maxima, settings);
    if (data.floorRange && !floor.values.empty()) {
        floor.minimum = data.floorRange->first;
        floor.maximum = data.floorRange->second;
        floor.caption += QString::fromStdString(data.floorRangeNote);
    }
    return floor;
}

int sectionMember(const std::vector<int>& selection, int lastHovered) {
    return !selection.empty() ? selection.front() : lastHovered;
}

gl::SectionVolume sceneSection(const SceneData& data, gl::SectionField field, int member) {
    SectionSources sources;
    sources.ensemble = data.ensemble;
    sources.mean = data.mean;
    sources.stddev = data.columnMaxima != nullptr ? data.columnMaxima->stddev.get() : nullptr;
    sources.exceedance = data.exceedance;
    sources.isovalue = data.isovalue.value_or(0.0F);
    sources.valueMinimum = data.valueMinimum;
    sources.valueMaximum = data.valueMaximum;
    sources.member = member;
    return sectionVolumeFor(sources, field);
}

std::vector<gl::MemberAppearance> sceneAppearance(const session::SessionState& state,
                                                  const std::vector<int>& labels,
                                                  const std::vector<int>& identities,
                                                  int memberCount) {
    return session::memberAppearance(labels, identities,
                                     session::memberFlags(state, labels, memberCount));
}

void showSession(gl::Renderer& renderer, const session::SessionState& state, const SceneData& data,
                 session::SessionParts parts) {
    using session::SessionPart;
    if (parts & SessionPart::Exaggeration) {
        renderer.setVerticalExaggeration(state.verticalExaggeration);
    }
    if (parts & (SessionPart::Rendering | SessionPart::Plane)) {
        const gl::RenderSettings& drawn = renderer.settings();
        if ((parts & SessionPart::Data) || state.render.floor != drawn.floor ||
            state.render.floorLevel != drawn.floorLevel) {
            renderer.setFloorMap(sceneFloor(data, state.render));
        }
        if (state.render.verticalAxis != drawn.verticalAxis) {
            renderer.setVerticalAxis(state.render.verticalAxis);
        }
        renderer.settings() = state.render;
    }
    if (parts & SessionPart::Background) renderer.setBackground({state.background, 1.0F});
    if (parts & SessionPart::Projection) {
        renderer.camera().setProjection(state.camera.orthographic
                                            ? gl::Camera::Projection::Orthographic
                                            : gl::Camera::Projection::Perspective);
    }
}

}  // namespace ensil::engine
