// What a picture shows, in words: the title line drawn above it ("t (Temperature) [K] ·
// isovalue 260 K · time 2017-01-01T00:00 · 10 members along number") and a file name made of
// the same facts ("t_260K_time-2017-01-01T00-00"), so a saved picture explains itself. Used
// by `ensil render` and the workbench's view and screenshots. Pure; any thread.
#pragma once

#include <string>

#include "data/ensemble.h"

namespace ensil::app {

std::string pictureTitle(const data::Ensemble& ensemble, float isovalue);
// What the floor map shows, for its colour bar: "floor: column maximum of the mean t [K]".
std::string floorCaption(const data::Ensemble& ensemble);
// Letters, digits, '.', '-' and '_' only; no extension.
std::string pictureFileStem(const data::Ensemble& ensemble, float isovalue);

}  // namespace ensil::app
