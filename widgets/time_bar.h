// The time controls (issue 17): a slider over the data's time steps with the step's date, step
// back and forward (Page Up, Page Down), play and pause (Shift+Space), loop and speed. It asks
// for a step (stepRequested) and is told when that step is on screen (setShownStep); while
// playing it asks for the next step only once the last one is shown, so steps are never queued
// and a slow step slows the playback instead of piling up. Knows nothing of the data or the
// renderer. GUI thread only.
#pragma once

#include <QStringList>
#include <QTimer>
#include <QToolBar>

class QAction;
class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QSlider;

namespace ensil::ui {

class TimeBar : public QToolBar {
    Q_OBJECT
public:
    explicit TimeBar(QWidget* parent = nullptr);

    // The steps' labels (dates); fewer than two steps hides the bar's controls. Stops playing.
    void setSteps(QStringList labels, int shown);
    [[nodiscard]] int stepCount() const { return static_cast<int>(m_labels.size()); }
    // The step on screen: the slider and label follow it, and playback may go on.
    void setShownStep(int step);
    [[nodiscard]] int shownStep() const { return m_shown; }
    // The step asked for last and not yet shown (-1: none).
    [[nodiscard]] int pendingStep() const { return m_pending; }
    [[nodiscard]] bool isPlaying() const { return m_timer.isActive(); }
    void setStepsPerSecond(double steps);
    void setLoop(bool loop);
    [[nodiscard]] QAction* playAction() const { return m_play; }

public slots:
    void play();
    void pause();
    void togglePlaying();
    // Asks for the step `delta` away from the one shown (wrapping when looping).
    void step(int delta);
    // Asks for this step (the slider), unless it is the one shown or already asked for.
    void requestStep(int step);
    // What the playback timer does at each tick: the next step, unless the last one asked
    // for is not on screen yet.
    void playbackTick();

signals:
    void stepRequested(int step);

private:
    void showState();

    QStringList m_labels;
    int m_shown = 0;
    int m_pending = -1;
    QTimer m_timer;
    QAction* m_play;
    QAction* m_back;
    QAction* m_forward;
    QSlider* m_slider;
    QDoubleSpinBox* m_speed;
    QCheckBox* m_loop;
    QLabel* m_label;
};

}  // namespace ensil::ui
