#include "widgets/csv_export.h"

#include <QSaveFile>
#include <QStringList>
#include <cmath>

#include "workbench/member_selection.h"

namespace ensil::ui {
namespace {
QString field(const QString& text) {
    if (!text.contains(QLatin1Char(',')) && !text.contains(QLatin1Char('"')) &&
        !text.contains(QLatin1Char('\n')) && !text.contains(QLatin1Char('\r'))) {
        return text;
    }
    QString quoted = text;
    quoted.replace(QLatin1String("\""), QLatin1String("\"\""));
    return QLatin1Char('"') + quoted + QLatin1Char('"');
}

QString flag(bool value) { return value ? QStringLiteral("1") : QStringLiteral("0"); }

QString number(double value) {
    if (std::isnan(value)) return {};
    if (std::isinf(value)) return value > 0 ? QStringLiteral("inf") : QStringLiteral("-inf");
    return QString::number(value, 'g', 17);
}
}  // namespace

QString memberTableCsv(const workbench::MemberSelection& selection) {
    QStringList lines;
    lines << QStringLiteral(
        "number,name,cluster,distance_to_mean,mean_outlyingness,depth,median,outlier,visible,"
        "selected");
    for (int m = 0; m < selection.memberCount(); ++m) {
        const int cluster = selection.clusterNumber(selection.clusterOf(m));
        // The median and outlier flags are unknown (empty) while the depths are.
        const bool boxplot = !std::isnan(selection.depth(m));
        lines << QStringList{QString::number(m + 1),
                             field(selection.name(m)),
                             cluster <= 0 ? QString() : QString::number(cluster),
                             number(selection.distanceToMean(m)),
                             number(selection.meanOutlyingness(m)),
                             number(selection.depth(m)),
                             boxplot ? flag(selection.isMedian(m)) : QString(),
                             boxplot ? flag(selection.isOutlier(m)) : QString(),
                             flag(selection.isMemberVisible(m)),
                             flag(selection.isSelected(m))}
                     .join(QLatin1Char(','));
    }
    return lines.join(QStringLiteral("\r\n")) + QStringLiteral("\r\n");
}

bool writeMemberTableCsv(const workbench::MemberSelection& selection, const QString& path,
                         QString* error) {
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(memberTableCsv(selection).toUtf8()) < 0 ||
        !file.commit()) {
        if (error != nullptr) {
            *error = QObject::tr("Could not write '%1': %2").arg(path, file.errorString());
        }
        return false;
    }
    return true;
}

}  // namespace ensil::ui
