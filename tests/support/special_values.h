// The float values that stand for missing data and overflow in the tests' fields.
#pragma once

#include <limits>

namespace ensil::test {

inline constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
inline constexpr float kInf = std::numeric_limits<float>::infinity();

}  // namespace ensil::test
