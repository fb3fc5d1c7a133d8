#include "engine/workbench_reading.h"

#include <cstdio>

#include "data/error.h"
#include "data/reader_support.h"
#include "data/thinned_ensemble.h"
#include "engine/streaming_run.h"

namespace ensil::engine {
namespace {

std::string ordinal(std::size_t n) {
    const std::size_t tens = n % 100;
    const char* suffix = (tens >= 11 && tens <= 13) ? "th"
                         : n % 10 == 1              ? "st"
                         : n % 10 == 2              ? "nd"
                         : n % 10 == 3              ? "rd"
                                                    : "th";
    return std::to_string(n) + suffix;
}

}  // namespace

std::string everyNthPoint(std::size_t stride) { return "every " + ordinal(stride) + " point"; }

std::optional<StreamedSource> streamedSourceFor(const data::DataSelection& selection,
                                                const data::EnsembleDescription& d,
                                                std::size_t memoryLimit) {
    if (inMemoryPeakBytes(d) <= memoryLimit || !canStream(selection)) return std::nullopt;
    StreamedSource source;
    source.selection = selection;
    source.description = d;
    source.memoryLimit = memoryLimit;
    const auto copyShare =
        static_cast<std::size_t>(kThinnedCopyShare * static_cast<double>(memoryLimit));
    // The copy's values are two thirds of its share: the workbench builds half as much again
    // from them (moments, statistics).
    source.stride = data::thinningStrideFor(d, copyShare / 3 * 2);
    if (source.stride == 0) {
        throw data::Error(data::ErrorKind::OutOfMemory,
                          "'" + d.variable + "' (" +
                              data::sizeText(static_cast<double>(d.bytes())) +
                              ") cannot be opened within the workbench's memory budget of " +
                              data::sizeText(static_cast<double>(memoryLimit)) +
                              ": not even a copy of its corner points fits a quarter of it");
    }
    // Planned now, so a budget too small for the slab passes is said before anything is read
    // (planStreaming names the least that would do).
    source.plan = prep::planStreaming(d, memoryLimit - copyShare, 0);
    return source;
}

WorkbenchEnsemble readForWorkbench(const data::DataSelection& selection, std::size_t memoryLimit,
                                   const std::stop_token& stop, const data::Progress& progress) {
    const data::EnsembleDescription d = data::describeEnsemble(selection);
    std::vector<std::string> variables;
    for (const data::VariableInfo& v : d.variables) {
        if (v.usable) variables.push_back(v.name);
    }
    std::optional<StreamedSource> source = streamedSourceFor(selection, d, memoryLimit);
    if (!source) {
        return {data::openEnsemble(selection, stop, progress), std::nullopt, std::move(variables)};
    }
    data::Ensemble copy =
        data::openThinnedEnsemble(selection, d, source->plan.slabs, source->stride, stop, progress);
    if (data::membersWithoutData(copy).size() == copy.members.size()) {
        throw data::Error(data::ErrorKind::AllValuesMissing,
                          "every value of '" + copy.variable + "' in " + copy.source + " read at " +
                              everyNthPoint(source->stride) +
                              " is missing (fill value or outside valid_range): there is "
                              "nothing to draw");
    }
    return {std::move(copy), std::move(source), std::move(variables)};
}

std::string howItOpens(const data::DataSelection& selection, const data::EnsembleDescription& d,
                       std::size_t memoryLimit) {
    const std::string values = data::sizeText(static_cast<double>(d.bytes())) + " of values";
    try {
        const std::optional<StreamedSource> source = streamedSourceFor(selection, d, memoryLimit);
        if (!source) return values;
        return values + ", more than the memory budget of " +
               data::sizeText(static_cast<double>(memoryLimit)) + ": read in slabs, a copy at " +
               everyNthPoint(source->stride) + " in memory";
    } catch (const std::exception& e) {
        return values + ": " + e.what();
    }
}

std::string streamedDataNote(const StreamedSource& source, const data::Ensemble& copy) {
    const data::EnsembleDescription& d = source.description;
    return "'" + d.variable + "' (" + data::sizeText(static_cast<double>(d.bytes())) +
           " of values) is larger than the workbench's memory budget of " +
           data::sizeText(static_cast<double>(source.memoryLimit)) +
           ": its surfaces, distances and clusters are built from the whole data, read in "
           "slabs; the statistics, histogram, floor, sections, contour boxplot and values under "
           "the cursor come from a copy at " +
           everyNthPoint(source.stride) + " (" + data::sizeText(static_cast<double>(copy.bytes())) +
           ")";
}

}  // namespace ensil::engine
