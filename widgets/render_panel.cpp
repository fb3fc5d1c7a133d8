#include "widgets/render_panel.h"

#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QPixmap>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QToolButton>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <utility>

#include "widgets/setting_controls.h"

namespace ensil::ui {
namespace {
// Enough decimals to step through a hundredth of the range.
int decimalsFor(double span) {
    return std::clamp(static_cast<int>(std::ceil(-std::log10(std::max(span, 1e-12) / 100.0))), 0,
                      6);
}
}  // namespace

RenderPanel::RenderPanel(QWidget* parent)
    : QWidget(parent),
      m_mode(new QComboBox(this)),
      m_thickness(new QDoubleSpinBox(this)),
      m_opacity(new QDoubleSpinBox(this)),
      m_mean(new QCheckBox(tr("Show the context surface"), this)),
      m_meanOpacity(new QDoubleSpinBox(this)),
      m_context(new QComboBox(this)),
      m_band(new QCheckBox(tr("Contour boxplot: 50 % band, outliers dashed"), this)),
      m_contextSpread(new QCheckBox(tr("Colour the context by the spread"), this)),
      m_axes(new QCheckBox(tr("Axis labels"), this)),
      m_legend(new QCheckBox(tr("Cluster legend"), this)),
      m_rims(new QCheckBox(tr("Rims where surfaces meet the box"), this)),
      m_floor(new QComboBox(this)),
      m_floorLevel(new QSpinBox(this)),
      m_map(new QGroupBox(tr("Map"), this)),
      m_coastlines(new QCheckBox(tr("Coasts"), m_map)),
      m_borders(new QCheckBox(tr("Borders"), m_map)),
      m_graticule(new QCheckBox(tr("Graticule"), m_map)),
      m_removal(new QGroupBox(tr("Density-based removal"), this)),
      m_removalMin(new QDoubleSpinBox(m_removal)),
      m_removalMax(new QDoubleSpinBox(m_removal)),
      m_groupSize(new QSpinBox(m_removal)),
      m_exaggeration(new QDoubleSpinBox(this)),
      m_projection(new QComboBox(this)),
      m_backgroundButton(new QToolButton(this)) {
    for (auto [widget, name] : std::initializer_list<std::pair<QWidget*, const char*>>{
             {m_mode, "mode"},
             {m_thickness, "thickness"},
             {m_opacity, "opacity"},
             {m_mean, "mean"},
             {m_meanOpacity, "meanOpacity"},
             {m_context, "context"},
             {m_band, "band"},
             {m_contextSpread, "contextSpread"},
             {m_axes, "axes"},
             {m_legend, "legend"},
             {m_rims, "rims"},
             {m_floor, "floor"},
             {m_floorLevel, "floorLevel"},
             {m_map, "map"},
             {m_coastlines, "coastlines"},
             {m_borders, "borders"},
             {m_graticule, "graticule"},
             {m_removal, "removal"},
             {m_removalMin, "removalMin"},
             {m_removalMax, "removalMax"},
             {m_groupSize, "groupSize"},
             {m_exaggeration, "exaggeration"},
             {m_projection, "projection"},
             {m_backgroundButton, "background"}}) {
        widget->setObjectName(QLatin1String(name));
    }
    auto* form = new QFormLayout;
    m_mode->addItems({tr("Shaded silhouettes"), tr("3D spaghetti plot"),
                      tr("Semi-transparent surfaces"), tr("Opaque surfaces")});
    m_mode->setToolTip(tr("How members are drawn (keys 1 to 4 in the view)"));
    form->addRow(tr("Mode"), m_mode);
    shapeBySetting(*m_thickness, "thickness");
    form->addRow(tr("Thickness \u03c4"), m_thickness);
    shapeBySetting(*m_opacity, "surface_opacity");
    form->addRow(tr("Surface opacity"), m_opacity);
    m_mean->setToolTip(settingHelp("show_mean"));
    shapeBySetting(*m_meanOpacity, "mean_opacity");
    m_meanOpacity->setToolTip(settingHelp("mean_opacity"));
    m_meanOpacity->setPrefix(tr("opacity "));
    form->addRow(m_mean, m_meanOpacity);  // one row: the panel shares its dock's height
    // In gl::ContextSurface's order.
    m_context->addItems(
        {tr("Mean member"), tr("Median member (deepest)"), tr("Half the members exceed")});
    m_context->setToolTip(settingHelp("context"));
    form->addRow(tr("Context"), m_context);
    m_contextSpread->setToolTip(settingHelp("context_spread"));
    form->addRow(m_contextSpread);
    m_band->setToolTip(settingHelp("band"));
    form->addRow(m_band);

    m_removal->setCheckable(true);
    m_removal->setToolTip(settingHelp("removal"));
    auto* removalForm = new QFormLayout(m_removal);
    for (QDoubleSpinBox* box : {m_removalMin, m_removalMax}) box->setRange(0.0, 1.0);
    removalForm->addRow(tr("o*min"), m_removalMin);
    removalForm->addRow(tr("o*max"), m_removalMax);
    shapeBySetting(*m_groupSize, "group_size");
    removalForm->addRow(tr("Group size s_G"), m_groupSize);

    auto* sceneForm = new QFormLayout;
    shapeBySetting(*m_exaggeration, "vertical_exaggeration");
    m_exaggeration->setValue(1.0);
    m_exaggeration->setKeyboardTracking(false);
    sceneForm->addRow(tr("Vertical exaggeration"), m_exaggeration);
    m_projection->addItems({tr("Perspective"), tr("Orthographic")});
    sceneForm->addRow(tr("Projection"), m_projection);
    m_backgroundButton->setToolTip(tr("Choose the view's background colour"));
    sceneForm->addRow(tr("Background"), m_backgroundButton);
    m_axes->setToolTip(settingHelp("axis_labels"));
    sceneForm->addRow(m_axes);
    m_legend->setToolTip(settingHelp("legend"));
    sceneForm->addRow(m_legend);
    m_rims->setToolTip(settingHelp("rims"));
    sceneForm->addRow(m_rims);
    m_floor->addItems({tr("Nothing"), tr("Mean's column maximum"), tr("Mean at a level"),
                       tr("Spread's column maximum"), tr("Probability's column maximum")});
    m_floor->setToolTip(settingHelp("floor"));
    shapeBySetting(*m_floorLevel, "floor_level");
    m_floorLevel->setToolTip(settingHelp("floor_level"));
    m_floorLevel->setPrefix(tr("level "));
    auto* floorRow = new QHBoxLayout;
    floorRow->addWidget(m_floor, 1);
    floorRow->addWidget(m_floorLevel);
    sceneForm->addRow(tr("Floor"), floorRow);

    // One row: the three switches are short, and the panel shares its dock's height.
    auto* mapLayout = new QHBoxLayout(m_map);
    for (auto [box, setting] :
         {std::pair{m_coastlines, "coastlines"}, std::pair{m_borders, "borders"},
          std::pair{m_graticule, "graticule"}}) {
        box->setToolTip(settingHelp(setting));
        mapLayout->addWidget(box);
    }

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_removal);
    layout->addLayout(sceneForm);
    layout->addWidget(m_map);
    layout->addStretch(1);

