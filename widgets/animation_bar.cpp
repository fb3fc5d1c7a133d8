#include "widgets/animation_bar.h"

#include <QAction>
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QStyle>
#include <cmath>

namespace ensil::ui {

AnimationBar::AnimationBar(QWidget* parent)
    : QToolBar(tr("Animation"), parent),
      m_speed(new QDoubleSpinBox(this)),
      m_loop(new QCheckBox(tr("Loop"), this)),
      m_label(new QLabel(this)) {
    setObjectName(QStringLiteral("animationToolbar"));
    m_back = addAction(style()->standardIcon(QStyle::SP_MediaSeekBackward), tr("Previous Member"));
    m_back->setShortcut(QKeySequence(Qt::Key_BracketLeft));
    m_back->setToolTip(tr("Show the previous member ([)"));
    m_play = addAction(style()->standardIcon(QStyle::SP_MediaPlay), tr("Play"));
    m_play->setShortcut(QKeySequence(Qt::Key_Space));
    m_play->setToolTip(
        tr("Play the selected members (all, if none is selected) one after another as solid "
           "surfaces, in cluster then similarity order (Space)"));
    m_forward = addAction(style()->standardIcon(QStyle::SP_MediaSeekForward), tr("Next Member"));
    m_forward->setShortcut(QKeySequence(Qt::Key_BracketRight));
    m_forward->setToolTip(tr("Show the next member (])"));
    m_stop = addAction(style()->standardIcon(QStyle::SP_MediaStop), tr("Stop Animation"));
    m_stop->setToolTip(tr("Leave the animation"));
    m_speed->setRange(0.25, 30.0);
    m_speed->setDecimals(2);
    m_speed->setSingleStep(0.5);
    m_speed->setSuffix(tr(" members/s"));
    m_speed->setToolTip(tr("Animation speed"));
    addWidget(m_speed);
    m_loop->setChecked(true);
    m_loop->setToolTip(tr("Start again after the last member"));
    addWidget(m_loop);
    addWidget(m_label);
    setFramesPerSecond(2.0);

    connect(m_play, &QAction::triggered, this, &AnimationBar::togglePlaying);
    connect(m_back, &QAction::triggered, this, [this] { step(-1); });
    connect(m_forward, &QAction::triggered, this, [this] { step(1); });
    connect(m_stop, &QAction::triggered, this, &AnimationBar::stop);
    connect(&m_timer, &QTimer::timeout, this, &AnimationBar::advance);
    connect(m_speed, &QDoubleSpinBox::valueChanged, this, [this](double fps) {
        m_timer.setInterval(static_cast<int>(std::lround(1000.0 / fps)));
    });
    show(-1);
}

void AnimationBar::setSequence(std::vector<int> members, QStringList names) {
    const bool wasAnimating = m_position >= 0;
    m_timer.stop();
    m_sequence = std::move(members);
    m_names = std::move(names);
    m_position = -1;
    show(-1);
    if (wasAnimating) emit memberShown(-1);
}

int AnimationBar::currentMember() const {
    return m_position >= 0 && m_position < static_cast<int>(m_sequence.size())
               ? m_sequence[static_cast<std::size_t>(m_position)]
               : -1;
}

void AnimationBar::setFramesPerSecond(double fps) { m_speed->setValue(fps); }

void AnimationBar::setLoop(bool loop) { m_loop->setChecked(loop); }

void AnimationBar::play() {
    if (m_sequence.empty()) emit sequenceWanted();
    if (m_sequence.empty()) return;
    // Playing from the end starts again from the beginning.
    if (m_position < 0 || m_position + 1 >= static_cast<int>(m_sequence.size())) show(0);
    m_timer.start();
    show(m_position);
}

void AnimationBar::pause() {
    m_timer.stop();
    show(m_position);
}

void AnimationBar::togglePlaying() { isPlaying() ? pause() : play(); }

void AnimationBar::step(int delta) {
    if (m_sequence.empty()) emit sequenceWanted();
    if (m_sequence.empty()) return;
    const int n = static_cast<int>(m_sequence.size());
    if (m_position < 0) {
        show(delta >= 0 ? 0 : n - 1);
        return;
    }
    int next = m_position + delta;
    if (m_loop->isChecked()) {
        next = ((next % n) + n) % n;
    } else if (next < 0 || next >= n) {
        m_timer.stop();
        show(m_position);
        return;
    }
    show(next);
}

void AnimationBar::stop() {
    const bool wasAnimating = m_position >= 0;
    m_timer.stop();
    m_position = -1;
    show(-1);
    if (wasAnimating) emit memberShown(-1);
}

void AnimationBar::advance() { step(1); }

void AnimationBar::show(int position) {
    const bool changed = position != m_position;
    m_position = position;
    const bool playing = isPlaying();
    m_play->setIcon(style()->standardIcon(playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
    m_play->setText(playing ? tr("Pause") : tr("Play"));
    m_stop->setEnabled(position >= 0);
    const int member = currentMember();
    if (member < 0) {
        m_label->setText(tr("  not animating"));
    } else {
        const QString name =
            member < m_names.size() ? m_names[member] : tr("member %1").arg(member);
        m_label->setText(tr("  %1  (%2 of %3)").arg(name).arg(position + 1).arg(m_sequence.size()));
    }
    if (changed && member >= 0) emit memberShown(member);
}

}  // namespace ensil::ui
