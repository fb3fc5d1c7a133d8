// File > Export: the surfaces for ParaView, MeshLab or Blender (engine/surface_export.h, in the
// background with progress and cancel), the dendrogram as SVG, the member table as CSV, and the
// view as a screenshot at any size. Part of MainWindow.
#include <QAction>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QImage>
#include <QInputDialog>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QProgressBar>
#include <QSettings>
#include <QStatusBar>
#include <cmath>

#include "app/main_window.h"
#include "engine/picture_title.h"
#include "widgets/csv_export.h"
#include "widgets/dendrogram_export.h"
#include "widgets/silhouette_view.h"
#include "workbench/isovalue_session.h"
#include "workbench/member_selection.h"

namespace ensil::app {
namespace {

// The file dialog's filters, one per format, in the order of engine::SurfaceFormat.
struct FormatFilter {
    engine::SurfaceFormat format;
    const char* filter;
};
constexpr FormatFilter kSurfaceFilters[] = {
    {engine::SurfaceFormat::Vtp, "ParaView, VTK multiblock (*.vtm)"},
    {engine::SurfaceFormat::Ply, "MeshLab, CloudCompare, Blender: PLY (*.ply)"},
    {engine::SurfaceFormat::Obj, "Wavefront OBJ (*.obj)"},
    {engine::SurfaceFormat::Stl, "STL (*.stl)"},
};

}  // namespace

void MainWindow::addExportActions(QMenu* file) {
    QAction* surfaces =
        file->addAction(tr("Export &Surfaces..."), this, &MainWindow::chooseSurfaceExport);
    surfaces->setObjectName(QStringLiteral("exportSurfacesAction"));
    surfaces->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_E));
    surfaces->setStatusTip(
        tr("The selected members' surfaces (else those shown), the mean's and the summary "
           "surfaces, for ParaView, MeshLab or Blender"));
    file->addAction(tr("Export &Dendrogram as SVG..."), this, &MainWindow::exportDendrogram);
    file->addAction(tr("Export &Member Table as CSV..."), this, &MainWindow::exportMemberTable);
}

void MainWindow::chooseSurfaceExport() {
    if (m_session == nullptr || m_session->result() == nullptr || overview() == nullptr) {
        QMessageBox::information(this, tr("No surfaces yet"),
                                 tr("Surfaces can be exported once an isovalue's have been made."));
        return;
    }
    QStringList filters;
    for (const FormatFilter& f : kSurfaceFilters) filters << tr(f.filter);
    QSettings settings;
    QString filter =
        settings.value(QStringLiteral("export/surfaceFilter"), filters.front()).toString();
    const QString suggested =
        QFileInfo(settings.value(QStringLiteral("export/surfaceFolder")).toString(),
                  QStringLiteral("%1_iso%2.vtm")
                      .arg(QString::fromStdString(overview()->ensemble->variable))
                      .arg(static_cast<double>(m_session->result()->meshes->isovalue)))
            .filePath();
    const QString path = QFileDialog::getSaveFileName(this, tr("Export Surfaces"), suggested,
                                                      filters.join(QStringLiteral(";;")), &filter);
    if (path.isEmpty()) return;
    settings.setValue(QStringLiteral("export/surfaceFilter"), filter);
    settings.setValue(QStringLiteral("export/surfaceFolder"), QFileInfo(path).absolutePath());
    exportSurfaces(path);
}

void MainWindow::exportSurfaces(const QString& path) {
    const QFileInfo file(path);
    const auto format = engine::surfaceFormatOfFile(path.toStdString());
    const workbench::IsovalueResult* result = m_session != nullptr ? m_session->result() : nullptr;
    if (!format || result == nullptr || overview() == nullptr) {
        QMessageBox::warning(
            this, tr("Surfaces not exported"),
            !format ? tr("%1: name a file ending in .vtm, .ply, .obj or .stl.").arg(path)
                    : tr("There are no surfaces to export yet."));
        return;
    }
    // What the user is looking at: the selected members, else the visible ones.
    engine::SurfaceSet set;
    QList<int> members = m_selection->selectedMembers();
    if (members.isEmpty()) {
        for (int m = 0; m < m_selection->memberCount(); ++m) {
            if (m_selection->isMemberVisible(m)) members << m;
        }
    }
    set.members.assign(members.begin(), members.end());
    const data::Ensemble& ensemble = *overview()->ensemble;
    set.variable = ensemble.variable;
    set.units = ensemble.units;
    for (const data::Member& m : ensemble.members) set.memberNames.push_back(m.name);
    set.clusterNumbers = m_selection->memberClusterNumbers();
    set.depth = result->depth;
    set.stem = file.completeBaseName().toStdString();
    // The job keeps what it writes alive: the meshes and the grid, shared.
    auto meshes = result->meshes;
    auto ensembleKept = overview()->ensemble;
    const std::filesystem::path directory = file.absolutePath().toStdString();
    setBusy(tr("Writing the surfaces to %1...").arg(file.absolutePath()));
    m_surfaceExport.start(
        [set, meshes, ensembleKept, format, directory](const std::stop_token& stop,
                                                       const data::Progress& progress) mutable {
            set.meshes = meshes.get();
            set.grid = &ensembleKept->grid;
            return engine::exportSurfaces(set, *format, directory, stop, progress);
        },
        [this](const engine::ExportedSurfaces& written) {
            QStringList files;
            for (const auto& f : written.files) files << QString::fromStdString(f.string());
            QString message =
                tr("%n surface(s) written to %1", "", static_cast<int>(written.surfaces))
                    .arg(files.front());
            if (written.trianglesLeftOut > 0) {
                message += tr(" (%1 triangles left out: the format keeps surfaces manifold)")
                               .arg(written.trianglesLeftOut);
            }
            setIdle(message);
            emit surfacesExported(files);
        },
        [this](const std::exception_ptr& error, bool cancelled) {
            if (cancelled || !error) {
                setIdle(tr("Export cancelled"));
                return;
            }
            try {
                std::rethrow_exception(error);
            } catch (const std::exception& e) {
                setIdle(tr("Surfaces not exported"));
                QMessageBox::warning(this, tr("Surfaces not exported"),
                                     QString::fromUtf8(e.what()));
            }
        },
        [this](double fraction) {
            m_progress->setValue(static_cast<int>(fraction * m_progress->maximum()));
        });
}

