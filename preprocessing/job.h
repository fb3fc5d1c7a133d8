// Preprocessing steps follow the job contract of data/job.h: pure functions
// (input, std::stop_token, Progress) -> result that throw Cancelled when stopped.
#pragma once

#include "data/job.h"

namespace ensil::prep {

using data::Cancelled;
using data::Progress;
using data::report;
using data::throwIfStopped;

}  // namespace ensil::prep
