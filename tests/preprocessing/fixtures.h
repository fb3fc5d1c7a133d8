// Small analytic ensembles for preprocessing tests.
#pragma once

#include <functional>

#include "data/ensemble.h"

namespace ensil::test {

// n members on an nx x ny x nz unit grid; member m's value at index (i, j, k) is f(m, i, j, k).
inline data::Ensemble analyticEnsemble(
    std::size_t members, std::size_t nx, std::size_t ny, std::size_t nz,
    const std::function<float(std::size_t, std::size_t, std::size_t, std::size_t)>& f) {
    data::Ensemble e;
    e.variable = "f";
    e.grid = data::Grid(data::makeUniformAxis("x", "m", 0, 1, nx),
                        data::makeUniformAxis("y", "m", 0, 1, ny),
                        data::makeUniformAxis("z", "m", 0, 1, nz));
    e.members.resize(members);
    for (std::size_t m = 0; m < members; ++m) {
        e.members[m].values.resize(e.grid.pointCount());
        for (std::size_t k = 0; k < nz; ++k)
            for (std::size_t j = 0; j < ny; ++j)
                for (std::size_t i = 0; i < nx; ++i)
                    e.members[m].values[e.grid.index(i, j, k)] = f(m, i, j, k);
    }
    return e;
}

}  // namespace ensil::test
