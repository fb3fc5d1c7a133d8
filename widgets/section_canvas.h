// One map or cross-section on screen (engine/section_painter.h draws it, as in the exported
// figure): the members' contours in their clusters' colours, the selected ones wider, the
// hovered one widest, hidden ones left out. The pointer over a contour names its member and
// the value there; a click selects it (Shift adds, Ctrl toggles), a click beside every
// contour clears; on the map a drag with the right button draws the cross-section's path.
// Without a section it says why (no data yet, or the place lies outside the
// data). GUI thread only.
#pragma once

#include <QImage>
#include <QWidget>
#include <memory>
#include <optional>
#include <vector>

#include "engine/ensemble_section.h"
#include "engine/section_painter.h"

namespace ensil::ui {

class SectionCanvas : public QWidget {
    Q_OBJECT
public:
    explicit SectionCanvas(QWidget* parent = nullptr);

    void setView(std::shared_ptr<const engine::SectionView> view);
    [[nodiscard]] const engine::SectionView* view() const { return m_view.get(); }
    // What is said where no section is drawn.
    void setMessage(const QString& message);
    [[nodiscard]] QString message() const { return m_message; }
    // The selection's look: wider lines for `selected`, the widest for `hovered`; members
    // whose `visible` is false are not drawn.
    void setEmphasis(engine::SectionEmphasis emphasis);
    // Where the other section lies, drawn dashed over this one (unit-square polylines): the
    // cross-section's path on the map, the map's level on the cross-section.
    void setOverlay(std::vector<engine::SectionLine> overlay);
    [[nodiscard]] const std::vector<engine::SectionLine>& overlay() const { return m_overlay; }
    // Whether a drag with the right button draws a path (the map's: it places the
    // cross-section, pathDrawn).
    void setDrawsPaths(bool draws) { m_drawsPaths = draws; }
    // The member whose contour passes within a few pixels of `pos` (the nearest), if any.
    [[nodiscard]] std::optional<std::size_t> memberAt(QPointF pos) const;
    // What the tooltip says at `pos`: the member under it and its value there, or the fill's.
    [[nodiscard]] QString describe(QPointF pos) const;
    [[nodiscard]] QSize sizeHint() const override { return {520, 300}; }
    // How the dock draws: compact, in the widget's font.
    [[nodiscard]] engine::SectionStyle sectionStyle() const;

signals:
    void memberClicked(int member, Qt::KeyboardModifiers modifiers);  // -1: beside every one
    void memberHovered(int member);                                   // -1: none
    // A path drawn with the right button, from and to in the plot's unit square.
    void pathDrawn(glm::dvec2 from, glm::dvec2 to);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void leaveEvent(QEvent* event) override;
    bool event(QEvent* event) override;  // tooltips
    void resizeEvent(QResizeEvent* event) override;

private:
    // The plot's unit-square place of a widget position; nullopt outside the plot.
    [[nodiscard]] std::optional<glm::dvec2> unitAt(QPointF pos) const;

    std::shared_ptr<const engine::SectionView> m_view;
    engine::SectionEmphasis m_emphasis;
    // The section as drawn without the hovered member: drawing all of it takes a few hundred
    // ms in software, so a pointer's move redraws this image and the hovered contour only.
    QImage m_drawn;
    bool m_drawnValid = false;
    std::vector<engine::SectionLine> m_overlay;
    bool m_drawsPaths = false;
    std::optional<glm::dvec2> m_pathStart;  // a path being drawn: where the drag began
    glm::dvec2 m_pathEnd{0.0};
    QString m_message;
    int m_hovered = -1;
};

}  // namespace ensil::ui
