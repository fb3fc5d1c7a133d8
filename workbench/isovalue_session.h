// Keeps the view's isosurfaces in step with the chosen isovalue: for each new isovalue it runs
// one background job (meshes through the disk cache, similarity matrix, clustering, each
// member's distance to the mean and mean outlyingness, the contour boxplot's depths, median and
// outliers) and, when it is done, hands the meshes to the display and the members, their
// figures and the merge tree to the shared MemberSelection (which colours the view and feeds
// the panels; see MainWindow). The previous isovalue stays on screen until the new one is
// ready; a newer request drops an older result. The number of clusters and the linkage change
// at once from the kept distances.
// While the isovalue is scrubbed (the slider dragged), previewIsovalue shows reduced-detail
// surfaces (preprocessing/preview_meshes.h) for the value under the pointer: one preview is
// built at a time and at most one value waits, the newest, so the view follows the pointer
// and never lags behind a queue; the members keep their cluster colours meanwhile. The full
// result of the value released replaces the preview. GUI thread only.
#pragma once

#include <QObject>
#include <QThreadPool>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "data/ensemble.h"
#include "data/packed_mesh.h"
#include "engine/isovalue_job.h"
#include "engine/workbench_reading.h"
#include "preprocessing/clustering.h"
#include "preprocessing/ensemble_moments.h"
#include "preprocessing/similarity.h"
#include "workbench/background_job.h"

namespace ensil::workbench {

class MemberSelection;
class SurfaceDisplay;

struct IsovalueResult {
    std::shared_ptr<const data::MeshSet> meshes;
    prep::DistanceMatrix distances;
    prep::MergeTree tree;
    std::vector<double> distancesToMean;   // per member, in the similarity measure
    std::vector<double> meanOutlyingness;  // per member, over its isosurface's vertices
    // The contour boxplot (preprocessing/inclusion_depth.h), without its band fields (their
    // surfaces are in `meshes`): the inclusion depth per member, the median, the outliers.
    std::vector<double> depth;
    int medianMember = -1;
    std::vector<int> outliers;
    std::vector<float> exceedanceColumnMaximum;           // for the floor: max over z of P(f > c)
    std::shared_ptr<const data::FieldValues> exceedance;  // P(f > c), for a section
    // The members and mean in reduced detail, drawn while the view moves
    // (gl::Renderer::setMotionMeshes); built after the result is shown, or with a step built
    // ahead. Null until then.
    std::shared_ptr<const data::MeshSet> motionMeshes;
    // Whether `meshes` holds the context surfaces (P = 0.5, the 50 % band): made only while
    // the view draws them (IsovalueSession::setContextSurfacesWanted).
    bool contextSurfaces = false;
    std::size_t triangles = 0;
    double seconds = 0.0;
    bool fromCache = false;
    bool keptInMemory = false;  // shown again as built before (IsovalueSession::kKeptResults)
};

class IsovalueSession : public QObject {
    Q_OBJECT
public:
    // The display and the selection outlive the session (all are the workbench's).
    IsovalueSession(SurfaceDisplay* display, MemberSelection* selection, QString cacheDirectory,
                    QObject* parent = nullptr);

