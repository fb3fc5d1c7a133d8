// `ensil stats PATH... --iso C [--var V] [--member-dim D] [--time-index I] [--members LIST]
// --out STATS.nc [--json]`: per-point ensemble statistics (mean, standard deviation, minimum,
// maximum, range, P(f > C), member count) and per-cell level-crossing probability (METHODS.md
// section 17), written as one CF-1.8 NetCDF file (data/statistics_writer.h). Main thread; no
// display needed.
#pragma once

#include <QString>
#include <QStringList>
#include <QTextStream>
#include <cstddef>
#include <optional>
#include <vector>

namespace ensil::cli {

int runStatsCommand(const QStringList& args, QTextStream& out, QTextStream& err);

// Members first to last, both included, by their numbers: 1..N in the order the file holds
// them, the member table's # (METHODS.md "Numbers of members and clusters").
struct MemberRange {
    std::size_t first = 0;
    std::size_t last = 0;
    bool operator==(const MemberRange&) const = default;
};

// A member list as a user writes it, "1,3,5-9": numbers and ranges separated by commas,
// spaces allowed around them. Returns nullopt and sets `problem` (naming --members and the
// entry at fault) when an entry is empty or not a whole number from 1, a range runs
// backwards ("3-1") or a member is listed twice ("1,1", "1-4,3").
std::optional<std::vector<MemberRange>> parseMemberList(const QString& text, QString& problem);

}  // namespace ensil::cli
