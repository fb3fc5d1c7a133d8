// The Sections dock's Colours button: a menu of the fill's colour maps and a fixed range (the
// setting table's sections_colour_map, sections_fixed_range, sections_range_min and
// sections_range_max). Each pick is a session edit (edited(): an undo step); the check marks
// show the session. GUI thread only.
#pragma once

#include <QToolButton>
#include <functional>
#include <optional>
#include <utility>

namespace ensil::session {
class SessionModel;
}  // namespace ensil::session

namespace ensil::ui {

class SectionColoursButton : public QToolButton {
    Q_OBJECT
public:
    // The range and units the sections show now: where Fixed Range... starts.
    struct ShownRange {
        double minimum = 0.0;
        double maximum = 1.0;
        QString units;
    };
    SectionColoursButton(session::SessionModel* model,
                         std::function<std::optional<ShownRange>()> shownRange,
                         QWidget* parent = nullptr);

    // Fixed to [minimum, maximum], or (nullopt) the shown section's own: a session edit.
    void setFixedRange(std::optional<std::pair<double, double>> range);
    // The check marks and the range's text as the session has them.
    void showSession();

signals:
    void edited();

private:
    void askFixedRange();

    session::SessionModel* m_model;
    std::function<std::optional<ShownRange>()> m_shownRange;
    QAction* m_fixedRange = nullptr;
};

}  // namespace ensil::ui
