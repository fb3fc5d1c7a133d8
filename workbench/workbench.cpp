#include "workbench/workbench.h"

#include <QFileInfo>
#include <algorithm>
#include <new>
#include <string>
#include <utility>

#include "data/error.h"
#include "engine/ensemble_overview.h"
#include "engine/session_renderer.h"
#include "engine/streaming_run.h"
#include "engine/workbench_reading.h"
#include "session/member_appearance.h"
#include "session/session_history.h"
#include "session/session_model.h"
#include "workbench/isovalue_session.h"
#include "workbench/member_selection.h"
#include "workbench/step_cluster_strip.h"
#include "workbench/time_steps.h"

namespace ensil::workbench {
namespace {

// The reader's typed error, if that is what the worker threw.
std::optional<data::Error> dataErrorOf(const std::exception_ptr& error) {
    try {
        std::rethrow_exception(error);  // unwrapped by BackgroundJob
    } catch (const data::Error& e) {
        return e;
    } catch (...) {
        return std::nullopt;
    }
}

}  // namespace

QString Workbench::messageOf(const std::exception_ptr& error) {
    try {
        std::rethrow_exception(error);  // unwrapped by BackgroundJob
    } catch (const std::bad_alloc&) {
        return tr("not enough memory to load the ensemble");
    } catch (const std::exception& e) {
        return QString::fromStdString(e.what());
    } catch (...) {
        return QStringLiteral("unknown error");
    }
}

Workbench::Workbench(SurfaceDisplay* display, const QString& cacheDirectory, QObject* parent)
    : QObject(parent),
      m_model(new session::SessionModel(this)),
      m_selection(new MemberSelection(m_model, this)),
      m_isovalue(new IsovalueSession(display, m_selection, cacheDirectory, this)),
      m_timeSteps(new TimeSteps(this)),
      m_strip(new StepClusterStrip(this)),
      m_history(new session::SessionHistory(
          [this] { return captureSession(); },
          [this](const session::SessionState& s) { applySession(s); }, this)) {
    m_isovalue->setContextSurfacesWanted(m_model->state().render.drawsContextSurfaces());
    // A project being opened is dropped when its surfaces cannot be built.
    connect(m_isovalue, &IsovalueSession::failed, this, [this] { m_pendingProject.reset(); });
    // The step shown gives the strip its clusters; the strip's filling waits while the next
    // step is built ahead.
    connect(m_selection, &MemberSelection::clustersChanged, m_strip,
            &StepClusterStrip::recordShown);
    connect(m_isovalue, &IsovalueSession::preparationEnded, m_strip, &StepClusterStrip::fill);
    connect(m_timeSteps, &TimeSteps::stepRead, this, &Workbench::showOrBuildStepRead);
}

Workbench::~Workbench() {
    // A worker must not outlive what it reports to.
    m_loader.cancel();
    m_loader.wait();
}

void Workbench::loadDemo(const data::DemoEnsembleParams& params) {
    m_requested.reset();
    m_requestedDemo = params;
    startOpening(
        tr("Generating the demo ensemble (%1 members, %2 x %3 x %4)...")
            .arg(params.members)
            .arg(params.nx)
            .arg(params.ny)
            .arg(params.nz),
        [params] { return engine::demoSourceKey(params); },
        [params](const std::stop_token& stop, const data::Progress& progress) {
            return engine::WorkbenchEnsemble{
                data::makeDemoEnsemble(params, stop, progress).ensemble, {}, {}};
        });
}

void Workbench::openFiles(const data::DataSelection& selection) {
    const QString name = selection.paths.size() == 1
                             ? QFileInfo(QString::fromStdString(selection.paths.front())).fileName()
                             : tr("%1 files").arg(selection.paths.size());
    m_requested = selection;
    m_requestedDemo.reset();
    startOpening(
        tr("Reading %1...").arg(name), [selection] { return data::sourceIdentity(selection); },
        [selection, limit = memoryLimit()](const std::stop_token& stop,
                                           const data::Progress& progress) {
            return engine::readForWorkbench(selection, limit, stop, progress);
        });
}

std::size_t Workbench::memoryLimit() const {
    return m_memoryLimit != 0 ? m_memoryLimit : engine::defaultMemoryLimit();
}

void Workbench::startOpening(const QString& what, std::function<std::string()> identify,
                             engine::WorkbenchRead read) {
    m_timeSteps->forget();  // other data: the steps read ahead are not its
    m_strip->forget();
    emit openingStarted(what);
    m_loader.start(
        [read = std::move(read), identify = std::move(identify)](const std::stop_token& stop,
                                                                 const data::Progress& progress) {
            return engine::readEnsembleOverview(read, identify, stop, progress);
        },
        [this](engine::EnsembleOverview overview) {
            m_overview = std::make_unique<engine::EnsembleOverview>(std::move(overview));
            m_historyStartsAfresh = true;
            if (!m_pendingProject) m_projectPath.clear();  // other data: no longer that project
            // The old data's surfaces, figures and clusters go; the new members are known.
            m_isovalue->setEnsemble(m_overview->ensemble, m_overview->moments,
                                    m_overview->sourceKey, m_overview->streamed);
            QStringList steps;
            for (const std::string& label : m_overview->ensemble->timeSteps.labels) {
                steps << QString::fromStdString(label);
            }
            m_strip->setSteps(steps);
            emit dataArrived();
        },
        [this](const std::exception_ptr& error, bool cancelled) { openingEnded(error, cancelled); },
        [this](double f) { emit progressed(f); });
}

void Workbench::cancel() {
    m_loader.cancel();
    m_isovalue->cancel();
}

void Workbench::openingEnded(const std::exception_ptr& error, bool cancelled) {
    if (cancelled || !error) {
        m_pendingProject.reset();  // a project whose data did not load is not applied
        emit openingCancelled();
        return;
    }
    // Many files hold one run over time or months: the user may say which dimension stands in
    // for members (and the project being opened waits for that answer).
    const auto dataError = dataErrorOf(error);
    if (dataError && dataError->kind() == data::ErrorKind::MemberDimensionNotFound &&
        !dataError->choices().empty() && m_requested) {
        QStringList choices;
        for (const auto& c : dataError->choices()) choices << QString::fromStdString(c);
        emit memberDimensionAsked(
            QFileInfo(QString::fromStdString(m_requested->paths.front())).fileName(), choices);
        return;
    }
    m_pendingProject.reset();
    emit openingFailed(messageOf(error));
}

void Workbench::startSessionOfNewData(float shownIsovalue) {
    const int members = static_cast<int>(m_overview->ensemble->memberCount());
    m_model->update([&](session::SessionState& s) {
        if (m_pendingProject) {
            s = *m_pendingProject;
            // Its members are shown once their surfaces are built (applyPendingProjectMembers).
            s.hiddenMembers.clear();
            s.hiddenClusters.clear();
            s.selection.clear();
        }
        s.demo = m_requestedDemo.has_value();
        s.demoParams = m_requestedDemo.value_or(data::DemoEnsembleParams{});
        s.data = m_requested.value_or(data::DataSelection{});
        if (!m_pendingProject || !s.isovalue) s.isovalue = shownIsovalue;
        s.clusters = m_pendingProject ? std::clamp(s.clusters, 1, members)
                                      : session::defaultClusters(members);
    });
}

void Workbench::buildFirstSurfaces() {
    const session::SessionState& s = m_model->state();
    m_isovalue->setIsovalue(*s.isovalue, s.verticalExaggeration);
}

void Workbench::openProject(session::SessionState project, const QString& path) {
    m_pendingProject = std::make_unique<session::SessionState>(std::move(project));
    m_pendingProjectPath = path;
    if (m_pendingProject->demo) {
        loadDemo(m_pendingProject->demoParams);
    } else {
        openFiles(m_pendingProject->data);
    }
}

session::SessionState Workbench::captureSession() const {
    session::SessionState p = m_model->state();
    if (m_isovalue->result() == nullptr) p.isovalue.reset();  // nothing built yet
    p.memberClusters = m_selection->memberClusterNumbers();
    if (m_viewCapture) m_viewCapture(p);
    return p;
}

void Workbench::applySession(const session::SessionState& state) {
    if (!m_overview) return;
    m_model->replace(state);  // the bindings show it
    emit sessionApplied(state);
}

void Workbench::surfacesShown() {
    applyPendingProjectMembers();
    if (std::exchange(m_historyStartsAfresh, false)) m_history->reset();
}

void Workbench::applyPendingProjectMembers() {
    if (!m_pendingProject) return;
    const session::SessionState p = *m_pendingProject;
    m_pendingProject.reset();
    // The clusters numbered and coloured as they were saved (hidden clusters below are by
    // label of the saved cut, which the same data and k give again).
    m_selection->numberClustersAs(p.memberClusters);
    // Hidden clusters are hidden by their members, now that the clusters are known.
    const session::MemberFlags flags =
        session::memberFlags(p, m_selection->labels(), m_selection->memberCount());
    m_model->update([&flags, &p](session::SessionState& s) {
        s.hiddenMembers.clear();
        for (std::size_t m = 0; m < flags.visible.size(); ++m) {
            if (!flags.visible[m]) s.hiddenMembers.push_back(static_cast<int>(m));
        }
        s.hiddenClusters.clear();
        s.selection = p.selection;
    });
    m_projectPath = m_pendingProjectPath;
    emit projectOpened(m_projectPath);
}

}  // namespace ensil::workbench
