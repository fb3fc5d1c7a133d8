#include "cli/data_selection_options.h"

#include "data/error.h"
#include "data/level_range.h"
#include "data/region.h"

namespace ensil::cli {

DataSelectionOptions::DataSelectionOptions()
    : m_variable(QStringList{QStringLiteral("var")},
                 QStringLiteral("Variable (or dataset, or VTK array) to use; default: the one "
                                "with three spatial dimensions and the most vertical levels "
                                "(the first among equals)."),
                 QStringLiteral("V")),
      m_memberDim(QStringList{QStringLiteral("member-dim")},
                  QStringLiteral("Dimension that holds the members (e.g. time, month), when "
                                 "ensil cannot find one."),
                  QStringLiteral("D")),
      m_timeIndex(QStringList{QStringLiteral("time-index")},
                  QStringLiteral("Index taken along every other non-spatial dimension, such as "
                                 "time (default 0)."),
                  QStringLiteral("I"), QStringLiteral("0")),
      m_levels(QStringList{QStringLiteral("levels")},
               QStringLiteral("Keep only the vertical levels from FROM to TO, ends included, in "
                              "any units UDUNITS-2 converts to the vertical axis's (e.g. "
                              "1000:100hPa, 0:12km), or in the axis's own without units "
                              "(default: every level)."),
               QStringLiteral("FROM:TO")),
      m_region(QStringList{QStringLiteral("bbox")},
               QStringLiteral("Keep only the grid columns and rows within LON0..LON1 east and "
                              "LAT0..LAT1 north, edges included, in degrees (e.g. -10,40,35,72 "
                              "for Europe; LON0 > LON1 crosses the date line or the 0/360 seam: "
                              "350,20,35,70). Needs a regular longitude-latitude grid (default: "
                              "the whole grid)."),
               QStringLiteral("LON0,LON1,LAT0,LAT1")) {}

void DataSelectionOptions::addTo(QCommandLineParser& parser) const {
    parser.addOptions({m_variable, m_memberDim, m_timeIndex, m_levels, m_region});
    parser.addPositionalArgument(
        QStringLiteral("PATH"),
        QStringLiteral(
            "NetCDF, HDF5, VTK or GRIB file(s): one file with a member dimension, or one "
            "file per member."),
        QStringLiteral("PATH..."));
}

std::optional<data::DataSelection> DataSelectionOptions::selection(const QCommandLineParser& parser,
                                                                   QString& error) const {
    data::DataSelection s;
    for (const QString& path : parser.positionalArguments()) s.paths.push_back(path.toStdString());
    s.variable = parser.value(m_variable).toStdString();
    s.memberDimension = parser.value(m_memberDim).toStdString();
    bool ok = false;
    const qulonglong index = parser.value(m_timeIndex).toULongLong(&ok);
    if (!ok) {
        error = QStringLiteral("--time-index must be a whole number from 0, not '%1'")
                    .arg(parser.value(m_timeIndex));
        return std::nullopt;
    }
    s.timeIndex = index;
    if (parser.isSet(m_levels)) {
        try {
            s.levels = data::parseLevelRange(parser.value(m_levels).toStdString());
        } catch (const data::Error& e) {
            error = QStringLiteral("--levels: %1").arg(QString::fromUtf8(e.what()));
            return std::nullopt;
        }
    }
    if (parser.isSet(m_region)) {
        try {
            s.region = data::parseRegion(parser.value(m_region).toStdString());
        } catch (const data::Error& e) {
            error = QStringLiteral("--bbox: %1").arg(QString::fromUtf8(e.what()));
            return std::nullopt;
        }
    }
    return s;
}

}  // namespace ensil::cli
