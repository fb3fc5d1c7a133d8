#include "widgets/time_bar.h"

#include <QAction>
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QStyle>
#include <algorithm>
#include <cmath>

namespace ensil::ui {

TimeBar::TimeBar(QWidget* parent)
    : QToolBar(tr("Time"), parent),
      m_slider(new QSlider(Qt::Horizontal, this)),
      m_speed(new QDoubleSpinBox(this)),
      m_loop(new QCheckBox(tr("Loop"), this)),
      m_label(new QLabel(this)) {
    setObjectName(QStringLiteral("timeToolbar"));
    m_back = addAction(style()->standardIcon(QStyle::SP_MediaSkipBackward), tr("Previous Time"));
    m_back->setShortcut(QKeySequence(Qt::Key_PageUp));
    m_back->setToolTip(tr("Show the previous time step (Page Up)"));
    m_play = addAction(style()->standardIcon(QStyle::SP_MediaPlay), tr("Play Time"));
    m_play->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_Space));
    m_play->setToolTip(
        tr("Step through the times; each step is shown once its surfaces are "
           "built (Shift+Space)"));
    m_forward = addAction(style()->standardIcon(QStyle::SP_MediaSkipForward), tr("Next Time"));
    m_forward->setShortcut(QKeySequence(Qt::Key_PageDown));
    m_forward->setToolTip(tr("Show the next time step (Page Down)"));
    m_slider->setObjectName(QStringLiteral("timeSlider"));
    m_slider->setMinimumWidth(160);
    m_slider->setToolTip(tr("The time step shown"));
    m_slider->setTracking(false);  // a step is asked for where the slider is let go
    addWidget(m_slider);
    addWidget(m_label);
    m_speed->setRange(0.1, 20.0);
    m_speed->setDecimals(1);
    m_speed->setSingleStep(0.5);
    m_speed->setSuffix(tr(" steps/s"));
    m_speed->setToolTip(tr("Playback speed (at most: a step waits for its surfaces)"));
    addWidget(m_speed);
    m_loop->setChecked(true);
    m_loop->setToolTip(tr("Start again after the last time step"));
    addWidget(m_loop);
    setStepsPerSecond(1.0);

    connect(m_play, &QAction::triggered, this, &TimeBar::togglePlaying);
    connect(m_back, &QAction::triggered, this, [this] { step(-1); });
    connect(m_forward, &QAction::triggered, this, [this] { step(1); });
    connect(m_slider, &QSlider::valueChanged, this, &TimeBar::requestStep);
    connect(&m_timer, &QTimer::timeout, this, &TimeBar::playbackTick);
    connect(m_speed, &QDoubleSpinBox::valueChanged, this, [this](double steps) {
        m_timer.setInterval(static_cast<int>(std::lround(1000.0 / steps)));
    });
    showState();
}

void TimeBar::setSteps(QStringList labels, int shown) {
    m_timer.stop();
    m_labels = std::move(labels);
    m_shown = std::clamp(shown, 0, std::max(0, stepCount() - 1));
    m_pending = -1;
    {
        const QSignalBlocker block(m_slider);
        m_slider->setRange(0, std::max(0, stepCount() - 1));
        m_slider->setValue(m_shown);
    }
    showState();
}

void TimeBar::setShownStep(int step) {
    if (step < 0 || step >= stepCount()) return;
    m_shown = step;
    if (m_pending == step) m_pending = -1;
    const QSignalBlocker block(m_slider);
    m_slider->setValue(step);
    showState();
}

void TimeBar::setStepsPerSecond(double steps) { m_speed->setValue(steps); }

void TimeBar::setLoop(bool loop) { m_loop->setChecked(loop); }

void TimeBar::play() {
    if (stepCount() < 2) return;
    // Playing from the last step starts again from the first.
    if (m_shown + 1 >= stepCount() && !m_loop->isChecked()) requestStep(0);
    m_timer.start();
    showState();
}

void TimeBar::pause() {
    m_timer.stop();
    showState();
}

void TimeBar::togglePlaying() { isPlaying() ? pause() : play(); }

void TimeBar::step(int delta) {
    const int n = stepCount();
    if (n < 2) return;
    int next = m_shown + delta;
    if (m_loop->isChecked()) {
        next = ((next % n) + n) % n;
    } else if (next < 0 || next >= n) {
        pause();
        return;
    }
    requestStep(next);
}

void TimeBar::requestStep(int step) {
    if (step < 0 || step >= stepCount() || step == m_pending) return;
    if (step == m_shown && m_pending < 0) return;
    m_pending = step;
    showState();
    emit stepRequested(step);
}

void TimeBar::playbackTick() {
    // One step at a time: the next is asked for only when the last one is on screen.
    if (m_pending >= 0) return;
    step(1);
}

void TimeBar::showState() {
    const bool steps = stepCount() > 1;
    for (QAction* a : {m_back, m_play, m_forward}) a->setEnabled(steps);
    m_slider->setEnabled(steps);
    m_speed->setEnabled(steps);
    m_loop->setEnabled(steps);
    const bool playing = isPlaying();
    m_play->setIcon(style()->standardIcon(playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
    m_play->setText(playing ? tr("Pause Time") : tr("Play Time"));
    if (!steps) {
        m_label->setText(stepCount() == 1 ? tr("  %1  (one time)").arg(m_labels.front())
                                          : tr("  no time steps"));
        return;
    }
    QString text = tr("  %1  (%2 of %3)").arg(m_labels[m_shown]).arg(m_shown + 1).arg(stepCount());
    if (m_pending >= 0 && m_pending != m_shown) {
        text += tr("  \u2192 %1 ...").arg(m_labels[m_pending]);
    }
    m_label->setText(text);
}

}  // namespace ensil::ui
