#include "mpi/distributed_preprocess.h"

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <cstdint>
#include <cstdlib>
#include <ctime>
#include <stdexcept>
#include <string>
#include <vector>

#include "data/display_frame.h"
#include "data/error.h"
#include "mpi/mesh_transfer.h"
#include "preprocessing/vertex_attributes.h"

namespace ensil::mpi {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// CPU seconds of this process (every thread): what a rank's own work costs, whatever else the
// machine runs.
double cpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

void check(int code, const char* what) {
    if (code == MPI_SUCCESS) return;
    char text[MPI_MAX_ERROR_STRING];
    int length = 0;
    MPI_Error_string(code, text, &length);
    throw std::runtime_error(std::string("MPI failed ") + what + ": " + std::string(text, length));
}

int countOf(std::size_t n, const char* what) {
    if (n > static_cast<std::size_t>(INT_MAX)) {
        throw std::runtime_error(std::string(what) + " is more than MPI sends in one message (" +
                                 std::to_string(n) + " elements)");
    }
    return static_cast<int>(n);
}

// Sums `values` over every rank, in place, in pieces MPI's int counts can say.
template <typename T>
void sumEverywhere(T* values, std::size_t n, MPI_Datatype type, const char* what) {
    constexpr std::size_t kPiece = std::size_t{1} << 28;
    for (std::size_t first = 0; first < n; first += kPiece) {
        const int count = static_cast<int>(std::min(kPiece, n - first));
        check(MPI_Allreduce(MPI_IN_PLACE, values + first, count, type, MPI_SUM, MPI_COMM_WORLD),
              what);
    }
}

void failIfAsked(int rank) {
    const char* asked = std::getenv("ENSIL_MPI_TEST_FAIL_RANK");
    if (asked != nullptr && std::to_string(rank) == asked) {
        throw data::Error(data::ErrorKind::CorruptFile,
                          "failing on purpose at the first slab (ENSIL_MPI_TEST_FAIL_RANK=" +
                              std::string(asked) + ")");
    }
}

// Pass 1 on this rank's slabs, then the reductions: every rank ends with the whole grid's
// moments, counts and range, and the distance sums merged in slab order.
prep::SlabSums sumSlabs(const Session& session, const data::DataSelection& selection,
                        const data::EnsembleDescription& d, const prep::StreamingPlan& plan,
                        float isovalue, double& workSeconds) {
    const auto K = static_cast<std::size_t>(session.size());
    const auto me = static_cast<std::size_t>(session.rank());
    const std::size_t layer = d.grid.nx() * d.grid.ny();
    prep::SlabSums sums = prep::emptySlabSums(d, isovalue);
    failIfAsked(session.rank());
    std::vector<double> mine;  // this rank's slabs' distance sums, one after another
    std::vector<char> owned(d.grid.nz(), 0);
    const double work = cpuSeconds();
    for (std::size_t s = me; s < plan.slabs.size(); s += K) {
        const data::EnsemblePart& slab = plan.slabs[s];
        const prep::DistanceSums part = prep::addSlab(sums, selection, d, slab);
        mine.insert(mine.end(), part.raw().begin(), part.raw().end());
        std::fill_n(owned.begin() + static_cast<std::ptrdiff_t>(slab.firstLayer), slab.layerCount,
                    1);
    }
    workSeconds += cpuSeconds() - work;
    // Each layer's moments come from the one rank that read it: the others add zeros, so the
    // sum is that rank's value exactly (NaN + 0 stays NaN).
    for (std::size_t z = 0; z < owned.size(); ++z) {
        if (owned[z] != 0) continue;
        const auto first = static_cast<std::ptrdiff_t>(z * layer);
        std::fill_n(sums.moments.mean.values.begin() + first, layer, 0.0F);
        std::fill_n(sums.moments.variance.begin() + first, layer, 0.0F);
    }
    sumEverywhere(sums.moments.mean.values.data(), sums.moments.mean.values.size(), MPI_FLOAT,
                  "summing the mean member");
    sumEverywhere(sums.moments.variance.data(), sums.moments.variance.size(), MPI_FLOAT,
                  "summing the variance");
    sumEverywhere(sums.validValues.data(), sums.validValues.size(), MPI_DOUBLE,
                  "summing the members' valid values");
    sumEverywhere(&sums.infiniteValues, 1, MPI_DOUBLE, "summing the infinite values");
    check(MPI_Allreduce(MPI_IN_PLACE, &sums.minimum, 1, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD),
          "finding the least value");
    check(MPI_Allreduce(MPI_IN_PLACE, &sums.maximum, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD),
          "finding the greatest value");

    // Every slab's distance sums to rank 0, merged there in slab order, then the total to all.
    const std::size_t rawSize = sums.distances.raw().size();
    std::vector<int> counts(K), offsets(K);
    std::size_t total = 0;
    for (std::size_t r = 0; r < K; ++r) {
        std::size_t slabs = 0;
        for (std::size_t s = r; s < plan.slabs.size(); s += K) ++slabs;
        counts[r] = countOf(slabs * rawSize, "a rank's distance sums");
        offsets[r] = countOf(total, "the distance sums of all slabs");
        total += slabs * rawSize;
    }
    std::vector<double> all(me == 0 ? total : 0);
    check(MPI_Gatherv(mine.data(), countOf(mine.size(), "this rank's distance sums"), MPI_DOUBLE,
                      all.data(), counts.data(), offsets.data(), MPI_DOUBLE, 0, MPI_COMM_WORLD),
          "gathering the distance sums");
    if (me == 0) {
        for (std::size_t s = 0; s < plan.slabs.size(); ++s) {
            prep::DistanceSums part(d.members, isovalue);
            const double* from =
                all.data() + static_cast<std::size_t>(offsets[s % K]) + (s / K) * rawSize;
            std::copy(from, from + rawSize, part.raw().begin());
            sums.distances.merge(part);
        }
    }
    check(MPI_Bcast(sums.distances.raw().data(), countOf(rawSize, "the distance sums"), MPI_DOUBLE,
                    0, MPI_COMM_WORLD),
          "sending the distance sums");
    return sums;
}

// Rank 0 receives every field's result in order; the others send theirs.
std::vector<prep::MemberResult> gatherMembers(const Session& session, std::size_t fields,
                                              std::vector<prep::MemberResult>&& mine) {
    const auto K = static_cast<std::size_t>(session.size());
    const auto me = static_cast<std::size_t>(session.rank());
    std::vector<prep::MemberResult> all;
    if (me != 0) {
        for (std::size_t j = 0; j < mine.size(); ++j) {
            const std::vector<char> bytes = serialiseMember(mine[j]);
            const auto size = static_cast<std::uint64_t>(bytes.size());
            const int tag = countOf(me + j * K, "a field's number");
            check(MPI_Send(&size, 1, MPI_UINT64_T, 0, tag, MPI_COMM_WORLD), "sending a mesh size");
            check(MPI_Send(bytes.data(), countOf(bytes.size(), "a member's mesh"), MPI_BYTE, 0, tag,
                           MPI_COMM_WORLD),
                  "sending a mesh");
        }
        return all;
    }
    all.resize(fields);
    for (std::size_t i = 0; i < fields; ++i) {
        const std::size_t owner = i % K;
        if (owner == 0) {
            all[i] = std::move(mine[i / K]);
            continue;
        }
        const int tag = countOf(i, "a field's number");
        std::uint64_t size = 0;
        check(MPI_Recv(&size, 1, MPI_UINT64_T, static_cast<int>(owner), tag, MPI_COMM_WORLD,
                       MPI_STATUS_IGNORE),
              "receiving a mesh size");
        std::vector<char> bytes(size);
        check(MPI_Recv(bytes.data(), countOf(bytes.size(), "a member's mesh"), MPI_BYTE,
                       static_cast<int>(owner), tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE),
              "receiving a mesh");
        all[i] = deserialiseMember(bytes);
    }
    return all;
}

}  // namespace

