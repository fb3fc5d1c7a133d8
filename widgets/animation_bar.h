// The animation controls: play/pause, step back and forward, speed and loop, over a sequence of
// members (the app decides which: the selected ones, or all, in cluster then similarity order).
// It says which member to show; it knows nothing of the renderer. GUI thread only.
#pragma once

#include <QStringList>
#include <QTimer>
#include <QToolBar>
#include <vector>

class QAction;
class QCheckBox;
class QDoubleSpinBox;
class QLabel;

namespace ensil::ui {

class AnimationBar : public QToolBar {
    Q_OBJECT
public:
    explicit AnimationBar(QWidget* parent = nullptr);

    // The members to step through, in order, and their names for the label. Stops playing.
    void setSequence(std::vector<int> members, QStringList names = {});
    [[nodiscard]] const std::vector<int>& sequence() const { return m_sequence; }
    // Position in the sequence (-1: not animating) and the member shown there.
    [[nodiscard]] int position() const { return m_position; }
    [[nodiscard]] int currentMember() const;
    [[nodiscard]] bool isPlaying() const { return m_timer.isActive(); }
    void setFramesPerSecond(double fps);
    void setLoop(bool loop);

    [[nodiscard]] QAction* playAction() const { return m_play; }

public slots:
    void play();
    void pause();
    void togglePlaying();
    // Moves by `delta` members (wrapping when looping); starts at the first when stopped.
    void step(int delta);
    // Leaves the animation: nothing is shown as animated any more.
    void stop();

signals:
    // The member to show as the animated one, -1 when the animation stops.
    void memberShown(int member);
    // Asked when play or step finds no sequence: the owner sets one (setSequence) in response.
    void sequenceWanted();

private:
    void advance();
    void show(int position);

    std::vector<int> m_sequence;
    QStringList m_names;
    int m_position = -1;
    QTimer m_timer;
    QAction* m_play;
    QAction* m_back;
    QAction* m_forward;
    QAction* m_stop;
    QDoubleSpinBox* m_speed;
    QCheckBox* m_loop;
    QLabel* m_label;
};

}  // namespace ensil::ui
