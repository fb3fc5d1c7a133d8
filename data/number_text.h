// A value as a person reads it in a figure, a title or a colour bar: its significant digits,
// in plain decimal notation between 0.001 and 1,000,000 ("23,690", "0.06712", "260"), with a
// comma between thousands from 10,000 on, and in exponent notation only outside that range
// ("1.035e-05"). Trailing zeros after the point are dropped. Pure; any thread.
#pragma once

#include <string>

namespace ensil::data {

// `significant` digits (at least 1); more of the integer part are kept, never rounded away:
// 23694 with 4 digits is "23,694".
std::string readableNumber(double value, int significant = 4);

}  // namespace ensil::data