    setSettings(gl::RenderSettings{});
    setBackground(QColor::fromRgbF(0.11F, 0.12F, 0.14F));

    const auto edited = [this] {
        updateEnabled();
        emit settingsEdited();
    };
    connect(m_mode, &QComboBox::currentIndexChanged, this, edited);
    connect(m_thickness, &QDoubleSpinBox::valueChanged, this, edited);
    connect(m_opacity, &QDoubleSpinBox::valueChanged, this, edited);
    connect(m_meanOpacity, &QDoubleSpinBox::valueChanged, this, edited);
    connect(m_mean, &QCheckBox::toggled, this, edited);  // also enables the mean's opacity
    connect(m_axes, &QCheckBox::toggled, this, edited);
    connect(m_legend, &QCheckBox::toggled, this, edited);
    connect(m_context, &QComboBox::currentIndexChanged, this, edited);
    connect(m_band, &QCheckBox::toggled, this, edited);
    connect(m_contextSpread, &QCheckBox::toggled, this, edited);
    connect(m_rims, &QCheckBox::toggled, this, edited);
    for (QCheckBox* box : {m_coastlines, m_borders, m_graticule}) {
        connect(box, &QCheckBox::toggled, this, edited);
    }
    connect(m_floor, &QComboBox::currentIndexChanged, this, edited);
    connect(m_floorLevel, &QSpinBox::valueChanged, this, edited);
    connect(m_removal, &QGroupBox::toggled, this, edited);
    connect(m_groupSize, &QSpinBox::valueChanged, this, edited);
    // The thresholds keep o*min below o*max by pushing the other one along.
    connect(m_removalMin, &QDoubleSpinBox::valueChanged, this, [this, edited](double v) {
        if (m_removalMax->value() <= v) {
            const QSignalBlocker block(m_removalMax);
            m_removalMax->setValue(
                std::min(v + m_removalMin->singleStep(), m_removalMax->maximum()));
        }
        edited();
    });
    connect(m_removalMax, &QDoubleSpinBox::valueChanged, this, [this, edited](double v) {
        if (m_removalMin->value() >= v) {
            const QSignalBlocker block(m_removalMin);
            m_removalMin->setValue(std::max(v - m_removalMax->singleStep(), 0.0));
        }
        edited();
    });
    connect(m_exaggeration, &QDoubleSpinBox::valueChanged, this,
            &RenderPanel::verticalExaggerationChanged);
    connect(m_projection, &QComboBox::currentIndexChanged, this,
            [this](int index) { emit projectionChanged(index == 1); });
    connect(m_backgroundButton, &QToolButton::clicked, this, &RenderPanel::chooseBackground);
}

