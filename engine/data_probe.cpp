#include "engine/data_probe.h"

#include <QObject>
#include <algorithm>

#include "data/error.h"
#include "engine/ensemble_facts.h"
#include "engine/workbench_reading.h"

namespace ensil::engine {
namespace {

QString qs(const std::string& s) { return QString::fromStdString(s); }

bool isAxis(const data::Grid& grid, const std::string& dimension) {
    for (int a = 0; a < 3; ++a) {
        if (grid.axis(a).name == dimension) return true;
    }
    return false;
}

// The candidates for the member dimension (the chosen variable's non-spatial dimensions) and
// how many time indices there are to choose from (the readers' TimeSteps).
void fillChoices(DataProbe& probe, const data::EnsembleDescription& d) {
    const auto chosen =
        std::find_if(d.variables.begin(), d.variables.end(),
                     [&](const data::VariableInfo& v) { return v.name == d.variable; });
    if (chosen == d.variables.end()) return;
    for (const std::string& dim : chosen->dimensions) {
        if (!isAxis(d.grid, dim)) probe.memberDimensionChoices << qs(dim);
    }
    if (d.timeSteps.count() > 0) probe.timeSteps = static_cast<int>(d.timeSteps.count());
}

void fill(DataProbe& probe, const data::EnsembleDescription& d) {
    probe.format = qs(d.format);
    for (const data::VariableInfo& v : d.variables) {
        probe.variables.push_back({.name = qs(v.name),
                                   .dimensions = describeDimensions(v),
                                   .units = qs(v.units),
                                   .longName = qs(v.longName),
                                   .usable = v.usable,
                                   .whyNotUsable = qs(v.whyNotUsable)});
    }
    probe.variable = qs(d.variable);
    probe.memberDimension = qs(d.memberDimension);
    probe.memberDimensionReason = qs(d.memberDimensionReason);
    probe.members = static_cast<int>(d.members);
    probe.grid = QStringLiteral("%1 x %2 x %3").arg(d.grid.nx()).arg(d.grid.ny()).arg(d.grid.nz());
    probe.levels = describeAxis(d.grid.z());
    if (d.keptLevels) {
        probe.levels += QObject::tr(" (%1 of the file's %2 levels)")
                            .arg(d.grid.nz())
                            .arg(d.keptLevels->fileZ.size());
    }
    probe.region = describeAxis(d.grid.x()) + QStringLiteral("; ") + describeAxis(d.grid.y());
    if (d.keptRegion) {
        probe.region += QObject::tr(" (%1 x %2 of the file's %3 x %4 columns and rows)")
                            .arg(d.grid.nx())
                            .arg(d.grid.ny())
                            .arg(d.keptRegion->fileX.size())
                            .arg(d.keptRegion->fileY.size());
    }
    for (const std::string& f : d.fixedDimensions) probe.fixedDimensions << qs(f);
    fillChoices(probe, d);
}

// The file holds no dimension ensil recognises as members: list its variables anyway (as if
// the first candidate held them) and leave the choice to the user.
DataProbe probeWithoutMemberDimension(const data::DataSelection& selection,
                                      const data::Error& error) {
    DataProbe probe;
    data::DataSelection guess = selection;
    guess.memberDimension = error.choices().front();
    try {
        fill(probe, data::describeEnsemble(guess));
    } catch (const std::exception&) {
        probe = {};  // the variables stay unlisted; the error below still says what to do
    }
    probe.memberDimension.clear();
    probe.memberDimensionReason.clear();
    probe.members = 0;
    probe.memberDimensionChoices.clear();
    for (const std::string& c : error.choices()) probe.memberDimensionChoices << qs(c);
    probe.error = qs(error.what()) + QLatin1Char('\n') +
                  QObject::tr("Choose the dimension that holds the members above.");
    return probe;
}

}  // namespace

DataProbe probeData(const data::DataSelection& selection, std::size_t memoryLimit) {
    try {
        DataProbe probe;
        const data::EnsembleDescription d = data::describeEnsemble(selection);
        fill(probe, d);
        if (memoryLimit != 0) probe.size = qs(howItOpens(selection, d, memoryLimit));
        return probe;
    } catch (const data::Error& e) {
        if (e.kind() == data::ErrorKind::MemberDimensionNotFound && !e.choices().empty() &&
            selection.memberDimension.empty()) {
            return probeWithoutMemberDimension(selection, e);
        }
        DataProbe probe;
        probe.error = qs(e.what());
        return probe;
    } catch (const std::bad_alloc&) {
        DataProbe probe;
        probe.error = QObject::tr("not enough memory to read the file headers");
        return probe;
    } catch (const std::exception& e) {
        DataProbe probe;
        probe.error = QObject::tr("the file headers could not be read: %1").arg(e.what());
        return probe;
    }
}

}  // namespace ensil::engine
