#include "engine/floor_map.h"

#include <algorithm>
#include <array>
#include <cstdio>

#include "engine/picture_title.h"
#include "preprocessing/column_maximum.h"
#include "preprocessing/member_spread.h"

namespace ensil::engine {

ColumnMaxima computeColumnMaxima(const data::Ensemble& ensemble, const data::Member& mean,
                                 const std::stop_token& stop) {
    ColumnMaxima maxima;
    maxima.mean = prep::computeColumnMaximum(ensemble.grid, mean);
    auto stddev =
        std::make_shared<const data::FieldValues>(prep::computeMemberSpread(ensemble, stop));
    maxima.spread = prep::computeColumnMaximum(ensemble.grid, {"stddev", *stddev});
    maxima.stddev = std::move(stddev);
    return maxima;
}

gl::FloorMap floorMapFor(const data::Ensemble& e, const data::Member& mean,
                         const ColumnMaxima& columnMaxima, const gl::RenderSettings& settings) {
    switch (settings.floor) {
        case gl::FloorContent::None:
            return {};
        case gl::FloorContent::ColumnMaximum:
            return gl::FloorMap::spanning(columnMaxima.mean,
                                          QString::fromStdString(floorCaption(e)));
        case gl::FloorContent::ProbabilityMaximum: {
            if (columnMaxima.exceedance.size() != e.grid.nx() * e.grid.ny()) return {};
            // A probability keeps its own scale, 0 to 1, whatever the values in view.
            gl::FloorMap map;
            map.values = columnMaxima.exceedance;
            map.caption = QString::fromStdString("floor: column maximum of " +
                                                 exceedanceText(e, columnMaxima.isovalue));
            return map;
        }
        case gl::FloorContent::SpreadMaximum:
            return gl::FloorMap::spanning(
                columnMaxima.spread,
                QString::fromStdString("floor: column maximum of the members' standard "
                                       "deviation of " +
                                       e.variable + unitsInBrackets(e)));
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

}  // namespace ensil::engine
