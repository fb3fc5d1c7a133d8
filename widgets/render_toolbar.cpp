#include "widgets/render_toolbar.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QSignalBlocker>
#include <QSpinBox>
#include <algorithm>

#include "widgets/isovalue_control.h"

namespace ensil::ui {

RenderToolbar::RenderToolbar(QWidget* parent)
    : QToolBar(tr("Rendering"), parent),
      m_isovalue(new IsovalueControl(this)),
      m_mode(new QComboBox(this)),
      m_thickness(new QDoubleSpinBox(this)),
      m_clusters(new QSpinBox(this)),
      m_mean(new QCheckBox(tr("Mean"), this)),
      m_exaggeration(new QDoubleSpinBox(this)) {
    setObjectName(QStringLiteral("renderToolbar"));
    addWidget(new QLabel(tr(" Isovalue "), this));
    m_isovalue->setMinimumWidth(320);
    addWidget(m_isovalue);
    addSeparator();
    m_mode->addItems({tr("Shaded silhouettes"), tr("3D spaghetti plot"), tr("Transparent surfaces"),
                      tr("Opaque surfaces")});
    m_mode->setToolTip(tr("How members are drawn"));
    addWidget(m_mode);
    addWidget(new QLabel(tr(" Thickness "), this));
    m_thickness->setRange(0.001, 0.5);
    m_thickness->setDecimals(3);
    m_thickness->setSingleStep(0.005);
    m_thickness->setToolTip(tr("Silhouette thickness (tau), in units of the data box width"));
    addWidget(m_thickness);
    addSeparator();
    addWidget(new QLabel(tr(" Clusters "), this));
    m_clusters->setRange(1, 1);
    m_clusters->setToolTip(tr("Number of clusters members are coloured by"));
    addWidget(m_clusters);
    m_mean->setChecked(true);
    m_mean->setToolTip(tr("Show the mean member's isosurface as a gray solid"));
    addWidget(m_mean);

    addSeparator();
    addWidget(new QLabel(tr(" Vertical x "), this));
    m_exaggeration->setRange(0.1, 50.0);
    m_exaggeration->setDecimals(1);
    m_exaggeration->setSingleStep(0.5);
    m_exaggeration->setValue(1.0);
    m_exaggeration->setKeyboardTracking(false);
    m_exaggeration->setToolTip(tr("Vertical exaggeration: stretches the vertical axis"));
    addWidget(m_exaggeration);

    connect(m_exaggeration, &QDoubleSpinBox::valueChanged, this,
            &RenderToolbar::verticalExaggerationChanged);
    // Preprocessing starts when the user commits a value, not on every keystroke or drag step.
    connect(m_isovalue, &IsovalueControl::isovalueChanged, this, &RenderToolbar::isovalueChanged);
    connect(m_mode, &QComboBox::currentIndexChanged, this, &RenderToolbar::modeChanged);
    connect(m_thickness, &QDoubleSpinBox::valueChanged, this, &RenderToolbar::thicknessChanged);
    connect(m_clusters, &QSpinBox::valueChanged, this, &RenderToolbar::clusterCountChanged);
    connect(m_mean, &QCheckBox::toggled, this, &RenderToolbar::meanToggled);
}

void RenderToolbar::setIsovalueRange(double minimum, double maximum, double value,
                                     const QString& units) {
    m_isovalue->setRange(minimum, maximum, value, units);
}

void RenderToolbar::setIsovalueHistogram(std::vector<std::uint64_t> counts) {
    m_isovalue->setHistogram(std::move(counts));
}

void RenderToolbar::setMemberCount(int members, int clusters) {
    const QSignalBlocker block(m_clusters);
    m_clusters->setRange(1, std::max(1, members));
    m_clusters->setValue(clusters);
}

void RenderToolbar::setThickness(double tau) {
    const QSignalBlocker block(m_thickness);
    m_thickness->setValue(tau);
}

double RenderToolbar::isovalue() const { return m_isovalue->value(); }
QDoubleSpinBox* RenderToolbar::isovalueBox() const { return m_isovalue->spinBox(); }
int RenderToolbar::clusterCount() const { return m_clusters->value(); }

}  // namespace ensil::ui
