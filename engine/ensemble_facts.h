// Turns an ensemble overview into the plain facts the info panel shows.
#pragma once

#include <QString>
#include <QStringList>

#include "data/ensemble_reader.h"
#include "engine/ensemble_overview.h"

namespace ensil::engine {

// The plain facts the info panel and `ensil info` show about what is loaded.
struct EnsembleFacts {
    QString source;
    QString variable;      // "wind_speed (Wind speed)"
    QString variableName;  // "wind_speed": as a file names it
    QString units;
    QString memberDimension;
    int members = 0;
    QString gridSize;  // "256 x 128 x 16"
    QStringList axes;  // one line per axis: "lon: -80 .. 40 degrees_east, uniform"
    QString valueRange;
    qulonglong missing = 0;
    double megabytes = 0.0;
    // What the data cannot show well (few levels, members left out), a line each; empty when
    // nothing.
    QString warning;
};

EnsembleFacts ensembleFacts(const EnsembleOverview& overview);
// "lon: -80 .. 40 degrees_east, 256 points, uniform"
QString describeAxis(const data::Axis& axis);
// A variable's dimensions with their lengths where known: "number=10, plev=7, lat=61, lon=120"
QString describeDimensions(const data::VariableInfo& variable);

}  // namespace ensil::engine
