// The real files written by others that the tests read (tests/data/real, ENSIL_SHARED_DATA_DIR,
// which every suite defines).
#pragma once

#include <string>

namespace ensil::test {

inline std::string sharedDataFile(const char* name) {
    return std::string(ENSIL_SHARED_DATA_DIR "/") + name;
}

}  // namespace ensil::test
