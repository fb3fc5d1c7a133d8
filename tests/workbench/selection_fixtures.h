// Members on a line, for the tests of the shared selection and of the panels that show it: their
// distance is how far apart they sit, so the clusters are known.
#pragma once

#include <QString>
#include <cmath>
#include <vector>

#include "preprocessing/clustering.h"
#include "workbench/member_selection.h"

namespace ensil::test {

// Six members in two groups, interleaved so the dendrogram order differs from the index
// order: {0, 2, 4} near 0 and {1, 3, 5} near 10.
inline const std::vector<double> kTwoGroups{0.0, 10.0, 0.5, 10.7, 1.5, 12.0};

inline prep::MergeTree treeOnALine(const std::vector<double>& positions,
                                   prep::Linkage linkage = prep::Linkage::Average) {
    prep::DistanceMatrix d;
    d.size = positions.size();
    d.values.resize(d.size * d.size);
    for (std::size_t i = 0; i < d.size; ++i)
        for (std::size_t j = 0; j < d.size; ++j)
            d.values[i * d.size + j] = std::abs(positions[i] - positions[j]);
    return prep::clusterMembers(d, linkage);
}

// Names "m0", "m1", ...; distance to the mean = position; outlyingness = 2 * position, except
// member 2's, which is unknown (NaN).
inline workbench::MemberFigures figuresOnALine(const std::vector<double>& positions) {
    workbench::MemberFigures f;
    for (std::size_t m = 0; m < positions.size(); ++m) {
        f.names << QStringLiteral("m%1").arg(m);
        f.distanceToMean.push_back(positions[m]);
        f.meanOutlyingness.push_back(m == 2 ? std::nan("") : 2.0 * positions[m]);
    }
    return f;
}

inline void loadTwoGroups(workbench::MemberSelection& selection, int clusters = 2) {
    selection.setMembers(figuresOnALine(kTwoGroups));
    selection.setTree(treeOnALine(kTwoGroups));
    selection.setClusterCount(clusters);
}

}  // namespace ensil::test
