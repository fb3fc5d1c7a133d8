#include "workbench/point_description.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "data/field_sampling.h"
#include "data/units_text.h"
#include "gl/axis_ticks.h"

namespace ensil::workbench {
namespace {

QString value(float v, const std::string& units) {
    if (std::isnan(v)) return QStringLiteral("missing");
    return QString::number(v, 'g', 5) +
           (units.empty() ? QString() : QStringLiteral(" ") + QString::fromStdString(units));
}

// The place: true longitude and latitude where the grid has geography, else its own axes.
QString place(const PointContext& c, const glm::dvec3& index) {
    const data::Grid& g = c.ensemble->grid;
    const double x = g.x().valueAt(index.x);
    const double y = g.y().valueAt(index.y);
    if (c.projection != nullptr && c.projection->hasGeography()) {
        std::vector<glm::dvec2> p{{x, y}};
        c.projection->toLonLat(p);
        if (std::isfinite(p.front().x)) return formatLonLat(p.front().x, p.front().y);
    }
    return QStringLiteral("%1 %2, %3 %4")
        .arg(QString::fromStdString(g.x().name))
        .arg(x, 0, 'g', 6)
        .arg(QString::fromStdString(g.y().name))
        .arg(y, 0, 'g', 6);
}

QString level(const data::Axis& axis, double index) {
    const gl::AxisLabelling labelling = gl::labellingFor(axis);
    const double shown = axis.valueAt(index) * labelling.shownPerUnit;
    return QString::number(shown, 'g', 4) + QStringLiteral(" ") +
           QString::fromStdString(labelling.units.empty() ? axis.name : labelling.units);
}

}  // namespace

QString formatLonLat(double lon, double lat) {
    const double east = std::remainder(lon, 360.0);
    return QStringLiteral("%1\u00b0 %2, %3\u00b0 %4")
        .arg(std::abs(lat), 0, 'f', 2)
        .arg(lat >= 0.0 ? QLatin1Char('N') : QLatin1Char('S'))
        .arg(std::abs(east), 0, 'f', 2)
        .arg(east >= 0.0 ? QLatin1Char('E') : QLatin1Char('W'));
}

QString describePoint(const PointContext& c, const gl::PickResult& hit) {
    if (c.ensemble == nullptr || c.frame == nullptr || c.mean == nullptr) return {};
    const data::Ensemble& e = *c.ensemble;
    const std::string units = data::readableUnits(e.units);
    const QString variable = QString::fromStdString(e.variable);
    if (hit.surface && hit.member >= 0 && static_cast<std::size_t>(hit.member) < e.memberCount()) {
        const glm::dvec3 index = c.frame->displayToIndex(*hit.surface);
        const float member = data::sampleTrilinear(
            e.grid, e.members[static_cast<std::size_t>(hit.member)].values, index);
        const float mean = data::sampleTrilinear(e.grid, c.mean->values, index);
        return QStringLiteral("%1 \u00b7 %2 \u00b7 %3 %4 here, mean %5")
            .arg(place(c, index), level(e.grid.z(), index.z), variable, value(member, units),
                 value(mean, units));
    }
    if (hit.section && c.section != nullptr && c.section->values.size() == e.grid.pointCount()) {
        const glm::dvec3 index = c.frame->displayToIndex(*hit.section);
        const float v = gl::sectionValueAt(*c.section, e.grid, *c.frame, *hit.section);
        return QStringLiteral("%1 \u00b7 %2 \u00b7 %3 %4")
            .arg(place(c, index), level(e.grid.z(), index.z), c.section->quantity,
                 value(v, c.section->units.toStdString()));
    }
    if (hit.floor) {
        glm::dvec3 index = c.frame->displayToIndex(*hit.floor);
        // The floor map: the mean's largest value in the column.
        float maximum = std::numeric_limits<float>::quiet_NaN();
        for (std::size_t k = 0; k < e.grid.nz(); ++k) {
            index.z = static_cast<double>(k);
            const float v = data::sampleTrilinear(e.grid, c.mean->values, index);
            if (!std::isnan(v) && !(v <= maximum)) maximum = v;
        }
        return QStringLiteral("%1 \u00b7 column maximum of the mean %2 %3")
            .arg(place(c, index), variable, value(maximum, units));
    }
    return {};
}

}  // namespace ensil::workbench
