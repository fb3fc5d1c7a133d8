// What a picture shows, in words: the title line drawn above it ("t (Temperature) [K] ·
// isovalue 260 K · time 2017-01-01T00:00 · 10 members along number") and a file name made of
// the same facts ("t_260K_time-2017-01-01T00-00"), so a saved picture explains itself. Used
// by `ensil render` and the workbench's view and screenshots. Pure; any thread.
#pragma once

#include <functional>
#include <string>

#include "data/ensemble.h"
#include "gl/render_settings.h"

namespace ensil::engine {

std::string pictureTitle(const data::Ensemble& ensemble, float isovalue);
// pictureTitle of this ensemble for any isovalue, holding only the words (not the data): the
// workbench's view titles each frame with the isovalue of the surfaces it draws.
std::function<std::string(float isovalue)> pictureTitleOf(const data::Ensemble& ensemble);
// " [m s⁻¹]" (the units as people read them, data/units_text.h), or nothing without units.
std::string unitsInBrackets(const data::Ensemble& ensemble);
// What the floor map shows, for its colour bar: "floor: column maximum of the mean t [K]",
// "floor: mean t at 850 hPa [K]" (level: a vertical grid index, clamped to the grid).
std::string floorCaption(const data::Ensemble& ensemble);
std::string floorCaption(const data::Ensemble& ensemble, int level);
// "P(z > 5.757e+04 m2 s-2)": the probability of exceeding the isovalue, in the floor's and
// the section's captions.
std::string exceedanceText(const data::Ensemble& ensemble, float isovalue);
// What a value on the cutting plane's cut face is: "member 7: z", "mean z", "standard
// deviation of z", "P(t > 260 K)". `member` indexes ensemble.members.
std::string sectionQuantity(const data::Ensemble& ensemble, gl::SectionField field, int member,
                            float isovalue);
// Letters, digits, '.', '-' and '_' only; no extension.
std::string pictureFileStem(const data::Ensemble& ensemble, float isovalue);

}  // namespace ensil::engine
