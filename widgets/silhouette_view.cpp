#include "widgets/silhouette_view.h"

#include <QElapsedTimer>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLFramebufferObject>
#include <QOpenGLFunctions>
#include <QPainter>
#include <QRubberBand>
#include <QToolTip>
#include <QWheelEvent>
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

namespace ensil::ui {
namespace {
// Long enough to skip the picks of a cursor in motion, short enough to feel immediate.
constexpr int kHoverDelayMs = 40;
// A pause in wheel turns (or time steps) this long ends the motion.
constexpr int kWheelSettleMs = 200;
// The resolutions motion may use, full first; few steps, as each change reallocates the
// renderer's targets.
constexpr std::array<float, 5> kMotionScales{1.0F, 0.75F, 0.5F, 0.35F, 0.25F};
constexpr int kCoarsestMotionStep = static_cast<int>(kMotionScales.size()) - 1;
}  // namespace

SilhouetteView::SilhouetteView(QWidget* parent) : QOpenGLWidget(parent) {
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(200, 150);
    setMouseTracking(true);
    m_hoverTimer.setSingleShot(true);
    m_hoverTimer.setInterval(kHoverDelayMs);
    connect(&m_hoverTimer, &QTimer::timeout, this, &SilhouetteView::pickHovered);
    m_settleTimer.setSingleShot(true);
    m_settleTimer.setInterval(kWheelSettleMs);
    connect(&m_settleTimer, &QTimer::timeout, this, &SilhouetteView::stopMoving);
}

void SilhouetteView::setAdaptiveResolution(bool on) {
    m_adaptiveResolution = on;
    update();
}

float SilhouetteView::frameResolutionScale() const {
    return m_moving && m_adaptiveResolution ? kMotionScales[m_motionStep] : 1.0F;
}

void SilhouetteView::adaptMotionStep(double frameMs, float scale) {
    if (!m_moving) {
        // A still frame at full resolution: motion starts no finer than the step whose pixels
        // fit the budget, as a software renderer's time goes with them, and never finer than
        // the step motion frames themselves arrived at: part of a frame's time does not shrink
        // with its pixels, so the estimate from a still frame is too fine on software OpenGL
        // (the demo's still frame of 200 ms asked for 0.35, whose frames took 57 ms of a 33 ms
        // budget, and every time step's first frame was drawn there). Motion frames measured
        // faster than half the budget still make it finer, below.
        const auto wanted = static_cast<float>(std::sqrt(m_motionBudgetMs / frameMs));
        int estimate = 0;
        while (estimate < kCoarsestMotionStep && kMotionScales[estimate] > wanted) ++estimate;
        m_motionStep = std::max(estimate, m_measuredMotionStep);
        return;
    }
    // During motion, what each frame took decides the next: part of a frame's time does not
    // shrink with its pixels, so the first guess may be too fine (or too coarse).
    if (scale != kMotionScales[m_motionStep]) return;
    if (frameMs > m_motionBudgetMs && m_motionStep < kCoarsestMotionStep) {
        ++m_motionStep;
    } else if (frameMs < 0.5 * m_motionBudgetMs && m_motionStep > 0) {
        --m_motionStep;
    }
    m_measuredMotionStep = m_motionStep;
}

void SilhouetteView::beginInteraction() {
    m_moving = true;
    // A settling still pending (the last step's, when steps follow faster than it settles)
    // would draw this interaction's frames at full resolution: on software OpenGL such a frame
    // takes 200 ms of both cores, which a new step's build behind its preview needs.
    m_settleTimer.stop();
}

void SilhouetteView::showPassingChange() {
    m_moving = true;
    m_settleTimer.start();
    update();
}

void SilhouetteView::afterNextFrame(QObject* context, std::function<void()> work) {
    auto connection = std::make_shared<QMetaObject::Connection>();
    *connection =
        connect(this, &QOpenGLWidget::frameSwapped, context, [connection, work = std::move(work)] {
            disconnect(*connection);
            work();
        });
    update();  // so that there is a next frame
}

void SilhouetteView::stopMoving() {
    if (!m_moving) return;
    m_moving = false;
    m_settleTimer.stop();
    update();  // the still frame, at full resolution
}

SilhouetteView::~SilhouetteView() {
    if (context() != nullptr) {
        // QOpenGLWidget's destructor destroys the context after this class is gone.
        disconnect(context(), nullptr, this, nullptr);
        makeCurrent();
        releaseGpu();
        doneCurrent();
    }
}

void SilhouetteView::releaseGpu() { m_renderer.releaseGpuResources(); }

void SilhouetteView::onContextAboutToBeDestroyed() {
    makeCurrent();
    releaseGpu();
    doneCurrent();
}

void SilhouetteView::initializeGL() {
    // initializeGL runs again for each new context (re-parenting); connect to each once.
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this,
            &SilhouetteView::onContextAboutToBeDestroyed, Qt::UniqueConnection);
    try {
        m_renderer.initialize();
        m_renderer.warmUp();
        m_glError.clear();
    } catch (const std::exception& e) {
        m_glError = QString::fromStdString(e.what());
        emit renderingFailed(m_glError);
    }
}