    // A new ensemble: forgets the old meshes. sourceKey identifies the data for the cache.
    // With `streamed`, `ensemble` and `moments` are a thinned copy's and each isovalue's
    // surfaces come from the whole data read in slabs (engine/streamed_isovalue_job.h).
    void setEnsemble(std::shared_ptr<const data::Ensemble> ensemble,
                     std::shared_ptr<const prep::EnsembleMoments> moments, std::string sourceKey,
                     std::shared_ptr<const engine::StreamedSource> streamed = nullptr);
    // Another time step of the same members: the last step's surfaces, figures and clusters
    // stay on screen until setIsovalue's are built, and its clusters are what the new ones are
    // matched to (MemberSelection), so colours follow groups across steps.
    void setTimeStep(std::shared_ptr<const data::Ensemble> ensemble,
                     std::shared_ptr<const prep::EnsembleMoments> moments, std::string sourceKey,
                     std::shared_ptr<const engine::StreamedSource> streamed = nullptr);
    // Builds (or reads from the cache) this isovalue's surfaces, their attributes taken in the
    // display space of this vertical exaggeration.
    void setIsovalue(float isovalue, float verticalExaggeration);
    // A time step visited again: this isovalue's result for the data now set, kept
    // (kKeptResults), shown at once on the GUI thread instead of through a job (a job runs at
    // the workers' low priority and may wait for a core while the window draws another frame
    // of the last step). False, doing nothing, when none is kept or a job is under way; then
    // setIsovalue.
    bool showKept(float isovalue, float verticalExaggeration);
    // Another time step's result built ahead, in the background, while the user looks at this
    // one (MainWindow reads the next step ahead and hands it here): kept (kKeptResults) but not
    // shown, so that stepping there shows it at once (showKept). When that step is asked for
    // while its result is still being built, setIsovalue waits for this build instead of
    // starting another. A newer preparation, another isovalue, cancel() or other data drop it.
    void prepareTimeStep(std::shared_ptr<const data::Ensemble> ensemble,
                         std::shared_ptr<const prep::EnsembleMoments> moments,
                         std::string sourceKey, float isovalue, float verticalExaggeration);
    // A time step never seen: its reduced-detail surfaces (preprocessing/preview_meshes.h),
    // built in a fraction of the full ones' time, shown while those are built (setIsovalue,
    // called before) as motion frames, with no clusters of their own (the members keep their
    // colours). The full surfaces replace them; nothing is shown when they come first.
    void previewTimeStep(float isovalue, float verticalExaggeration);
    [[nodiscard]] bool isPreparing() const { return m_prepareJob.isRunning(); }
    // The surfaces asked for are those being prepared ahead, and are waited for.
    [[nodiscard]] bool awaitsPreparedStep() const { return m_awaitingPrepared; }
    // Whether the view draws the context surfaces (gl::RenderSettings::drawsContextSurfaces).
    // The jobs make their meshes only then (on the demo 120 ms of a core of every new
    // isovalue or time step, for surfaces drawn only on request), and a result shown without
    // them gets them in the background once they are wanted.
    void setContextSurfacesWanted(bool wanted);
    void setClusterCount(int k);
    // Clusters the current distances again (at once) and uses this linkage from now on.
    void setLinkage(prep::Linkage linkage);
    [[nodiscard]] prep::Linkage linkage() const { return m_linkage; }
    void cancel();

    // Shows this isovalue's preview surfaces as soon as they can be built (see above).
    void previewIsovalue(float isovalue, float verticalExaggeration);
    // The scrub is over: a waiting value is dropped. The preview stays on screen while the
    // released value's full surfaces are built (setIsovalue, called before this), else the
    // full surfaces shown before come back.
    void endPreview();
    // 0 or 1: the value waiting for the preview being built.
    [[nodiscard]] int pendingPreviews() const { return m_pendingPreview ? 1 : 0; }
    [[nodiscard]] bool isPreviewing() const { return m_previewing; }
    // Previews built since the ensemble was set (not those shown again from memory).
    [[nodiscard]] int previewsBuilt() const { return m_previewsBuilt; }

    [[nodiscard]] const IsovalueResult* result() const { return m_result.get(); }
    [[nodiscard]] std::vector<int> labels() const;
    // The surfaces asked for are being built (or prepared ahead, and waited for).
    [[nodiscard]] bool isRunning() const { return m_job.isRunning() || m_awaitingPrepared; }

    // The last results built, kept whole (meshes, distances, clusters, summaries) so that a
    // time step or isovalue visited again is shown without rebuilding: a few MiB each.
    static constexpr std::size_t kKeptResults = 24;
    // Previews kept for a scrub back over the same values: about 0.5 MiB each.
    static constexpr std::size_t kKeptPreviews = 32;

signals:
    void started(const QString& what);
    void progressed(double fraction);
    void finished(const QString& summary);
    void failed(const QString& message);
    // A time step's result prepared ahead is kept (prepareTimeStep), or its build ended,
    // while no one waited for it (a step waited for says finished or failed instead).
    void preparationEnded();
    // A preview is on screen (handed to the view, which repaints); seconds to build it.
    void previewShown(float isovalue, double seconds);

private:
    // Shows the result kept (or to keep) under `key`, and builds its motion meshes if it has
    // none.
    void show(IsovalueResult result, float isovalue, float verticalExaggeration,
              const std::string& key);
    void buildMotionMeshes(const std::string& key, float verticalExaggeration);
    // The result showing `shown` (kept under `key`) gets these motion meshes, on screen too.
    void attachMotionMeshes(const std::string& key,
                            const std::shared_ptr<const data::MeshSet>& shown,
                            std::shared_ptr<const data::MeshSet> motion);
    // Makes the context surfaces of the result shown when they are wanted and it has none
    // (not while another result is on its way: it gets them when shown).
    void addContextSurfacesIfWanted();
    [[nodiscard]] std::shared_ptr<const data::MeshSet> keptPreview(const std::string& key) const;
    void keepPreview(const std::string& key, std::shared_ptr<const data::MeshSet> meshes);
    // A job's input for this data, isovalue and exaggeration (its ensemble and moments not set).
    [[nodiscard]] engine::IsovalueJobInput jobInput(std::string sourceKey, float isovalue,
                                                    float verticalExaggeration) const;
    void startPreview(float isovalue, float verticalExaggeration);
    void startWaitingPreview();
    void showPreview(std::shared_ptr<const data::MeshSet> meshes, float isovalue, double seconds);
    void forgetPreviews();
    void keep(const std::string& key, const IsovalueResult& result);
    // Applies `change` to a copy of the result kept under `key` that shows `meshes` (if any),
    // which replaces it.
    void changeKept(const std::string& key, const std::shared_ptr<const data::MeshSet>& meshes,
                    const std::function<void(IsovalueResult&)>& change);
    void reportFailure(const std::exception_ptr& error, bool cancelled);
    // A step's preview gives way: to the full surfaces (settle: the view's motion ends as after
    // a passing change), or to nothing (a failure or cancel: it ends now).
    void endStepPreview(bool settle);
    // The key of a kept result: the data, isovalue, exaggeration and linkage.
    [[nodiscard]] std::string keptKey(float isovalue, float verticalExaggeration) const {
        return keyOf(m_sourceKey, isovalue, verticalExaggeration);
    }
    [[nodiscard]] std::string keyOf(const std::string& sourceKey, float isovalue,
                                    float verticalExaggeration) const;
    [[nodiscard]] std::shared_ptr<const IsovalueResult> kept(const std::string& key) const;
    std::vector<std::pair<std::string, std::shared_ptr<const IsovalueResult>>> m_kept;
    [[nodiscard]] QStringList memberNames() const;

