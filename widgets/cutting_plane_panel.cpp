#include "widgets/cutting_plane_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <algorithm>
#include <cmath>
#include <limits>

#include "widgets/setting_controls.h"

namespace ensil::ui {
namespace {
// Linear interpolation of ys over xs at x; xs monotone (either way), clamped at the ends.
double interpolate(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
    if (xs.empty() || xs.size() != ys.size()) return std::numeric_limits<double>::quiet_NaN();
    if (xs.size() == 1) return ys.front();
    const bool increasing = xs.back() > xs.front();
    std::size_t i = 1;
    while (i + 1 < xs.size() && (increasing ? xs[i] < x : xs[i] > x)) ++i;
    const double x0 = xs[i - 1], x1 = xs[i];
    const double t = x1 == x0 ? 0.0 : std::clamp((x - x0) / (x1 - x0), 0.0, 1.0);
    return ys[i - 1] + t * (ys[i] - ys[i - 1]);
}
}  // namespace

double axisValueAt(const PlaneAxis& axis, double position) {
    return interpolate(axis.positions, axis.values, position);
}

double axisPositionOf(const PlaneAxis& axis, double value) {
    return interpolate(axis.values, axis.positions, value);
}

CuttingPlanePanel::CuttingPlanePanel(QWidget* parent)
    : QWidget(parent),
      m_enabled(new QCheckBox(tr("Cut the scene"), this)),
      m_orientation(new QComboBox(this)),
      m_position(new QSlider(Qt::Horizontal, this)),
      m_dataValue(new QDoubleSpinBox(this)),
      m_dataLabel(new QLabel(this)),
      m_thickness(new QDoubleSpinBox(this)),
      m_fill(new QComboBox(this)) {
    m_enabled->setToolTip(
        tr("Removes everything between the plane and the camera and draws where each member "
           "crosses the plane (Ctrl+Shift+P)"));
    m_orientation->addItems(
        {tr("Across x (east)"), tr("Across y (north)"), tr("Across z (up)"), tr("Free normal")});
    m_orientation->setCurrentIndex(AlongZ);
    auto* normalRow = new QHBoxLayout;
    const glm::vec3 initial{0.0F, 0.0F, 1.0F};
    for (int i = 0; i < 3; ++i) {
        m_normal[i] = new QDoubleSpinBox(this);
        m_normal[i]->setObjectName(QStringLiteral("normal") + QStringLiteral("XYZ").mid(i, 1));
        m_normal[i]->setRange(-1.0, 1.0);
        m_normal[i]->setDecimals(2);
        m_normal[i]->setSingleStep(0.1);
        m_normal[i]->setValue(initial[i]);
        m_normal[i]->setPrefix(QStringLiteral("xyz").mid(i, 1) + QStringLiteral(" "));
        normalRow->addWidget(m_normal[i]);
        connect(m_normal[i], &QDoubleSpinBox::valueChanged, this,
                &CuttingPlanePanel::onNormalEdited);
    }
    m_position->setObjectName(QStringLiteral("position"));
    m_dataValue->setObjectName(QStringLiteral("dataValue"));
    m_thickness->setObjectName(QStringLiteral("curveWidth"));
    m_position->setRange(-kSliderSteps, kSliderSteps);
    m_position->setPageStep(kSliderSteps / 10);
    m_position->setToolTip(tr("Where the plane lies across the data box"));
    m_dataValue->setKeyboardTracking(false);
    m_dataValue->setToolTip(tr("The plane's position in the axis's units"));
    shapeBySetting(*m_thickness, "plane_thickness");
    m_thickness->setValue(gl::CuttingPlane{}.thickness);

    // In gl::SectionField's order.
    m_fill->addItems({tr("Nothing"), tr("Member (selected, else last hovered)"), tr("Mean"),
                      tr("Standard deviation"), tr("P(f > isovalue)")});
    m_fill->setObjectName(QStringLiteral("fill"));
    m_fill->setToolTip(settingHelp("section"));

    auto* form = new QFormLayout(this);
    form->addRow(m_enabled);
    form->addRow(tr("Orientation"), m_orientation);
    form->addRow(tr("Normal"), normalRow);
    form->addRow(tr("Position"), m_position);
    auto* valueRow = new QHBoxLayout;
    valueRow->addWidget(m_dataValue, 1);
    form->addRow(m_dataLabel, valueRow);
    form->addRow(tr("Curve width \u03b5"), m_thickness);
    form->addRow(tr("Fill"), m_fill);

    connect(m_enabled, &QCheckBox::toggled, this, &CuttingPlanePanel::planeChanged);
    connect(m_orientation, &QComboBox::currentIndexChanged, this,
            &CuttingPlanePanel::onOrientationChosen);
    connect(m_position, &QSlider::valueChanged, this, &CuttingPlanePanel::onSliderMoved);
    connect(m_dataValue, &QDoubleSpinBox::valueChanged, this,
            &CuttingPlanePanel::onDataValueEdited);
    connect(m_thickness, &QDoubleSpinBox::valueChanged, this, &CuttingPlanePanel::planeChanged);
    // A fill is seen only on a cut: choosing one turns the cut on, in the same change.
    connect(m_fill, &QComboBox::currentIndexChanged, this, [this](int index) {
        if (index > 0 && !m_enabled->isChecked()) {
            const QSignalBlocker block(m_enabled);
            m_enabled->setChecked(true);
        }
        emit planeChanged();
    });
    onOrientationChosen(AlongZ);
}

void CuttingPlanePanel::setBox(const glm::vec3& boxMin, const glm::vec3& boxMax,
                               std::array<PlaneAxis, 3> axes) {
    m_boxMin = boxMin;
    m_boxMax = boxMax;
    m_axes = std::move(axes);
    showPosition();
}

glm::vec3 CuttingPlanePanel::normal() const {
    const glm::vec3 n(m_normal[0]->value(), m_normal[1]->value(), m_normal[2]->value());
    return glm::length(n) > 0.0F ? glm::normalize(n) : glm::vec3(0.0F, 0.0F, 1.0F);
}

const PlaneAxis* CuttingPlanePanel::alignedAxis() const {
    const int index = m_orientation->currentIndex();
    if (index == Free || m_axes[static_cast<std::size_t>(index)].positions.empty()) return nullptr;
    return &m_axes[static_cast<std::size_t>(index)];
}

gl::CuttingPlane CuttingPlanePanel::plane() const {
    gl::CuttingPlane plane =
        gl::CuttingPlane::acrossBox(normal(), static_cast<float>(position()), m_boxMin, m_boxMax);
    plane.enabled = m_enabled->isChecked();
    plane.thickness = static_cast<float>(m_thickness->value());
    plane.fill = static_cast<gl::SectionField>(std::max(m_fill->currentIndex(), 0));
    return plane;
}

void CuttingPlanePanel::setPlane(const gl::CuttingPlane& plane) {
    const QSignalBlocker b0(this);
    m_enabled->setChecked(plane.enabled);
    m_thickness->setValue(plane.thickness);
    m_fill->setCurrentIndex(static_cast<int>(plane.fill));
    int orientation = Free;
    for (int axis = 0; axis < 3; ++axis) {
        if (std::abs(std::abs(plane.normal[axis]) - 1.0F) < 1e-6F) orientation = axis;
    }
    {
        const QSignalBlocker b1(m_orientation);
        m_orientation->setCurrentIndex(orientation);
        for (int i = 0; i < 3; ++i) {
            const QSignalBlocker b2(m_normal[i]);
            m_normal[i]->setValue(plane.normal[i]);
            m_normal[i]->setEnabled(orientation == Free);
        }
    }
    const QSignalBlocker b3(m_position);
    m_position->setValue(
        static_cast<int>(std::lround(plane.positionAcross(m_boxMin, m_boxMax) * kSliderSteps)));
    showPosition();
}

void CuttingPlanePanel::setCutting(bool on) { m_enabled->setChecked(on); }

bool CuttingPlanePanel::cutting() const { return m_enabled->isChecked(); }

void CuttingPlanePanel::setOrientation(Orientation orientation) {
    m_orientation->setCurrentIndex(orientation);
}

void CuttingPlanePanel::setPosition(double position) {
    m_position->setValue(
        static_cast<int>(std::lround(std::clamp(position, -1.0, 1.0) * kSliderSteps)));
}

double CuttingPlanePanel::position() const {
    return static_cast<double>(m_position->value()) / kSliderSteps;
}

double CuttingPlanePanel::dataPosition() const {
    const PlaneAxis* axis = alignedAxis();
    return axis != nullptr ? axisValueAt(*axis, position())
                           : std::numeric_limits<double>::quiet_NaN();
}

void CuttingPlanePanel::onOrientationChosen(int index) {
    for (int i = 0; i < 3; ++i) {
        m_normal[i]->setEnabled(index == Free);
        if (index != Free) {
            const QSignalBlocker block(m_normal[i]);
            m_normal[i]->setValue(i == index ? 1.0 : 0.0);
        }
    }
    showPosition();
    emit planeChanged();
}

void CuttingPlanePanel::onNormalEdited() {
    if (m_orientation->currentIndex() != Free) return;
    emit planeChanged();
}

void CuttingPlanePanel::onSliderMoved(int /*value*/) {
    showPosition();
    emit planeChanged();
}

void CuttingPlanePanel::onDataValueEdited(double value) {
    const PlaneAxis* axis = alignedAxis();
    if (axis == nullptr) return;
    const QSignalBlocker block(m_position);
    m_position->setValue(
        static_cast<int>(std::lround(axisPositionOf(*axis, value) * kSliderSteps)));
    emit planeChanged();
}

void CuttingPlanePanel::showPosition() {
    const PlaneAxis* axis = alignedAxis();
    const QSignalBlocker block(m_dataValue);
    m_dataValue->setEnabled(axis != nullptr);
    if (axis == nullptr) {
        m_dataLabel->setText(tr("Across the box"));
        m_dataValue->setRange(-1.0, 1.0);
        m_dataValue->setDecimals(3);
        m_dataValue->setSuffix(QString());
        m_dataValue->setValue(position());
        return;
    }
    const auto [lo, hi] = std::minmax_element(axis->values.begin(), axis->values.end());
    const double span = std::max(*hi - *lo, 1e-12);
    m_dataLabel->setText(axis->name);
    m_dataValue->setDecimals(
        std::clamp(static_cast<int>(std::ceil(-std::log10(span / 1000.0))), 0, 6));
    m_dataValue->setRange(*lo, *hi);
    m_dataValue->setSingleStep(span / 100.0);
    m_dataValue->setSuffix(axis->units.isEmpty() ? QString() : QLatin1Char(' ') + axis->units);
    m_dataValue->setValue(axisValueAt(*axis, position()));
}

}  // namespace ensil::ui