void SilhouetteView::paintGL() {
    if (!m_renderer.isInitialized()) return;
    const qreal ratio = devicePixelRatioF();
    const int w = static_cast<int>(std::lround(width() * ratio));
    const int h = static_cast<int>(std::lround(height() * ratio));
    const float scale = frameResolutionScale();
    m_renderer.setResolutionScale(scale);
    QElapsedTimer timer;
    timer.start();
    m_renderer.render(defaultFramebufferObject(), w, h);
    ++m_framesDrawn;
    if (m_adaptiveResolution) {
        // Timed to the end of the GPU's work: the next motion frame's resolution depends on it.
        context()->functions()->glFinish();
        adaptMotionStep(static_cast<double>(timer.nsecsElapsed()) * 1e-6, scale);
    }
    gl::ViewOverlay overlay = m_renderer.overlay(w, h);
    if (!m_renderer.hasGrid()) overlay.message = m_placeholder;
    QPainter painter(this);
    gl::paintOverlay(painter, overlay, ratio);
}

QImage SilhouetteView::renderImage(const QSize& size) {
    if (!m_renderer.isInitialized() || size.isEmpty()) return {};
    // Text and lines grow with the picture's size by the rule `ensil render` uses, so a
    // screenshot and the same project rendered headless are the same picture.
    const double scale = gl::exportTextScale(size.height());
    makeCurrent();
    QImage image;
    {
        QOpenGLFramebufferObject target(size, QOpenGLFramebufferObject::CombinedDepthStencil);
        m_renderer.setResolutionScale(1.0F);  // pictures are always full resolution
        m_renderer.setLineScale(static_cast<float>(scale));
        m_renderer.render(target.handle(), size.width(), size.height());
        m_renderer.setLineScale(1.0F);
        image = target.toImage();
    }
    // The picks answer for the window's frame, not this one: draw the window's again.
    doneCurrent();
    update();
    QPainter painter(&image);
    painter.scale(scale, scale);
    gl::paintOverlay(painter, m_renderer.overlay(size.width(), size.height()), scale,
                     QSizeF(size.width() / scale, size.height() / scale));
    return image;
}

void SilhouetteView::resetCamera() {
    m_renderer.resetCamera();
    update();
}

void SilhouetteView::lookFrom(float azimuth, float elevation) {
    m_renderer.lookFrom(azimuth, elevation);
    update();
}

void SilhouetteView::resizeGL(int width, int height) { m_renderer.setViewSize(width, height); }

QPoint SilhouetteView::toFramebuffer(QPoint position) const {
    const qreal ratio = devicePixelRatioF();
    return {static_cast<int>(std::lround(position.x() * ratio)),
            static_cast<int>(std::lround(position.y() * ratio))};
}

gl::PickResult SilhouetteView::pickAt(QPoint position) {
    if (!m_renderer.isInitialized()) return {};
    const QPoint p = toFramebuffer(position);
    makeCurrent();
    const gl::PickResult result = m_renderer.pick(p.x(), p.y());
    doneCurrent();
    return result;
}

QList<int> SilhouetteView::membersInside(const QRect& rectangle) {
    if (!m_renderer.isInitialized()) return {};
    const QPoint a = toFramebuffer(rectangle.topLeft());
    const QPoint b = toFramebuffer(rectangle.bottomRight());
    makeCurrent();
    const std::vector<int> members = m_renderer.membersIn(a.x(), a.y(), b.x(), b.y());
    doneCurrent();
    return {members.begin(), members.end()};
}

