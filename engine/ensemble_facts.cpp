#include "engine/ensemble_facts.h"

#include <QObject>

namespace ensil::engine {

QString describeAxis(const data::Axis& axis) {
    return QStringLiteral("%1: %2 .. %3 %4, %5 points, %6")
        .arg(QString::fromStdString(axis.name))
        .arg(axis.front(), 0, 'g', 6)
        .arg(axis.back(), 0, 'g', 6)
        .arg(QString::fromStdString(axis.units))
        .arg(axis.size())
        .arg(axis.isUniform() ? QStringLiteral("uniform") : QStringLiteral("uneven spacing"));
}

QString describeDimensions(const data::VariableInfo& variable) {
    QStringList dims;
    for (std::size_t i = 0; i < variable.dimensions.size(); ++i) {
        const QString name = QString::fromStdString(variable.dimensions[i]);
        dims << (i < variable.shape.size()
                     ? QStringLiteral("%1=%2").arg(name).arg(variable.shape[i])
                     : name);
    }
    return dims.join(QStringLiteral(", "));
}

EnsembleFacts ensembleFacts(const EnsembleOverview& overview) {
    const data::Ensemble& e = *overview.ensemble;
    EnsembleFacts facts;
    facts.source = QString::fromStdString(e.source);
    facts.variable = QString::fromStdString(e.variable);
    facts.variableName = facts.variable;
    if (!e.longName.empty()) facts.variable += QStringLiteral(" (%1)").arg(e.longName.c_str());
    facts.units = QString::fromStdString(e.units);
    facts.memberDimension = QString::fromStdString(e.memberDimension);
    facts.members = static_cast<int>(e.memberCount());
    // A streamed ensemble's facts are the whole data's; its statistics are the copy's.
    const data::Grid& grid = overview.streamed ? overview.streamed->description.grid : e.grid;
    facts.gridSize = QStringLiteral("%1 x %2 x %3").arg(grid.nx()).arg(grid.ny()).arg(grid.nz());
    if (overview.streamed) {
        facts.gridSize +=
            QObject::tr(" (in memory: %1 x %2 x %3, a copy at %4)")
                .arg(e.grid.nx())
                .arg(e.grid.ny())
                .arg(e.grid.nz())
                .arg(QString::fromStdString(everyNthPoint(overview.streamed->stride)));
    }
    for (int a = 0; a < 3; ++a) facts.axes << describeAxis(grid.axis(a));
    facts.valueRange = QStringLiteral("%1 .. %2 %3, mean %4")
                           .arg(overview.statistics.minimum, 0, 'g', 5)
                           .arg(overview.statistics.maximum, 0, 'g', 5)
                           .arg(facts.units)
                           .arg(overview.statistics.mean, 0, 'g', 5);
    facts.missing = overview.statistics.missingCount;
    facts.megabytes = static_cast<double>(overview.streamed ? overview.streamed->description.bytes()
                                                            : e.bytes()) /
                      (1024.0 * 1024.0);
    QStringList warnings;
    if (overview.streamed) {
        warnings << QString::fromStdString(streamedDataNote(*overview.streamed, e));
    }
    for (const std::string& warning : e.warnings) warnings << QString::fromStdString(warning);
    if (const auto warning = data::fewLevelsWarning(e.grid)) {
        warnings << QString::fromStdString(*warning);
    }
    for (const std::string& name : overview.membersWithoutData) {
        warnings << QString::fromStdString(data::memberWithoutDataWarning(e, name));
    }
    facts.warning = warnings.join(QLatin1Char('\n'));
    return facts;
}

}  // namespace ensil::engine
