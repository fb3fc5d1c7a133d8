#include "workbench/recent_selections.h"

#include <QFileInfo>
#include <QObject>
#include <QStringList>
#include <QVariantMap>
#include <exception>
#include <iterator>

#include "data/level_range.h"
#include "data/region.h"

namespace ensil::workbench {
namespace {
const QString kFiles = QStringLiteral("recentFiles");
const QString kChoices = QStringLiteral("recentChoices");

QString keyOf(const data::DataSelection& selection) {
    QStringList paths;
    for (const auto& p : selection.paths) {
        paths << QFileInfo(QString::fromStdString(p)).absoluteFilePath();
    }
    return paths.join(QLatin1Char('\n'));
}
}  // namespace

void rememberSelection(QSettings& settings, const data::DataSelection& selection, int keep) {
    const QString key = keyOf(selection);
    QStringList recent = settings.value(kFiles).toStringList();
    recent.removeAll(key);
    recent.prepend(key);
    while (recent.size() > keep) recent.removeLast();
    QVariantMap choices = settings.value(kChoices).toMap();
    choices[key] = QStringList{
        QString::fromStdString(selection.variable),
        QString::fromStdString(selection.memberDimension), QString::number(selection.timeIndex),
        QString::fromStdString(selection.levels ? data::levelRangeText(*selection.levels) : ""),
        QString::fromStdString(selection.region ? data::regionText(*selection.region) : "")};
    // Choices of entries that fell off the list go with them.
    for (auto it = choices.begin(); it != choices.end();) {
        it = recent.contains(it.key()) ? std::next(it) : choices.erase(it);
    }
    settings.setValue(kFiles, recent);
    settings.setValue(kChoices, choices);
}

std::vector<RecentSelection> recentSelections(const QSettings& settings) {
    std::vector<RecentSelection> entries;
    const QVariantMap choices = settings.value(kChoices).toMap();
    for (const QString& key : settings.value(kFiles).toStringList()) {
        RecentSelection entry;
        const QStringList paths = key.split(QLatin1Char('\n'));
        for (const QString& p : paths) entry.selection.paths.push_back(p.toStdString());
        entry.label = paths.size() == 1 ? paths.front()
                                        : QObject::tr("%1 files in %2")
                                              .arg(paths.size())
                                              .arg(QFileInfo(paths.front()).absolutePath());
        // Entries written before choices were kept have none: the readers choose; those
        // written before the levels and the region were kept have three.
        const QStringList chosen = choices.value(key).toStringList();
        if (chosen.size() >= 3) {
            entry.selection.variable = chosen[0].toStdString();
            entry.selection.memberDimension = chosen[1].toStdString();
            entry.selection.timeIndex = chosen[2].toULongLong();
        }
        if (chosen.size() == 5) {
            // Written by rememberSelection from parsed values; a settings file edited by hand
            // into something else opens the whole file rather than failing.
            try {
                if (!chosen[3].isEmpty()) {
                    entry.selection.levels = data::parseLevelRange(chosen[3].toStdString());
                }
                if (!chosen[4].isEmpty()) {
                    entry.selection.region = data::parseRegion(chosen[4].toStdString());
                }
            } catch (const std::exception&) {
                entry.selection.levels.reset();
                entry.selection.region.reset();
            }
        }
        entries.push_back(std::move(entry));
    }
    return entries;
}

}  // namespace ensil::workbench