void SilhouetteView::mousePressEvent(QMouseEvent* event) {
    m_lastMouse = event->position().toPoint();
    m_pressPosition = m_lastMouse;
    m_pressButton = event->button();
    m_dragged = false;
    m_hoverTimer.stop();
    event->accept();
}

void SilhouetteView::mouseMoveEvent(QMouseEvent* event) {
    const QPoint pos = event->position().toPoint();
    const QPoint delta = pos - m_lastMouse;
    m_lastMouse = pos;
    if (event->buttons() == Qt::NoButton) {
        m_hoverPosition = pos;
        m_hoverTimer.start();
        return;
    }
    if ((pos - m_pressPosition).manhattanLength() >= kClickSlop) m_dragged = true;
    if (event->buttons() & Qt::RightButton) {
        if (!m_dragged) return;
        if (m_rubberBand == nullptr) m_rubberBand = new QRubberBand(QRubberBand::Rectangle, this);
        m_rubberBand->setGeometry(QRect(m_pressPosition, pos).normalized());
        m_rubberBand->show();
        return;
    }
    const bool panning =
        (event->buttons() & Qt::MiddleButton) ||
        ((event->buttons() & Qt::LeftButton) && (event->modifiers() & Qt::ShiftModifier));
    if (panning) {
        m_renderer.camera().pan(static_cast<float>(delta.x()), static_cast<float>(delta.y()),
                                static_cast<float>(height()));
    } else if (event->buttons() & Qt::LeftButton) {
        // A drag across the view turns it half way round, whatever the view's size.
        m_renderer.camera().orbit(static_cast<float>(delta.x()), static_cast<float>(delta.y()),
                                  kDragAcrossDegrees / static_cast<float>(std::max(1, width())));
    } else {
        return;
    }
    m_moving = true;
    update();
}

void SilhouetteView::mouseReleaseEvent(QMouseEvent* event) {
    const QPoint pos = event->position().toPoint();
    const Qt::MouseButton button = event->button();
    if (button != m_pressButton) return;
    m_pressButton = Qt::NoButton;
    stopMoving();
    if (button == Qt::LeftButton && !m_dragged) {
        emit memberClicked(pickAt(pos).member, event->modifiers());
    } else if (button == Qt::RightButton && m_dragged) {
        if (m_rubberBand != nullptr) m_rubberBand->hide();
        emit membersBrushed(membersInside(QRect(m_pressPosition, pos).normalized()),
                            event->modifiers());
    }
    event->accept();
}

void SilhouetteView::pickHovered() {
    // No need to ask whether the pointer is still here: leaving the view stops the timer.
    const gl::PickResult hit = pickAt(m_hoverPosition);
    const QString description = m_describeHover ? m_describeHover(hit) : QString();
    setHovered(hit.member, m_hoverPosition, hit.cluster, description);
    emit hoverDescribed(description);
}

void SilhouetteView::setHovered(int member, QPoint position, int cluster,
                                const QString& description) {
    QStringList lines;
    if (member >= 0) {
        const QString name = member < m_memberNames.size() && !m_memberNames[member].isEmpty()
                                 ? m_memberNames[member]
                                 : tr("member %1").arg(member);
        lines << (cluster >= 0 ? tr("%1\ncluster %2").arg(name).arg(cluster + 1) : name);
    }
    if (!description.isEmpty()) lines << description;
    if (!lines.isEmpty()) {
        QToolTip::showText(mapToGlobal(position), lines.join(QLatin1Char('\n')), this);
    } else {
        QToolTip::hideText();
    }
    if (member == m_hovered) return;
    m_hovered = member;
    m_renderer.setHighlightedMember(member);
    update();
    emit memberHovered(member);
}

void SilhouetteView::leaveEvent(QEvent* event) {
    m_hoverTimer.stop();
    setHovered(-1, {}, -1);
    QOpenGLWidget::leaveEvent(event);
}

void SilhouetteView::wheelEvent(QWheelEvent* event) {
    // One notch (120 units) zooms by 12 %.
    const double notches = event->angleDelta().y() / 120.0;
    // Toward the cursor, so what a user points at stays where it is.
    const QPointF offset = event->position() - QPointF(width() / 2.0, height() / 2.0);
    m_renderer.camera().zoomToward(static_cast<float>(std::pow(1.12, notches)),
                                   {static_cast<float>(offset.x()), static_cast<float>(offset.y())},
                                   static_cast<float>(height()));
    showPassingChange();
    event->accept();
}

}  // namespace ensil::ui
