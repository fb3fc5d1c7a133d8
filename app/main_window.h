// The workbench window: the silhouette view in the centre, dock panels around it, menus with
// standard shortcuts, and the status bar that shows background work with a cancel button.
// Loading runs on a worker thread (QtConcurrent); results come back through QFutureWatcher's
// queued signals. Window layout is remembered with QSettings. GUI thread only.
#pragma once

#include <QMainWindow>
#include <functional>
#include <memory>
#include <optional>
#include <stop_token>

#include "app/background_job.h"
#include "app/ensemble_overview.h"
#include "data/demo_ensemble.h"
#include "data/ensemble_reader.h"
#include "data/error.h"

class QProgressBar;
class QToolButton;
class QLabel;
class QMenu;

namespace ensil::ui {
class SilhouetteView;
class EnsembleInfoPanel;
class RenderToolbar;
class MemberSelection;
class MemberTablePanel;
class ClusterPanel;
class DendrogramView;
}  // namespace ensil::ui

namespace ensil::app {

class IsovalueSession;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Start loading in the background; ensembleLoaded() or loadingFailed() follows. The
    // ensemble on screen stays until the new one is ready, and stays if loading fails.
    void loadDemo(const data::DemoEnsembleParams& params = {});
    void openFiles(const data::DataSelection& selection);
    void cancelLoading();

    [[nodiscard]] ui::SilhouetteView* view() const { return m_view; }
    [[nodiscard]] ui::EnsembleInfoPanel* infoPanel() const { return m_info; }
    [[nodiscard]] ui::RenderToolbar* renderToolbar() const { return m_toolbar; }
    [[nodiscard]] IsovalueSession* isovalueSession() const { return m_session; }
    [[nodiscard]] const EnsembleOverview* overview() const { return m_overview.get(); }
    [[nodiscard]] bool isLoading() const { return m_loader.isRunning(); }
    // Loading or building isosurfaces.
    [[nodiscard]] bool isBusy() const;

    // The shared selection model every panel and the view follow (main_window_panels.cpp).
    [[nodiscard]] ui::MemberSelection* memberSelection() const { return m_selection; }
    [[nodiscard]] ui::MemberTablePanel* memberTable() const { return m_memberTable; }
    [[nodiscard]] ui::ClusterPanel* clusterPanel() const { return m_clusterPanel; }
    [[nodiscard]] ui::DendrogramView* dendrogram() const { return m_dendrogram; }
    // Whether a window layout was saved by an earlier run (the first run starts maximised).
    [[nodiscard]] bool hasSavedLayout() const { return m_hasSavedLayout; }

    // Saves the view (without the UI) as an image; returns false with a message on failure.
    bool saveScreenshot(const QString& path, QString* error = nullptr);

public slots:
    // What the 3D view reports (ui::SilhouetteView's memberClicked, memberHovered and
    // membersBrushed): a click on a member (-1: the background; a plain click there clears),
    // the member under the pointer (-1: none), members inside a rubber band. Shift adds to the
    // selection, Ctrl toggles.
    void onMemberClicked(int member, Qt::KeyboardModifiers modifiers);
    void onMemberHovered(int member);
    void onMembersBrushed(const QList<int>& members, Qt::KeyboardModifiers modifiers);
    // Esc: stops the work in progress if there is any, otherwise clears the selection.
    void escape();

signals:
    void ensembleLoaded();
    void loadingFailed(const QString& message);

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    using EnsembleSource =
        std::function<data::Ensemble(const std::stop_token&, const data::Progress&)>;
    void startLoading(const QString& what, std::string sourceKey, EnsembleSource source);
    void createToolbar();
    void chooseFiles();
    void rememberRecent(const data::DataSelection& selection);
    void rebuildRecentMenu();
    void createMenus();
    void createDocks();
    void createStatusBar();
    // main_window_panels.cpp
    void createPanels();
    void arrangeDefaultLayout();
    void addExportActions(QMenu* file);
    void createEditMenu();
    void linkPanels();
    void showSelectionInView();
    void exportDendrogram();
    void exportMemberTable();
    void onLoadFailed(const std::exception_ptr& error, bool cancelled);
    void askForMemberDimension(const data::Error& error);
    void showOverview(std::unique_ptr<EnsembleOverview> overview);
    void setBusy(const QString& what);
    void setIdle(const QString& message);

    ui::SilhouetteView* m_view;
    ui::EnsembleInfoPanel* m_info = nullptr;
    QProgressBar* m_progress = nullptr;
    QToolButton* m_cancel = nullptr;
    QLabel* m_statusText = nullptr;
    QMenu* m_recentMenu = nullptr;
    ui::RenderToolbar* m_toolbar = nullptr;
    IsovalueSession* m_session = nullptr;
    ui::MemberSelection* m_selection = nullptr;
    ui::MemberTablePanel* m_memberTable = nullptr;
    ui::ClusterPanel* m_clusterPanel = nullptr;
    ui::DendrogramView* m_dendrogram = nullptr;
    bool m_hasSavedLayout = false;
    std::string m_loadingKey;  // identity of the data being loaded, for the mesh cache
    BackgroundJob<EnsembleOverview> m_loader{this};
    std::unique_ptr<EnsembleOverview> m_overview;
    std::optional<data::DataSelection> m_requested;  // files being opened, to retry with choices
};

}  // namespace ensil::app