    SurfaceDisplay* m_display;
    MemberSelection* m_selection;
    QString m_cacheDirectory;
    std::shared_ptr<const data::Ensemble> m_ensemble;
    std::shared_ptr<const prep::EnsembleMoments> m_moments;
    std::string m_sourceKey;
    std::shared_ptr<const engine::StreamedSource> m_streamed;
    std::unique_ptr<IsovalueResult> m_result;
    // The result shown: its key and display exaggeration, for the context surfaces made later.
    std::string m_shownKey;
    float m_shownExaggeration = 1.0F;
    bool m_contextWanted = true;
    BackgroundJob<std::shared_ptr<const data::MeshSet>> m_contextJob{this};
    std::string m_motionSourceKey;  // the data of the result m_motionJob builds for
    std::shared_ptr<const data::MeshSet> m_contextFor;  // the meshes m_contextJob completes
    prep::Linkage m_linkage = prep::Linkage::Average;
    BackgroundJob<IsovalueResult> m_job{this};
    // The step prepared ahead: its key, and whether the surfaces asked for are that build's.
    BackgroundJob<IsovalueResult> m_prepareJob{this};
    std::string m_preparingKey;
    bool m_awaitingPrepared = false;
    float m_awaitedIsovalue = 0.0F;
    float m_awaitedExaggeration = 1.0F;

    struct PreviewRequest {
        float isovalue = 0.0F;
        float verticalExaggeration = 1.0F;
    };
    struct BuiltPreview {
        std::shared_ptr<const data::MeshSet> meshes;
        double seconds = 0.0;
    };
    // A preview's work: its meshes marked with this median and these outliers.
    static BackgroundJob<BuiltPreview>::Work previewWork(
        std::shared_ptr<const data::Ensemble> ensemble,
        std::shared_ptr<const prep::EnsembleMoments> moments, float isovalue, float exaggeration,
        int median, std::vector<int> outliers);
    // Previews have a thread of their own: on the jobs' pool (a thread a core) one would wait
    // while a full build and a time step's motion meshes, or the reading ahead, held every
    // thread, and a step never seen could then reach full detail with no preview first.
    QThreadPool m_previewThread;
    BackgroundJob<BuiltPreview> m_previewJob{this, BackgroundJob<BuiltPreview>::WhenDestroyed::Wait,
                                             &m_previewThread};
    // A result's motion meshes: the one shown, or that of a time step just left.
    BackgroundJob<BuiltPreview> m_motionJob{this};
    std::optional<PreviewRequest> m_pendingPreview;
    bool m_previewing = false;
    // A preview job started and not yet handed back (done or dropped): until then new values
    // wait. BackgroundJob::isRunning turns false before its result reaches the GUI thread.
    bool m_previewInFlight = false;
    bool m_buildInFlight = false;     // the same for the full surfaces' job
    bool m_stepPreviewShown = false;  // a step's preview on screen until its full surfaces
    int m_previewsBuilt = 0;
    std::vector<std::pair<std::string, std::shared_ptr<const data::MeshSet>>> m_keptPreviews;
};

}  // namespace ensil::workbench