void RenderPanel::setSettings(const gl::RenderSettings& settings) {
    const QSignalBlocker b1(m_mode), b2(m_thickness), b3(m_opacity), b4(m_mean), b5(m_removal),
        b6(m_removalMin), b7(m_removalMax), b8(m_groupSize), b9(m_axes), b10(m_legend),
        b11(m_coastlines), b12(m_borders), b13(m_graticule), b14(m_meanOpacity), b15(m_floor),
        b16(m_floorLevel), b17(m_rims), b18(m_context), b19(m_band), b20(m_contextSpread);
    m_floor->setCurrentIndex(static_cast<int>(settings.floor));
    m_floorLevel->setValue(settings.floorLevel);
    m_meanOpacity->setValue(settings.meanOpacity);
    m_coastlines->setChecked(settings.showCoastlines);
    m_borders->setChecked(settings.showBorders);
    m_graticule->setChecked(settings.showGraticule);
    m_axes->setChecked(settings.showAxes);
    m_legend->setChecked(settings.showLegend);
    m_rims->setChecked(settings.showRims);
    m_context->setCurrentIndex(static_cast<int>(settings.context));
    m_band->setChecked(settings.showBand);
    m_contextSpread->setChecked(settings.contextBySpread);
    m_mode->setCurrentIndex(static_cast<int>(settings.mode));
    m_thickness->setValue(settings.thickness);
    m_opacity->setValue(settings.surfaceAlpha);
    m_mean->setChecked(settings.showMean);
    m_removal->setChecked(settings.removal);
    // Widen the ranges if needed, so the values are shown as they are.
    for (QDoubleSpinBox* box : {m_removalMin, m_removalMax}) {
        box->setMaximum(
            std::max({box->maximum(), double(settings.removalMin), double(settings.removalMax)}));
    }
    m_removalMin->setValue(settings.removalMin);
    m_removalMax->setValue(settings.removalMax);
    m_groupSize->setValue(settings.groupSize);
    updateEnabled();
}

