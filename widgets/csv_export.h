// The member table as CSV (RFC 4180: comma separated, fields with commas, quotes or line
// breaks quoted, quotes doubled), for spreadsheets and scripts: index, name, cluster, distance
// to the mean member, mean outlyingness, inclusion depth, whether the member is the contour
// boxplot's median and whether it is one of its outliers (1 or 0), visible, selected. Numbers in
// the C locale with full precision; unknown values empty. GUI thread (reads
// workbench::MemberSelection).
#pragma once

#include <QString>

namespace ensil::workbench {
class MemberSelection;
}  // namespace ensil::workbench

namespace ensil::ui {

[[nodiscard]] QString memberTableCsv(const workbench::MemberSelection& selection);
// Writes memberTableCsv to a file; false with a message naming the file on failure.
bool writeMemberTableCsv(const workbench::MemberSelection& selection, const QString& path,
                         QString* error = nullptr);

}  // namespace ensil::ui
