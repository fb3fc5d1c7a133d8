// The field the cutting plane's cut face shows (gl::SectionField, METHODS.md section 18), with
// its colour bar's caption and range. Shared by the workbench and `ensil render`.
#pragma once

#include "data/ensemble.h"
#include "gl/renderer.h"

namespace ensil::engine {

struct SectionSources {
    const data::Ensemble* ensemble = nullptr;
    const data::Member* mean = nullptr;
    const data::FieldValues* stddev = nullptr;      // the members' sample standard deviation
    const data::FieldValues* exceedance = nullptr;  // P(f > c) at `isovalue`; null before one
    float isovalue = 0.0F;
    // The ensemble's value range: a member and the mean are coloured on it, so one colour
    // means one value whichever member is shown.
    float valueMinimum = 0.0F;
    float valueMaximum = 1.0F;
    int member = -1;  // for SectionField::Member: the hovered member, else the first selected
};

// An empty volume (the face stays unfilled) when the field asked for is not there: no member
// to show, no isovalue yet, or a field of the wrong size.
gl::SectionVolume sectionVolumeFor(const SectionSources& sources, gl::SectionField field);

}  // namespace ensil::engine
