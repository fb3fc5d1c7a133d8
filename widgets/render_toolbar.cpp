#include "widgets/render_toolbar.h"

#include <QDoubleSpinBox>
#include <QLabel>
#include <QSignalBlocker>
#include <QSpinBox>
#include <algorithm>

#include "widgets/isovalue_control.h"

namespace ensil::ui {

RenderToolbar::RenderToolbar(QWidget* parent)
    : QToolBar(tr("Isovalue and clusters"), parent),
      m_isovalue(new IsovalueControl(this)),
      m_clusters(new QSpinBox(this)) {
    setObjectName(QStringLiteral("renderToolbar"));
    addWidget(new QLabel(tr(" Isovalue "), this));
    m_isovalue->setMinimumWidth(320);
    addWidget(m_isovalue);
    addSeparator();
    addWidget(new QLabel(tr(" Clusters "), this));
    m_clusters->setRange(1, 1);
    m_clusters->setToolTip(
        tr("Number of clusters members are coloured by (or drag the dendrogram's cut line)"));
    addWidget(m_clusters);

    // Preprocessing starts when the user commits a value, not on every keystroke or drag step.
    connect(m_isovalue, &IsovalueControl::isovalueChanged, this, &RenderToolbar::isovalueChanged);
    connect(m_isovalue, &IsovalueControl::isovalueScrubbed, this, &RenderToolbar::isovalueScrubbed);
    connect(m_isovalue, &IsovalueControl::scrubEnded, this, &RenderToolbar::isovalueScrubEnded);
    connect(m_clusters, &QSpinBox::valueChanged, this, &RenderToolbar::clusterCountChanged);
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

double RenderToolbar::isovalue() const { return m_isovalue->value(); }
QDoubleSpinBox* RenderToolbar::isovalueBox() const { return m_isovalue->spinBox(); }
int RenderToolbar::clusterCount() const { return m_clusters->value(); }

}  // namespace ensil::ui
