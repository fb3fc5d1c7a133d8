// The clusters over time (issue 17): one column per time step, each step's clusters as
// stacked bars in their colours (height: members), and each member a track from step to step,
// so a group that splits, merges or trades members reads at a glance (an alluvial view).
// Steps not yet built are empty columns (the workbench clusters them in the background). Linked
// with the selection both ways: the selected members' tracks are drawn bold, a click on a bar
// selects that cluster's members at that step (Shift adds, Ctrl toggles), hovering a track names
// and highlights its member. A view onto workbench::MemberSelection for the selection and hover;
// the steps' clusters are given to it. GUI thread.
#pragma once

#include <QStringList>
#include <QWidget>
#include <vector>

class QToolButton;

namespace ensil::workbench {
class MemberSelection;
}  // namespace ensil::workbench

namespace ensil::ui {

class ClusterTimeline : public QWidget {
    Q_OBJECT
public:
    explicit ClusterTimeline(workbench::MemberSelection* selection, QWidget* parent = nullptr);

    // The steps' labels (dates); forgets every step's clusters.
    void setSteps(QStringList labels);
    // A step's clusters: each member's cluster identity (its colour and number; -1 for none).
    void setStepClusters(int step, std::vector<int> identities);
    [[nodiscard]] const std::vector<int>& stepClusters(int step) const;
    // The step on screen, marked under its column.
    void setCurrentStep(int step);
    // The steps not visited being clustered in the background: `done` of `total` (total 0:
    // none), said on a button in the corner that asks to stop (stopFillingRequested).
    void setFilling(int done, int total);
    [[nodiscard]] QToolButton* fillingButton() const { return m_filling; }

    // Where things are drawn, for tests and picking: the column of a step, and the rectangle
    // of a cluster's bar at a step (empty when the step holds no such cluster).
    [[nodiscard]] double columnX(int step) const;
    [[nodiscard]] QRectF barRect(int step, int identity) const;
    // The members of a cluster at a step, in member order.
    [[nodiscard]] QList<int> membersAt(int step, int identity) const;

    [[nodiscard]] QSize sizeHint() const override { return {600, 160}; }

signals:
    void membersClicked(const QList<int>& members, Qt::KeyboardModifiers modifiers);
    void stopFillingRequested();

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void leaveEvent(QEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    // Each member's vertical slot (0 .. n-1 plus the gaps between clusters) at a built step:
    // clusters by identity, members in a cluster by their slot at the previous built step, so
    // tracks cross only where members change group.
    void layOut();
    [[nodiscard]] double slotY(double slot) const;
    [[nodiscard]] int memberNear(QPointF at) const;

    workbench::MemberSelection* m_selection;
    QStringList m_labels;
    std::vector<std::vector<int>> m_identities;  // per step, per member; empty: not built
    std::vector<std::vector<double>> m_slots;    // per step, per member
    double m_slotCount = 0.0;                    // members and gaps, the column's height
    int m_current = -1;
    QToolButton* m_filling;
};

}  // namespace ensil::ui
