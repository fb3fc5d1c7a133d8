// The isovalue a variable opens at: one where most members have a surface and the members
// differ (METHODS.md section 14). Candidates are the 50th to 95th percentiles of the values in
// steps of 5; for each, on an even sample of the grid's points, it counts the members with at
// least 1 % of their points on each side of it (they have a surface) and measures how much the
// members disagree about which side each point is on. Of the candidates where at least 80 % of
// the members have a surface and the disagreement is at least half the largest, the one nearest
// the paper's choice wins (the 90th percentile, about 30 m/s for the demo's wind speed; of two
// equally near, the higher). Pure; any thread.
#pragma once

#include "data/ensemble.h"
#include "preprocessing/field_statistics.h"

namespace ensil::prep {

struct IsovalueCandidate {
    int percentile = 0;
    float isovalue = 0.0F;
    double membersWithSurface = 0.0;  // fraction of the members
    double disagreement = 0.0;        // mean over sampled points of 4 p (1 - p), p: share above
};

// Every candidate, in percentile order, for tests and `ensil info`.
std::vector<IsovalueCandidate> isovalueCandidates(const data::Ensemble& ensemble,
                                                  const FieldStatistics& statistics);

// The chosen isovalue; the 90th percentile when no candidate has enough members with a
// surface, the middle of the range when there are no values.
float defaultIsovalue(const data::Ensemble& ensemble, const FieldStatistics& statistics);

inline constexpr double kMostMembers = 0.8;
// A member has a surface worth seeing when at least this share of its points lies on each
// side of the isovalue: a speck around a few points is not one.
inline constexpr double kLeastShare = 0.01;

}  // namespace ensil::prep
