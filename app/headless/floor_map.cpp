#include "app/headless/floor_map.h"

#include <algorithm>

#include "app/headless/picture_title.h"

namespace ensil::app {

gl::FloorMap floorMapFor(const data::Ensemble& e, const data::Member& mean,
                         const std::vector<float>& columnMaximum,
                         const gl::RenderSettings& settings) {
    switch (settings.floor) {
        case gl::FloorContent::None:
            return {};
        case gl::FloorContent::ColumnMaximum:
            return gl::FloorMap::spanning(columnMaximum, QString::fromStdString(floorCaption(e)));
        case gl::FloorContent::MeanAtLevel: {
            const std::size_t nx = e.grid.nx(), ny = e.grid.ny();
            const auto k = static_cast<std::size_t>(
                std::clamp(settings.floorLevel, 0, static_cast<int>(e.grid.nz()) - 1));
            if (mean.values.size() != e.grid.pointCount()) return {};
            std::vector<float> slice(nx * ny);
            std::copy_n(mean.values.begin() + static_cast<std::ptrdiff_t>(k * nx * ny), nx * ny,
                        slice.begin());
            return gl::FloorMap::spanning(
                std::move(slice), QString::fromStdString(floorCaption(e, settings.floorLevel)));
        }
    }
    return {};
}

}  // namespace ensil::app
