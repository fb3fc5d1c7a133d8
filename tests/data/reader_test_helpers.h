// Helpers shared by the reader tests: building a selection, and catching a reader's error.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "data/ensemble_reader.h"
#include "data/error.h"

namespace ensil::test {

// Spelled out because GCC 12 warns about designated initializers that skip fields.
inline data::DataSelection selection(std::vector<std::string> paths, std::string variable = {}) {
    data::DataSelection s;
    s.paths = std::move(paths);
    s.variable = std::move(variable);
    return s;
}

// The error openEnsemble throws for the selection; a test failure when it opens without one.
inline data::Error errorOpening(const data::DataSelection& s) {
    try {
        (void)data::openEnsemble(s);
    } catch (const data::Error& e) {
        return e;
    }
    ADD_FAILURE() << "no error for " << s.paths.front();
    return data::Error(data::ErrorKind::InvalidArgument, "");
}

// The error a reader throws for the selection; a test failure when it reads without one.
template <typename Reader>
data::Error errorFrom(const data::DataSelection& chosen) {
    try {
        (void)Reader().read(chosen, {}, {});
    } catch (const data::Error& e) {
        return e;
    }
    ADD_FAILURE() << "reading succeeded";
    return data::Error(data::ErrorKind::InvalidArgument, "");
}

inline bool contains(const data::Error& e, const std::string& text) {
    return std::string(e.what()).find(text) != std::string::npos;
}

}  // namespace ensil::test
