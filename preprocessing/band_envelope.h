// The fields whose isosurfaces bound the contour boxplot's 50 % band (METHODS.md section 17):
// at every grid point the lowest and the highest value of the band's members. A point is inside
// every band member (f > c in each) exactly where the lowest value exceeds c, and inside any of
// them where the highest does, so their isosurfaces at c are the boundaries of the intersection
// and the union of the members' inside sets, placed between grid points by the same linear
// interpolation as the members' own surfaces (not at the midpoint of every cell edge, as the
// 0.5 surface of a 0/1 indicator field is). Pure function; any thread.
#pragma once

#include <cstddef>
#include <span>
#include <stop_token>

#include "data/ensemble.h"

namespace ensil::prep {

struct BandEnvelope {
    // The lowest value of the members at each point; NaN where any of them is missing (NaN or
    // infinite): such a point is inside none of the intersections, and the inner surface
    // leaves it out as a member's surface leaves out its own missing points.
    data::FieldValues lowest;
    // The highest of the members' valid values; NaN where every one is missing.
    data::FieldValues highest;
};

// Throws data::Cancelled, and data::Error(InvalidArgument) for no members, a member index out
// of range, or a member whose value count differs from the grid's point count.
BandEnvelope computeBandEnvelope(const data::Ensemble& ensemble,
                                 std::span<const std::size_t> members,
                                 const std::stop_token& stop = {});

}  // namespace ensil::prep