void MainWindow::exportDendrogram() {
    QString error;
    if (!m_selection->isClustered()) {
        QMessageBox::information(this, tr("No dendrogram yet"),
                                 tr("The dendrogram appears once the members of an isovalue "
                                    "have been compared."));
        return;
    }
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export Dendrogram"), QStringLiteral("dendrogram.svg"), tr("SVG images (*.svg)"));
    if (path.isEmpty()) return;
    if (!ui::writeDendrogramSvg(*m_selection, path, &error)) {
        QMessageBox::warning(this, tr("Dendrogram not exported"), error);
        return;
    }
    statusBar()->showMessage(tr("Dendrogram written to %1").arg(path), 5000);
}

void MainWindow::exportMemberTable() {
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export Member Table"), QStringLiteral("members.csv"), tr("CSV files (*.csv)"));
    if (path.isEmpty()) return;
    QString error;
    if (!ui::writeMemberTableCsv(*m_selection, path, &error)) {
        QMessageBox::warning(this, tr("Member table not exported"), error);
        return;
    }
    statusBar()->showMessage(tr("Member table written to %1").arg(path), 5000);
}

QString MainWindow::defaultScreenshotPath(const QString& lastPath) const {
    // In the folder of the last screenshot, named after what the picture shows.
    const QString folder = lastPath.isEmpty() ? QString() : QFileInfo(lastPath).absolutePath();
    QString name = QStringLiteral("ensil.png");
    if (overview() != nullptr && m_model->state().isovalue) {
        name = QString::fromStdString(
                   engine::pictureFileStem(*overview()->ensemble, *m_model->state().isovalue)) +
               QStringLiteral(".png");
    }
    return folder.isEmpty() ? name : QDir(folder).filePath(name);
}

void MainWindow::chooseScreenshot() {
    QSettings settings;
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Save Screenshot"),
        defaultScreenshotPath(settings.value(QStringLiteral("screenshot/path")).toString()),
        tr("PNG images (*.png)"));
    if (path.isEmpty()) return;
    // Any resolution: the view's own by default, or e.g. 3840x2400 for print.
    const qreal ratio = m_view->devicePixelRatioF();
    const QString viewSize = QStringLiteral("%1x%2")
                                 .arg(std::lround(m_view->width() * ratio))
                                 .arg(std::lround(m_view->height() * ratio));
    bool ok = false;
    const QString answer = QInputDialog::getText(
        this, tr("Screenshot Size"), tr("Width x height in pixels:"), QLineEdit::Normal,
        settings.value(QStringLiteral("screenshot/size"), viewSize).toString(), &ok);
    if (!ok) return;
    const QStringList parts = answer.toLower().split(QLatin1Char('x'));
    const int width = parts.size() == 2 ? parts[0].trimmed().toInt() : 0;
    const int height = parts.size() == 2 ? parts[1].trimmed().toInt() : 0;
    if (width < 16 || height < 16 || width > 16384 || height > 16384) {
        QMessageBox::warning(this, tr("Screenshot not saved"),
                             tr("'%1' is not a size such as 1920x1200 (16 to 16384 pixels a "
                                "side).")
                                 .arg(answer));
        return;
    }
    settings.setValue(QStringLiteral("screenshot/path"), path);
    settings.setValue(QStringLiteral("screenshot/size"), answer);
    QString error;
    if (!saveScreenshot(path, &error, QSize(width, height))) {
        QMessageBox::warning(this, tr("Screenshot not saved"), error);
    }
}

bool MainWindow::saveScreenshot(const QString& path, QString* error, QSize size) {
    const QImage image = size.isEmpty() ? m_view->grabFramebuffer() : m_view->renderImage(size);
    if (image.isNull()) {
        if (error != nullptr) {
            *error = tr("The view could not be drawn at %1 x %2 pixels; the graphics driver may "
                        "not allow images that large.")
                         .arg(size.width())
                         .arg(size.height());
        }
        return false;
    }
    if (!image.save(path)) {
        if (error != nullptr) *error = tr("Could not write '%1'.").arg(path);
        return false;
    }
    return true;
}

}  // namespace ensil::app
