#include "widgets/render_panel.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QSignalBlocker>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "widgets/setting_controls.h"

namespace ensil::ui {
namespace {
// Enough decimals to step through a hundredth of the range.
int decimalsFor(double span) {
    return std::clamp(static_cast<int>(std::ceil(-std::log10(std::max(span, 1e-12) / 100.0))), 0,
                      6);
}

// A control's row in a form: a check box carries its own label.
void addRow(QFormLayout& form, const SettingControl& control) {
    if (control.labelsItself()) {
        form.addRow(control.widget());
    } else {
        form.addRow(settingLabel(control.setting().id), control.widget());
    }
}
}  // namespace

RenderPanel::RenderPanel(QWidget* parent) : QWidget(parent) {
    // How members are drawn. The choices' words, in the setting table's order.
    auto* form = new QFormLayout;
    SettingControl* mode = add("mode", this,
                               {{tr("Shaded silhouettes"), tr("3D spaghetti plot"),
                                 tr("Semi-transparent surfaces"), tr("Opaque surfaces")}});
    addRow(*form, *mode);
    addRow(*form, *add("thickness", this));
    addRow(*form, *add("surface_opacity", this));
    // The context surface and its opacity in one row: the panel shares its dock's height.
    SettingControl* mean = add("show_mean", this);
    SettingControl* meanOpacity = add("mean_opacity", this);
    numberBox("mean_opacity")->setPrefix(tr("opacity "));
    form->addRow(mean->widget(), meanOpacity->widget());
    addRow(
        *form,
        *add("context", this,
             {{tr("Mean member"), tr("Median member (deepest)"), tr("Half the members exceed")}}));
    addRow(*form, *add("context_spread", this));
    addRow(*form, *add("band", this));

    // Density-based removal: a group its flag switches on. The thresholds' range follows the
    // outlyingness of the meshes on screen (setOutlyingnessRange).
    SettingControl* removal = add("removal", this, {{}, /*group=*/true});
    auto* removalForm = new QFormLayout(removal->widget());
    for (const char* id : {"removal_min", "removal_max"}) {
        addRow(*removalForm, *add(id, removal->widget()));
        numberBox(id)->setRange(0.0, 1.0);
    }
    addRow(*removalForm, *add("group_size", removal->widget()));

    // The scene.
    auto* sceneForm = new QFormLayout;
    addRow(*sceneForm, *add("vertical_exaggeration", this));
    numberBox("vertical_exaggeration")->setKeyboardTracking(false);  // re-meshes: once typed
    addRow(*sceneForm, *add("vertical_axis", this,
                            {{tr("Log-pressure"), tr("Pressure"), tr("Standard height")}}));
    addRow(*sceneForm, *add("projection", this, {{tr("Perspective"), tr("Orthographic")}}));
    for (const char* id : {"background", "axis_labels", "legend", "title", "rims"}) {
        addRow(*sceneForm, *add(id, this));
    }
    SettingControl* floor =
        add("floor", this,
            {{tr("Nothing"), tr("Mean's column maximum"), tr("Mean at a level"),
              tr("Spread's column maximum"), tr("Probability's column maximum")}});
    SettingControl* floorLevel = add("floor_level", this);
    qobject_cast<QSpinBox*>(floorLevel->widget())->setPrefix(tr("level "));
    auto* floorRow = new QHBoxLayout;
    floorRow->addWidget(floor->widget(), 1);
    floorRow->addWidget(floorLevel->widget());
    sceneForm->addRow(settingLabel("floor"), floorRow);

    // The map lines in one row: the three switches are short.
    auto* map = new QGroupBox(tr("Map"), this);
    map->setObjectName(QStringLiteral("map"));
    auto* mapRow = new QHBoxLayout(map);
    for (const char* id : {"coastlines", "borders", "graticule"}) {
        mapRow->addWidget(add(id, map)->widget());
    }

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(removal->widget());
    layout->addLayout(sceneForm);
    layout->addWidget(map);
    layout->addStretch(1);
    updateEnabled();
}

SettingControl* RenderPanel::add(std::string_view id, QWidget* parent,
                                 SettingControl::Options options) {
    auto* control = new SettingControl(id, parent, std::move(options));
    m_controls.push_back(control);
    connect(control, &SettingControl::edited, this, [this, id] {
        if (id == "removal_min" || id == "removal_max") keepRemovalBandOrdered(id == "removal_min");
        updateEnabled();
        emit edited();
    });
    return control;
}

SettingControl* RenderPanel::control(std::string_view id) const {
    const auto found = std::find_if(m_controls.begin(), m_controls.end(),
                                    [id](auto* c) { return c->setting().id == id; });
    return found == m_controls.end() ? nullptr : *found;
}

QDoubleSpinBox* RenderPanel::numberBox(std::string_view id) const {
    return qobject_cast<QDoubleSpinBox*>(control(id)->widget());
}

void RenderPanel::showSession(const session::SessionState& state) {
    for (SettingControl* c : m_controls) c->showValue(c->setting().get(state));
    updateEnabled();
}

void RenderPanel::applyTo(session::SessionState& state) const {
    for (const SettingControl* c : m_controls) c->applyTo(state);
}

// Not const though it could be: it changes what the panel shows (through its controls).
void RenderPanel::setMode(gl::RenderMode mode) {  // NOLINT(readability-make-member-function-const)
    qobject_cast<QComboBox*>(control("mode")->widget())->setCurrentIndex(static_cast<int>(mode));
}

// The thresholds keep o*min below o*max by pushing the other one along.
void RenderPanel::keepRemovalBandOrdered(bool minimumMoved) {
    QDoubleSpinBox* lower = numberBox("removal_min");
    QDoubleSpinBox* upper = numberBox("removal_max");
    if (lower->value() < upper->value()) return;
    if (minimumMoved) {
        const QSignalBlocker block(upper);
        upper->setValue(std::min(lower->value() + lower->singleStep(), upper->maximum()));
    } else {
        const QSignalBlocker block(lower);
        lower->setValue(std::max(upper->value() - upper->singleStep(), 0.0));
    }
}

bool RenderPanel::setOutlyingnessRange(double maximum, const QString& unitsSquared) {
    maximum = std::max(maximum, 1e-9);
    QDoubleSpinBox* lower = numberBox("removal_min");
    QDoubleSpinBox* upper = numberBox("removal_max");
    const bool firstRange = upper->maximum() <= 1.0 && upper->value() == 1.0;
    // Values beyond the new range are kept as they are (a project's), never clamped.
    const double held = std::max(lower->value(), upper->value());
    for (QDoubleSpinBox* box : {lower, upper}) {
        const QSignalBlocker block(box);
        box->setDecimals(decimalsFor(maximum));
        box->setMaximum(firstRange ? maximum : std::max(maximum, held));
        box->setSingleStep(maximum / 100.0);
        box->setSuffix(unitsSquared.isEmpty() ? QString() : QLatin1Char(' ') + unitsSquared);
    }
    if (firstRange) {
        // A first sensible band: the lower half, where members agree most.
        const QSignalBlocker b1(lower), b2(upper);
        lower->setValue(0.0);
        upper->setValue(maximum / 2.0);
    }
    return firstRange;
}

void RenderPanel::updateEnabled() {  // NOLINT(readability-make-member-function-const): as setMode
    const auto mode = static_cast<gl::RenderMode>(control("mode")->value());
    const bool silhouettes =
        mode == gl::RenderMode::ShadedSilhouettes || mode == gl::RenderMode::Spaghetti;
    const bool mean = control("show_mean")->value() != 0.0;
    control("thickness")->widget()->setEnabled(silhouettes);
    control("surface_opacity")->widget()->setEnabled(mode == gl::RenderMode::Surfaces);
    control("mean_opacity")->widget()->setEnabled(mean);
    control("context")->widget()->setEnabled(mean);
    control("floor_level")
        ->widget()
        ->setEnabled(control("floor")->value() == static_cast<int>(gl::FloorContent::MeanAtLevel));
    control("removal")->widget()->setEnabled(mode != gl::RenderMode::OpaqueSurfaces);
}

}  // namespace ensil::ui
