#include "workbench/isovalue_session.h"

#include <QElapsedTimer>
#include <functional>
#include <numeric>
#include <utility>

#include "engine/isovalue_job.h"
#include "engine/streamed_isovalue_job.h"
#include "preprocessing/preview_meshes.h"
#include "session/session_state.h"
#include "workbench/member_selection.h"
#include "workbench/surface_display.h"

namespace ensil::workbench {

IsovalueSession::IsovalueSession(SurfaceDisplay* display, MemberSelection* selection,
                                 QString cacheDirectory, QObject* parent)
    : QObject(parent),
      m_display(display),
      m_selection(selection),
      m_cacheDirectory(std::move(cacheDirectory)) {
    m_previewThread.setMaxThreadCount(1);  // one preview runs at a time anyway
}

QStringList IsovalueSession::memberNames() const {
    QStringList names;
    for (std::size_t m = 0; m < m_ensemble->memberCount(); ++m) {
        const std::string& name = m_ensemble->members[m].name;
        names << (name.empty() ? tr("member %1").arg(m + 1) : QString::fromStdString(name));
    }
    return names;
}

void IsovalueSession::setEnsemble(std::shared_ptr<const data::Ensemble> ensemble,
                                  std::shared_ptr<const prep::EnsembleMoments> moments,
                                  std::string sourceKey,
                                  std::shared_ptr<const engine::StreamedSource> streamed) {
    setTimeStep(std::move(ensemble), std::move(moments), std::move(sourceKey), std::move(streamed));
    m_prepareJob.cancel();  // a step of other data
    m_kept.clear();         // other data
    m_result.reset();
    m_display->setSurfaces(nullptr);
    // The members are known now; their figures and clusters come with the first isovalue.
    MemberFigures names;
    names.names = memberNames();
    m_selection->setMembers(std::move(names));
    m_selection->setTree({});  // the same names may belong to other data
    m_selection->setClusterCount(
        session::defaultClusters(static_cast<int>(m_ensemble->memberCount())));
    m_display->requestRepaint();
}

void IsovalueSession::setTimeStep(std::shared_ptr<const data::Ensemble> ensemble,
                                  std::shared_ptr<const prep::EnsembleMoments> moments,
                                  std::string sourceKey,
                                  std::shared_ptr<const engine::StreamedSource> streamed) {
    // A step prepared ahead goes on: it may be this one (setIsovalue then waits for it). So
    // do the motion meshes of the step left, for its return (attachMotionMeshes keeps them):
    // the step opened first gets its own only after its first frame, and without them its
    // first frame when visited again drew the full meshes (100 ms of software OpenGL, not 40).
    m_job.cancel();
    m_awaitingPrepared = false;
    forgetPreviews();
    m_streamed = std::move(streamed);
    m_ensemble = std::move(ensemble);
    m_moments = std::move(moments);
    m_sourceKey = std::move(sourceKey);
}

namespace {

// One isovalue's surfaces, figures and clusters for one step's data: the work of a job.
IsovalueResult buildResult(const engine::IsovalueJobInput& input,
                           const engine::StreamedSource* streamed, const std::stop_token& stop,
                           const data::Progress& progress) {
    QElapsedTimer timer;
    timer.start();
    engine::IsovalueOutcome outcome =
        streamed ? engine::runStreamedIsovalueJob(input, *streamed, stop, progress)
                 : engine::runIsovalueJob(input, stop, progress);
    IsovalueResult r;
    r.fromCache = outcome.fromCache;
    r.triangles = outcome.meshes.triangles;
    r.meshes = std::make_shared<data::MeshSet>(std::move(outcome.meshes));
    r.contextSurfaces = input.context == prep::ContextParts::FiguresAndSurfaces;
    r.distances = std::move(outcome.distances);
    r.tree = std::move(outcome.tree);
    r.distancesToMean = std::move(outcome.distancesToMean);
    r.exceedanceColumnMaximum = std::move(outcome.exceedanceColumnMaximum);
    r.exceedance = std::move(outcome.exceedance);
    r.meanOutlyingness = std::move(outcome.meanOutlyingness);
    r.depth = std::move(outcome.boxplot.depth);
    if (!r.depth.empty()) r.medianMember = static_cast<int>(outcome.boxplot.median);
    r.outliers.assign(outcome.boxplot.outliers.begin(), outcome.boxplot.outliers.end());
    r.seconds = static_cast<double>(timer.nsecsElapsed()) * 1e-9;
    return r;
}

}  // namespace

void IsovalueSession::setIsovalue(float isovalue, float exaggeration) {
    if (!m_ensemble) return;
    const auto ensemble = m_ensemble;
    const auto moments = m_moments;
    const auto streamed = m_streamed;
    emit started(
        m_streamed
            ? tr("Building the isosurfaces at %1 from the whole data, in slabs...").arg(isovalue)
            : tr("Building the isosurfaces at %1...").arg(isovalue));
    // The full surfaces take over from a preview: none is built or waits any more.
    m_previewJob.cancel();
    m_pendingPreview.reset();
    // A result kept from before (a time step or isovalue visited again) is shown as it was,
    // through the same job so that a newer request still drops it.
    const std::string key = keptKey(isovalue, exaggeration);
    const std::shared_ptr<const IsovalueResult> kept = this->kept(key);
    m_awaitingPrepared = false;
    if (!kept && m_prepareJob.isRunning() && m_preparingKey == key) {
        // This step is being prepared ahead: its build is what is shown when done.
        m_job.cancel();
        m_buildInFlight = true;
        m_awaitingPrepared = true;
        m_awaitedIsovalue = isovalue;
        m_awaitedExaggeration = exaggeration;
        return;
    }
    m_prepareJob.cancel();  // a guess the user did not follow: its cores are wanted here
    if (m_motionSourceKey == m_sourceKey) m_motionJob.cancel();  // not a step left's
    engine::IsovalueJobInput input = jobInput(m_sourceKey, isovalue, exaggeration);
    m_buildInFlight = true;
    m_job.start(
        [=](const std::stop_token& stop, const data::Progress& progress) mutable {
            if (kept) {
                IsovalueResult r = *kept;
                r.keptInMemory = true;
                r.seconds = 0.0;
                return r;
            }
            input.ensemble = ensemble.get();
            input.moments = moments.get();
            return buildResult(input, streamed.get(), stop, progress);
        },
        [this, isovalue, exaggeration, key](IsovalueResult r) {
            m_buildInFlight = false;
            if (!r.keptInMemory) keep(key, r);
            show(std::move(r), isovalue, exaggeration, key);
        },
        [this](const std::exception_ptr& error, bool cancelled) {
            if (m_awaitingPrepared) return;  // given up for the step prepared ahead
            m_buildInFlight = false;
            reportFailure(error, cancelled);
        },
        [this](double f) { emit progressed(f); });
}

void IsovalueSession::prepareTimeStep(std::shared_ptr<const data::Ensemble> ensemble,
                                      std::shared_ptr<const prep::EnsembleMoments> moments,
                                      std::string sourceKey, float isovalue, float exaggeration) {
    if (!ensemble || !moments) return;
    const std::string key = keyOf(sourceKey, isovalue, exaggeration);
    if (kept(key) || (m_prepareJob.isRunning() && m_preparingKey == key)) return;
    if (m_awaitingPrepared) return;  // the step shown is still waiting for the last one
    engine::IsovalueJobInput input = jobInput(std::move(sourceKey), isovalue, exaggeration);
    m_preparingKey = key;
    m_prepareJob.start(
        [=](const std::stop_token& stop, const data::Progress& progress) mutable {
            input.ensemble = ensemble.get();
            input.moments = moments.get();
            IsovalueResult r = buildResult(input, nullptr, stop, progress);
            // Its motion meshes too: its first frame, a motion frame, is drawn from them.
            r.motionMeshes = previewWork(ensemble, moments, input.options.isovalue,
                                         input.verticalExaggeration, -1, {})(stop, {})
                                 .meshes;
            return r;
        },
        // When the step is waited for, showing it is the last thing done: what that sets off
        // (the next step read and prepared ahead) replaces these functions while they run.
        [this, key](IsovalueResult r) {
            keep(key, r);
            if (!std::exchange(m_awaitingPrepared, false)) {
                emit preparationEnded();
                return;
            }
            m_buildInFlight = false;
            show(std::move(r), m_awaitedIsovalue, m_awaitedExaggeration, key);
        },
        [this](const std::exception_ptr& error, bool cancelled) {
            // A guess that failed says nothing, unless the user is waiting for it.
            if (!std::exchange(m_awaitingPrepared, false)) {
                emit preparationEnded();
                return;
            }
            m_buildInFlight = false;
            reportFailure(error, cancelled);
        },
        [this](double f) {
            if (m_awaitingPrepared) emit progressed(f);
        });
}

BackgroundJob<IsovalueSession::BuiltPreview>::Work IsovalueSession::previewWork(
    std::shared_ptr<const data::Ensemble> ensemble,
    std::shared_ptr<const prep::EnsembleMoments> moments, float isovalue, float exaggeration,
    int median, std::vector<int> outliers) {
    return [=](const std::stop_token& stop, const data::Progress&) {
        QElapsedTimer timer;
        timer.start();
        auto meshes = std::make_shared<prep::IsovalueMeshes>(prep::buildPreviewMeshes(
            *ensemble, *moments, data::DisplayFrame(ensemble->grid, exaggeration), isovalue, {},
            stop));
        meshes->median = median;
        meshes->outliers = outliers;
        return BuiltPreview{std::move(meshes), static_cast<double>(timer.nsecsElapsed()) * 1e-9};
    };
}

void IsovalueSession::buildMotionMeshes(const std::string& key, float exaggeration) {
    if (!m_ensemble || !m_moments || !m_result || !m_result->meshes) return;
    const auto shown = m_result->meshes;
    // The preview of this very isovalue and step (the scrub's last, or the step's) serves as it
    // is; otherwise it is built. The renderer takes the median and outliers from the full
    // meshes, so the motion meshes need none.
    if (auto preview = keptPreview(key)) return attachMotionMeshes(key, shown, std::move(preview));
    m_motionSourceKey = m_sourceKey;
    m_motionJob.start(
        previewWork(m_ensemble, m_moments, shown->isovalue, exaggeration, -1, {}),
        [this, key, shown](BuiltPreview built) {
            attachMotionMeshes(key, shown, std::move(built.meshes));
        },
        // None: the full meshes are drawn in motion.
        [](const std::exception_ptr&, bool) {});
}

void IsovalueSession::attachMotionMeshes(const std::string& key,
                                         const std::shared_ptr<const data::MeshSet>& shown,
                                         std::shared_ptr<const data::MeshSet> motion) {
    // Kept with the result, also when another is shown now (a time step left), for its return.
    changeKept(key, shown, [&motion](IsovalueResult& kept) { kept.motionMeshes = motion; });
    if (!m_result || m_result->meshes != shown) return;  // another result meanwhile
    m_result->motionMeshes = motion;
    if (m_display->surfaces() == shown) m_display->setMotionSurfaces(std::move(motion));
}

std::shared_ptr<const data::MeshSet> IsovalueSession::keptPreview(const std::string& key) const {
    for (const auto& [previewKey, meshes] : m_keptPreviews) {
        if (previewKey == key) return meshes;
    }
    return nullptr;
}

void IsovalueSession::keepPreview(const std::string& key,
                                  std::shared_ptr<const data::MeshSet> meshes) {
    std::erase_if(m_keptPreviews, [&key](const auto& entry) { return entry.first == key; });
    m_keptPreviews.emplace(m_keptPreviews.begin(), key, std::move(meshes));
    if (m_keptPreviews.size() > kKeptPreviews) m_keptPreviews.resize(kKeptPreviews);
}

void IsovalueSession::previewTimeStep(float isovalue, float exaggeration) {
    if (!m_ensemble || !m_moments || !m_buildInFlight || m_awaitingPrepared || m_previewing) return;
    const auto ensemble = m_ensemble;
    const auto moments = m_moments;
    m_previewInFlight = true;
    m_previewJob.start(
        // No median or outliers of its own: the step's come with its full surfaces.
        previewWork(ensemble, moments, isovalue, exaggeration, -1, {}),
        [this, ensemble, isovalue, key = keptKey(isovalue, exaggeration)](BuiltPreview built) {
            m_previewInFlight = false;
            if (ensemble == m_ensemble) keepPreview(key, built.meshes);
            if (m_buildInFlight && !m_previewing && ensemble == m_ensemble) {
                m_stepPreviewShown = true;
                // Motion frames until the full surfaces (show) let the view settle.
                m_display->beginInteraction();
                m_display->setSurfaces(std::move(built.meshes));
                m_display->requestRepaint();
                emit previewShown(isovalue, built.seconds);
            }
            startWaitingPreview();  // a scrub begun meanwhile
        },
        [this](const std::exception_ptr&, bool) {
            m_previewInFlight = false;
            startWaitingPreview();
        });
}

void IsovalueSession::endStepPreview(bool settle) {
    if (!std::exchange(m_stepPreviewShown, false)) return;
    if (settle) {
        m_display->showPassingChange();  // one more motion frame, then full resolution
    } else {
        m_display->endInteraction();
    }
}

void IsovalueSession::cancel() {
    m_job.cancel();
    m_prepareJob.cancel();
    m_contextJob.cancel();
    m_contextFor.reset();
}

void IsovalueSession::changeKept(const std::string& key,
                                 const std::shared_ptr<const data::MeshSet>& meshes,
                                 const std::function<void(IsovalueResult&)>& change) {
    for (auto& [keptKey, kept] : m_kept) {
        if (keptKey != key || kept->meshes != meshes) continue;
        auto changed = std::make_shared<IsovalueResult>(*kept);  // kept results are shared
        change(*changed);
        kept = std::move(changed);
    }
}

void IsovalueSession::keep(const std::string& key, const IsovalueResult& result) {
    // The most recent first; the oldest go beyond kKeptResults.
    std::erase_if(m_kept, [&key](const auto& entry) { return entry.first == key; });
    m_kept.emplace(m_kept.begin(), key, std::make_shared<const IsovalueResult>(result));
    if (m_kept.size() > kKeptResults) m_kept.resize(kKeptResults);
}

void IsovalueSession::reportFailure(const std::exception_ptr& error, bool cancelled) {
    endStepPreview(false);
    if (cancelled || !error) {
        emit failed(tr("Isosurfaces cancelled"));
        return;
    }
    try {
        std::rethrow_exception(error);
    } catch (const std::exception& e) {
        emit failed(QString::fromStdString(e.what()));
    } catch (...) {
        emit failed(tr("unknown error"));
    }
}

engine::IsovalueJobInput IsovalueSession::jobInput(std::string sourceKey, float isovalue,
                                                   float exaggeration) const {
    engine::IsovalueJobInput input;
    input.options.isovalue = isovalue;
    input.verticalExaggeration = exaggeration;
    input.cacheDirectory = m_cacheDirectory.toStdString();
    input.sourceKey = std::move(sourceKey);
    input.linkage = m_linkage;
    input.context =
        m_contextWanted ? prep::ContextParts::FiguresAndSurfaces : prep::ContextParts::FiguresOnly;
    return input;
}

std::string IsovalueSession::keyOf(const std::string& sourceKey, float isovalue,
                                   float exaggeration) const {
    return sourceKey + "; iso=" + std::to_string(isovalue) +
           "; exaggeration=" + std::to_string(exaggeration) +
           "; linkage=" + std::to_string(static_cast<int>(m_linkage));
}

std::shared_ptr<const IsovalueResult> IsovalueSession::kept(const std::string& key) const {
    for (const auto& [keptKey, result] : m_kept) {
        if (keptKey == key) return result;
    }
    return nullptr;
}

bool IsovalueSession::showKept(float isovalue, float exaggeration) {
    const auto result = m_ensemble ? kept(keptKey(isovalue, exaggeration)) : nullptr;
    if (!result || isRunning()) return false;
    emit started(tr("Showing the isosurfaces at %1...").arg(isovalue));
    IsovalueResult r = *result;
    r.keptInMemory = true;
    r.seconds = 0.0;
    show(std::move(r), isovalue, exaggeration, keptKey(isovalue, exaggeration));
    return true;
}

void IsovalueSession::show(IsovalueResult result, float isovalue, float exaggeration,
                           const std::string& key) {
    endStepPreview(true);
    m_result = std::make_unique<IsovalueResult>(std::move(result));
    m_shownKey = key;
    m_shownExaggeration = exaggeration;
    // While the user scrubs, the view follows the pointer; endPreview shows these after.
    if (!m_previewing) {
        m_display->setSurfaces(m_result->meshes);
        m_display->setMotionSurfaces(m_result->motionMeshes);
    }
    // Motion meshes not built or kept with the result (as a step prepared ahead has them):
    if (auto preview = m_result->motionMeshes ? nullptr : keptPreview(key)) {
        // the preview of this very isovalue and step (a step never seen was on screen in it),
        // from the result's first frame on, a motion frame: drawing the full meshes there took
        // 60 to 110 ms of software OpenGL, the preview 40;
        attachMotionMeshes(key, m_result->meshes, std::move(preview));
    } else if (!m_result->motionMeshes) {
        // otherwise built after that frame, whose cores the build would take.
        // Not when another time step was asked for before that frame: the data at hand is
        // that step's (this result gets its motion meshes when visited again).
        const auto shown = m_result->meshes;
        m_display->afterNextFrame(this, [this, key, exaggeration, shown, source = m_sourceKey] {
            if (m_result && m_result->meshes == shown && m_sourceKey == source) {
                buildMotionMeshes(key, exaggeration);
            }
        });
    }
    addContextSurfacesIfWanted();
    // Same names: the selection keeps what the user selected and hid.
    MemberFigures figures;
    figures.names = memberNames();
    figures.distanceToMean = m_result->distancesToMean;
    figures.meanOutlyingness = m_result->meanOutlyingness;
    figures.depth = m_result->depth;
    figures.median = m_result->medianMember;
    figures.outliers = m_result->outliers;
    m_selection->setMembers(std::move(figures));
    m_selection->setTree(m_result->tree);
    // Members that could not be compared are said where the user looks after each rebuild.
    const std::string warning = prep::pairsWithoutOverlapWarning(*m_ensemble, m_result->distances);
    emit finished(tr("Isovalue %1: %2 triangles for %3 members and the mean, %4 s%5%6")
                      .arg(isovalue)
                      .arg(m_result->triangles)
                      .arg(m_result->meshes->members.size())
                      .arg(m_result->seconds, 0, 'f', 2)
                      .arg(m_result->keptInMemory ? tr(" (kept in memory)")
                           : m_result->fromCache  ? tr(" (from the cache)")
                                                  : QString())
                      .arg(warning.empty()
                               ? QString()
                               : tr(". Note: %1").arg(QString::fromStdString(warning))));
}

void IsovalueSession::setContextSurfacesWanted(bool wanted) {
    m_contextWanted = wanted;
    addContextSurfacesIfWanted();
}

void IsovalueSession::addContextSurfacesIfWanted() {
    if (!m_contextWanted || !m_result || m_result->contextSurfaces || !m_ensemble ||
        m_buildInFlight || m_contextFor == m_result->meshes) {
        return;
    }
    const auto shown = m_result->meshes;
    m_contextFor = shown;
    engine::IsovalueJobInput input = jobInput(m_sourceKey, shown->isovalue, m_shownExaggeration);
    input.context = prep::ContextParts::FiguresAndSurfaces;
    m_contextJob.start(
        [input, ensemble = m_ensemble, shown](const std::stop_token& stop,
                                              const data::Progress& progress) mutable {
            input.ensemble = ensemble.get();
            const prep::ContextSurfaces context = engine::buildContextOf(input, stop, progress);
            auto withContext = std::make_shared<data::MeshSet>(*shown);
            prep::addContextSurfaces(*withContext, context);
            return std::shared_ptr<const data::MeshSet>(std::move(withContext));
        },
        [this, shown, key = m_shownKey](std::shared_ptr<const data::MeshSet> withContext) {
            m_contextFor.reset();
            if (!m_result || m_result->meshes != shown) return;  // another result meanwhile
            const auto addContext = [&withContext](IsovalueResult& r) {
                r.meshes = withContext;
                r.contextSurfaces = true;
            };
            changeKept(key, shown, addContext);
            addContext(*m_result);
            if (m_display->surfaces() == shown) {
                m_display->setSurfaces(withContext);
                m_display->setMotionSurfaces(m_result->motionMeshes);
                m_display->requestRepaint();
            }
        },
        // A surface that could not be made is not drawn; the result stays as it is.
        [this](const std::exception_ptr&, bool) { m_contextFor.reset(); });
}

void IsovalueSession::forgetPreviews() {
    m_previewJob.cancel();
    m_pendingPreview.reset();
    m_keptPreviews.clear();
    m_previewsBuilt = 0;
}

void IsovalueSession::previewIsovalue(float isovalue, float exaggeration) {
    if (!m_ensemble || !m_moments) return;
    if (!m_previewing) {
        m_previewing = true;
        m_display->beginInteraction();  // frames at the resolution motion gets, see SilhouetteView
    }
    if (m_previewInFlight) {
        // The newest value replaces the one waiting: values the pointer passed are dropped.
        m_pendingPreview = PreviewRequest{isovalue, exaggeration};
        return;
    }
    startPreview(isovalue, exaggeration);
}

void IsovalueSession::startPreview(float isovalue, float exaggeration) {
    const std::string key = keptKey(isovalue, exaggeration);
    // Shown before, in full or as a preview: at once, from memory.
    if (const auto result = kept(key)) return showPreview(result->meshes, isovalue, 0.0);
    if (auto preview = keptPreview(key)) return showPreview(std::move(preview), isovalue, 0.0);
    // The median and outliers stay marked as the full result last said.
    const int median = m_result && m_result->meshes ? m_result->meshes->median : -1;
    const std::vector<int> outliers =
        m_result && m_result->meshes ? m_result->meshes->outliers : std::vector<int>{};
    m_previewInFlight = true;
    m_previewJob.start(
        previewWork(m_ensemble, m_moments, isovalue, exaggeration, median, outliers),
        [this, key, isovalue](BuiltPreview built) {
            m_previewInFlight = false;
            ++m_previewsBuilt;
            keepPreview(key, built.meshes);
            showPreview(std::move(built.meshes), isovalue, built.seconds);
        },
        // A preview overtaken by the full surfaces or a new ensemble is dropped; one that
        // fails says nothing (the full build on release reports the same problem).
        [this](const std::exception_ptr&, bool) {
            m_previewInFlight = false;
            startWaitingPreview();
        });
}

void IsovalueSession::showPreview(std::shared_ptr<const data::MeshSet> meshes, float isovalue,
                                  double seconds) {
    if (!m_previewing) return;  // the scrub ended while it was built
    m_display->setSurfaces(std::move(meshes));
    m_display->requestRepaint();
    emit previewShown(isovalue, seconds);
    startWaitingPreview();
}

void IsovalueSession::startWaitingPreview() {
    if (!m_pendingPreview || !m_previewing) return;
    const PreviewRequest next = *m_pendingPreview;
    m_pendingPreview.reset();
    startPreview(next.isovalue, next.verticalExaggeration);
}

void IsovalueSession::endPreview() {
    if (!m_previewing) return;
    m_previewing = false;
    m_previewJob.cancel();
    m_pendingPreview.reset();
    m_display->endInteraction();
    // Released where it started: the full surfaces of that value come back.
    if (!m_buildInFlight && m_result) {
        m_display->setSurfaces(m_result->meshes);
        m_display->setMotionSurfaces(m_result->motionMeshes);
        m_display->requestRepaint();
    }
}

std::vector<int> IsovalueSession::labels() const { return m_selection->labels(); }

void IsovalueSession::setClusterCount(int k) { m_selection->setClusterCount(k); }

void IsovalueSession::setLinkage(prep::Linkage linkage) {
    m_linkage = linkage;
    if (!m_result || m_result->distances.size == 0) return;
    // O(N^3) but about a millisecond for 200 members: no background job needed.
    m_result->tree = prep::clusterMembers(m_result->distances, m_linkage);
    m_selection->setTree(m_result->tree);
}

}  // namespace ensil::workbench
