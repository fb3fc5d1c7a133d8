// The isovalue a variable opens at: one where most members have a surface, in the middle half of
// the box's height, and the members differ (METHODS.md section 14). Candidates are the 50th to
// 95th percentiles of the values in steps of 5, then the 10th to 45th; for each, on an even
// sample of the grid's points, it counts the members with at least 1 % of their points on each
// side of it (they have a surface), on an even sample of the grid's columns the members whose
// surface crosses at least 1 % of them in the middle half of the box's height (as drawn, at
// vertical exaggeration 1: through log-pressure for pressure levels), and measures how much the
// members disagree about which side each point is on. Of the candidates where at least 80 % of
// the members have a surface, 80 % have one in the middle half, and the disagreement is at least
// half the largest, the one nearest the paper's choice wins (the 90th percentile, about 30 m/s
// for the demo's wind speed; of two equally near, the higher); the lower percentiles only when
// none of the upper ones qualifies (a temperature, whose warm end lies on the floor). Pure; any
// thread.
#pragma once

#include "data/ensemble.h"
#include "preprocessing/field_statistics.h"

namespace ensil::prep {

struct IsovalueCandidate {
    int percentile = 0;
    float isovalue = 0.0F;
    double membersWithSurface = 0.0;  // fraction of the members
    double membersInMiddle = 0.0;     // fraction with a surface in the middle half of the height
    double disagreement = 0.0;        // mean over sampled points of 4 p (1 - p), p: share above
};

// Every candidate, in percentile order, for tests and `ensil info`.
std::vector<IsovalueCandidate> isovalueCandidates(const data::Ensemble& ensemble,
                                                  const FieldStatistics& statistics);

// The chosen isovalue; when no candidate has enough members with a surface in the middle half,
// the same rule without that condition; the 90th percentile when no candidate has enough members
// with a surface at all, the middle of the range when there are no values.
float defaultIsovalue(const data::Ensemble& ensemble, const FieldStatistics& statistics);

inline constexpr double kMostMembers = 0.8;
// A member has a surface worth seeing when at least this share of its points lies on each
// side of the isovalue: a speck around a few points is not one.
inline constexpr double kLeastShare = 0.01;

}  // namespace ensil::prep
