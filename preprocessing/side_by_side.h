// Runs parts side by side on oneTBB's workers, each as it would run alone. Unlike a bare
// tbb::parallel_invoke, a part that throws does not cut the others short: oneTBB would cancel
// their inner parallel loops without a word, and those parts would carry on with half their
// results. Here each part's exception is kept, every part returns by itself (a stop asked for
// is seen at each part's own checks), and then the first exception, in part order, is rethrown.
// Where Qt is included too, include <tbb/parallel_invoke.h> before Qt (its `emit` macro clashes
// with oneTBB), as engine/isovalue_job.cpp does.
#pragma once

#include <tbb/parallel_invoke.h>

#include <array>
#include <exception>
#include <tuple>
#include <utility>

namespace ensil::prep {

template <typename... Parts>
void runSideBySide(Parts&&... parts) {
    std::array<std::exception_ptr, sizeof...(Parts)> failures{};
    auto all = std::forward_as_tuple(parts...);
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        tbb::parallel_invoke([&] {
            try {
                std::get<I>(all)();
            } catch (...) {
                failures[I] = std::current_exception();
            }
        }...);
    }
    (std::index_sequence_for<Parts...>{});
    for (const std::exception_ptr& failure : failures) {
        if (failure) std::rethrow_exception(failure);
    }
}

}  // namespace ensil::prep