prep::StreamingPlan distributedPlan(const prep::StreamingPlan& plan,
                                    const data::EnsembleDescription& description) {
    constexpr std::size_t kSlabs = 16;
    prep::StreamingPlan out = plan;
    const std::size_t wanted =
        std::max(plan.slabs.size(), std::min(kSlabs, description.grid.nz() / 2));
    out.slabs = prep::evenSlabs(description, wanted);
    return out;
}

std::optional<prep::StreamedEnsemble> distributedPreprocess(const Session& session,
                                                            const data::DataSelection& selection,
                                                            const data::EnsembleDescription& d,
                                                            const prep::StreamingPlan& plan,
                                                            const prep::PipelineOptions& options,
                                                            float verticalExaggeration,
                                                            const prep::RangeCheck& checkRange) {
    const auto K = static_cast<std::size_t>(session.size());
    const auto me = static_cast<std::size_t>(session.rank());
    prep::StreamedEnsemble out;
    out.plan = plan;
    out.meshes.isovalue = options.isovalue;
    auto start = Clock::now();
    double work = 0.0;
    const prep::SlabSums sums = sumSlabs(session, selection, d, plan, options.isovalue, work);
    out.slabSeconds = since(start);
    // The same sums on every rank: the same members kept and the same checks.
    const std::vector<std::size_t> keep = prep::concludeSlabs(sums, selection, d, checkRange, out);

    start = Clock::now();
    std::vector<std::size_t> fields = keep;
    fields.push_back(prep::kMeanMember);
    std::vector<std::size_t> mine;
    for (std::size_t i = me; i < fields.size(); i += K) mine.push_back(fields[i]);
    const prep::AxisTables axes =
        prep::axisTables(data::DisplayFrame(d.grid, verticalExaggeration));
    const double meshing = cpuSeconds();
    std::vector<prep::MemberResult> results =
        prep::meshMembers(selection, d, mine, sums.moments, axes, options, plan.membersAtOnce);
    work += cpuSeconds() - meshing;
    out.rankWorkSeconds.assign(me == 0 ? K : 0, 0.0);
    check(MPI_Gather(&work, 1, MPI_DOUBLE, out.rankWorkSeconds.data(), 1, MPI_DOUBLE, 0,
                     MPI_COMM_WORLD),
          "gathering the ranks' times");
    std::vector<prep::MemberResult> all = gatherMembers(session, fields.size(), std::move(results));
    if (me != 0) return std::nullopt;
    prep::collectMembers(out, std::move(all), since(start));
    return out;
}

}  // namespace ensil::mpi
