#include "workbench/dialog_paths.h"

#include <QDir>
#include <QFileInfo>
#include <QObject>

namespace ensil::workbench {

QString suggestedProjectPath(const QString& projectPath, const QString& lastFolder,
                             const QString& dataFile) {
    if (!projectPath.isEmpty()) return projectPath;
    QString folder = lastFolder;
    if (folder.isEmpty() && !dataFile.isEmpty()) folder = QFileInfo(dataFile).absolutePath();
    if (folder.isEmpty() || !QFileInfo(folder).isDir()) folder = QDir::homePath();
    return QDir(folder).filePath(QStringLiteral("session.ensil"));
}

QString ensembleFileFilters() {
    // wrfout_d01_2020-01-01_00:00:00 and its kind carry no extension; GRIB files often carry
    // none either, but have no common name to match, so "All files" stays offered.
    return QObject::tr(
        "Ensemble files (*.nc *.nc4 *.cdf *.netcdf *.h5 *.hdf5 *.he5 *.vtk *.vti "
        "*.grib *.grb *.grib1 *.grib2 *.grb2 wrfout_* wrfrst_* wrfinput_*);;"
        "All files (*)");
}

}  // namespace ensil::workbench
