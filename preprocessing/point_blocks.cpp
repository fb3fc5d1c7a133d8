#include "preprocessing/point_blocks.h"

#include <tbb/parallel_for.h>

#include <algorithm>

namespace ensil::prep {

void forEachPointBlock(std::size_t points, const std::stop_token& stop,
                       const data::Progress& progress, double from, double to,
                       const std::function<void(std::size_t first, std::size_t count)>& work) {
    const std::size_t blocks = (points + kPointsPerBlock - 1) / kPointsPerBlock;
    data::PartsProgress blocksDone(progress, blocks, from, to);
    tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
        data::throwIfStopped(stop);
        const std::size_t first = b * kPointsPerBlock;
        work(first, std::min(kPointsPerBlock, points - first));
        blocksDone.partDone();
    });
}

}  // namespace ensil::prep
