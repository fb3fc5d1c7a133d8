// Running results kept in lanes: one running sum (in double) is a chain of dependent additions,
// one every few cycles, and consecutive values of a smooth field fall into the same histogram
// bin, whose count each increment must wait for; kLanes independent results taken in turn keep
// a core busy. The caller combines the lanes in order at the end, so a result depends only on
// the values, never on threads. Used by the value statistics and the distances to the mean.
#pragma once

#include <cstddef>

namespace ensil::prep {

inline constexpr std::size_t kLanes = 4;

// Calls add(lane, i) for every i in [0, count): the whole groups of kLanes indices one lane
// each, in order, and the remaining indices (fewer than kLanes) in lane 0.
template <typename Add>
void forEachInLanes(std::size_t count, Add&& add) {
    std::size_t i = 0;
    for (; i + kLanes <= count; i += kLanes) {
        for (std::size_t lane = 0; lane < kLanes; ++lane) add(lane, i + lane);
    }
    for (; i < count; ++i) add(std::size_t{0}, i);
}

}  // namespace ensil::prep
