#include "cli/preprocess_mpi.h"

#include <exception>

#include "cli/subcommand.h"
#include "data/error.h"
#include "engine/streaming_run.h"
#include "mpi/distributed_preprocess.h"
#include "mpi/mpi_session.h"

namespace ensil::cli {

bool runningUnderMpi() { return mpi::launchedByMpirun(); }

int runDistributedPreprocess(const data::DataSelection& selection,
                             const engine::PreprocessRequest& given,
                             std::optional<std::size_t> memoryLimit,
                             const std::function<void(engine::PreprocessResult&&)>& print,
                             QTextStream& err) {
    const mpi::Session session;
    const bool first = session.rank() == 0;
    const auto say = [&](const QString& text) {
        if (first) err << "ensil preprocess: " << text << "\n";
        err.flush();
    };
    const engine::PreprocessNotice notice = [&](const std::string& kind, const std::string& text) {
        say(QString::fromStdString(kind + ": " + text));
    };
    try {
        // Read from the headers alike on every rank: a failure here is every rank's, said once.
        const data::EnsembleDescription d = data::describeEnsemble(selection);
        if (!engine::canStream(selection)) {
            say(
                QStringLiteral("mpirun runs ensil preprocess on NetCDF files only (read in slabs "
                               "by every rank); convert the data to NetCDF"));
            return 1;
        }
        engine::PreprocessRequest request = given;
        request.sourceKey = data::sourceIdentity(selection);
        if (!first) request.cacheDirectory.reset();  // rank 0 writes the cache
        engine::StreamBackend backend;
        backend.where = "over " + std::to_string(session.size()) + " MPI ranks";
        backend.refinePlan = [&](const prep::StreamingPlan& plan) {
            return mpi::distributedPlan(plan, d);
        };
        backend.run = [&](const prep::StreamingPlan& plan, const prep::PipelineOptions& options,
                          const prep::RangeCheck& checkRange) {
            try {
                return mpi::distributedPreprocess(session, selection, d, plan, options, 1.0F,
                                                  checkRange);
            } catch (const engine::PreprocessRefused&) {
                throw;  // every rank refuses alike (the same range)
            } catch (const data::Error& e) {
                if (e.kind() == data::ErrorKind::AllValuesMissing) throw;  // every rank's
                session.abort(e.what(), 1);
            } catch (const std::exception& e) {
                session.abort(e.what(), 1);
            }
        };
        std::optional<engine::PreprocessResult> result = engine::preprocessStreamingWith(
            selection, d, request, memoryLimit.value_or(engine::defaultMemoryLimit()), notice,
            backend);
        if (result) print(std::move(*result));
        return 0;
    } catch (const engine::PreprocessRefused& e) {
        say(QString::fromUtf8(e.what()));
        return e.exitCode();
    } catch (const data::Error& e) {
        say(QString::fromUtf8(e.what()));
        return dataFailureStatus(e);
    }
}

}  // namespace ensil::cli
