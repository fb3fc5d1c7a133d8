// Per-point sums over the members (the mean member, the variance) on oneTBB's threads: the grid's
// points in consecutive blocks, a block's sums small enough to stay in cache while every member
// passes through them. Each point's members are taken in member order inside its block, so the
// result does not depend on the threads. Any thread.
#pragma once

#include <cstddef>
#include <functional>
#include <stop_token>

#include "data/job.h"

namespace ensil::prep {

// Points a block holds: its sums take 12 bytes a point.
inline constexpr std::size_t kPointsPerBlock = std::size_t{1} << 14;

// Runs work(first, count) for the blocks of [0, points), each checking `stop` before it begins
// (throws data::Cancelled) and moving `progress` from `from` to `to` when it ends.
void forEachPointBlock(std::size_t points, const std::stop_token& stop,
                       const data::Progress& progress, double from, double to,
                       const std::function<void(std::size_t first, std::size_t count)>& work);

}  // namespace ensil::prep
