#include "engine/section_volume.h"

#include "data/units_text.h"
#include "engine/picture_title.h"

namespace ensil::engine {
namespace {

gl::SectionVolume volumeOf(const data::FieldValues& field, float minimum, float maximum,
                           const std::string& quantity, const std::string& units) {
    gl::SectionVolume volume;
    volume.values.assign(field.begin(), field.end());
    volume.minimum = minimum;
    volume.maximum = maximum;
    volume.quantity = QString::fromStdString(quantity);
    volume.units = QString::fromStdString(data::readableUnits(units));
    return volume;
}

}  // namespace

gl::SectionVolume sectionVolumeFor(const SectionSources& s, gl::SectionField field) {
    if (s.ensemble == nullptr) return {};
    const data::Ensemble& e = *s.ensemble;
    const std::size_t points = e.grid.pointCount();
    const auto fits = [&](const data::FieldValues* values) {
        return values != nullptr && values->size() == points && points > 0;
    };
    const std::string quantity = sectionQuantity(e, field, s.member, s.isovalue);
    switch (field) {
        case gl::SectionField::None:
            return {};
        case gl::SectionField::Member: {
            if (s.member < 0 || static_cast<std::size_t>(s.member) >= e.memberCount()) return {};
            const data::Member& member = e.members[static_cast<std::size_t>(s.member)];
            if (!fits(&member.values)) return {};
            return volumeOf(member.values, s.valueMinimum, s.valueMaximum, quantity, e.units);
        }
        case gl::SectionField::Mean:
            if (s.mean == nullptr || !fits(&s.mean->values)) return {};
            return volumeOf(s.mean->values, s.valueMinimum, s.valueMaximum, quantity, e.units);
        case gl::SectionField::StandardDeviation: {
            if (!fits(s.stddev)) return {};
            // From no spread up to the largest: zero reads as "the members agree".
            gl::SectionVolume volume = volumeOf(*s.stddev, 0.0F, 1.0F, quantity, e.units);
            float largest = 0.0F;
            for (const float v : volume.values) {
                if (v > largest) largest = v;  // NaN compares false
            }
            volume.maximum = largest > 0.0F ? largest : 1.0F;
            return volume;
        }
        case gl::SectionField::Probability:
            // A probability keeps its own scale, 0 to 1, as on the floor.
            if (!fits(s.exceedance)) return {};
            return volumeOf(*s.exceedance, 0.0F, 1.0F, quantity, {});
    }
    return {};
}

}  // namespace ensil::engine