gl::RenderSettings RenderPanel::applyTo(gl::RenderSettings settings) const {
    settings.mode = static_cast<gl::RenderMode>(m_mode->currentIndex());
    settings.thickness = static_cast<float>(m_thickness->value());
    settings.surfaceAlpha = static_cast<float>(m_opacity->value());
    settings.showMean = m_mean->isChecked();
    settings.meanOpacity = static_cast<float>(m_meanOpacity->value());
    settings.showAxes = m_axes->isChecked();
    settings.showLegend = m_legend->isChecked();
    settings.showRims = m_rims->isChecked();
    settings.context = static_cast<gl::ContextSurface>(m_context->currentIndex());
    settings.showBand = m_band->isChecked();
    settings.contextBySpread = m_contextSpread->isChecked();
    settings.showCoastlines = m_coastlines->isChecked();
    settings.showBorders = m_borders->isChecked();
    settings.showGraticule = m_graticule->isChecked();
    settings.floor = static_cast<gl::FloorContent>(m_floor->currentIndex());
    settings.floorLevel = m_floorLevel->value();
    settings.removal = m_removal->isChecked();
    settings.removalMin = static_cast<float>(m_removalMin->value());
    settings.removalMax = static_cast<float>(m_removalMax->value());
    settings.groupSize = m_groupSize->value();
    return settings;
}

void RenderPanel::setMode(gl::RenderMode mode) { m_mode->setCurrentIndex(static_cast<int>(mode)); }

bool RenderPanel::setOutlyingnessRange(double maximum, const QString& unitsSquared) {
    maximum = std::max(maximum, 1e-9);
    const bool firstRange = m_removalMax->maximum() <= 1.0 && m_removalMax->value() == 1.0;
    // Values beyond the new range are kept as they are (a project's), never clamped.
    const double held = std::max(m_removalMin->value(), m_removalMax->value());
    for (QDoubleSpinBox* box : {m_removalMin, m_removalMax}) {
        const QSignalBlocker block(box);
        box->setDecimals(decimalsFor(maximum));
        box->setMaximum(firstRange ? maximum : std::max(maximum, held));
        box->setSingleStep(maximum / 100.0);
        box->setSuffix(unitsSquared.isEmpty() ? QString() : QLatin1Char(' ') + unitsSquared);
    }
    if (firstRange) {
        // A first sensible band: the lower half, where members agree most.
        const QSignalBlocker b1(m_removalMin), b2(m_removalMax);
        m_removalMin->setValue(0.0);
        m_removalMax->setValue(maximum / 2.0);
    }
    return firstRange;
}

void RenderPanel::setVerticalExaggeration(double factor) {
    const QSignalBlocker block(m_exaggeration);
    m_exaggeration->setValue(factor);
}

double RenderPanel::verticalExaggeration() const { return m_exaggeration->value(); }

void RenderPanel::setOrthographic(bool orthographic) {
    const QSignalBlocker block(m_projection);
    m_projection->setCurrentIndex(orthographic ? 1 : 0);
}

bool RenderPanel::orthographic() const { return m_projection->currentIndex() == 1; }

void RenderPanel::setBackground(const QColor& colour) {
    m_background = colour;
    showBackground();
}

void RenderPanel::chooseBackground() {
    const QColor chosen = QColorDialog::getColor(m_background, this, tr("Background"));
    if (!chosen.isValid() || chosen == m_background) return;
    setBackground(chosen);
    emit backgroundChanged(chosen);
}

void RenderPanel::showBackground() {
    QPixmap swatch(32, 16);
    swatch.fill(m_background);
    m_backgroundButton->setIcon(QIcon(swatch));
    m_backgroundButton->setIconSize(swatch.size());
    m_backgroundButton->setText(m_background.name());
    m_backgroundButton->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
}

void RenderPanel::updateEnabled() {
    const auto mode = static_cast<gl::RenderMode>(m_mode->currentIndex());
    const bool silhouettes =
        mode == gl::RenderMode::ShadedSilhouettes || mode == gl::RenderMode::Spaghetti;
    m_thickness->setEnabled(silhouettes);
    m_opacity->setEnabled(mode == gl::RenderMode::Surfaces);
    m_meanOpacity->setEnabled(m_mean->isChecked());
    m_context->setEnabled(m_mean->isChecked());
    m_floorLevel->setEnabled(m_floor->currentIndex() ==
                             static_cast<int>(gl::FloorContent::MeanAtLevel));
    m_removal->setEnabled(mode != gl::RenderMode::OpaqueSurfaces);
}

}  // namespace ensil::ui
