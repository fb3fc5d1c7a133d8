// The rendering panel: how members are drawn (mode, silhouette thickness tau, surface opacity,
// the context surface, the contour boxplot), density-based silhouette removal (o*_min, o*_max,
// group size s_G), and the scene (vertical exaggeration, projection, background, axis labels,
// legend, title, rims, floor, map lines). It is made from a list of the setting table's ids,
// one SettingControl each (widgets/setting_controls.h), so a new setting shows here by adding
// its id to that list. It shows a session's values and writes its own into a session; it knows
// nothing of the renderer. GUI thread only.
#pragma once

#include <QWidget>
#include <string_view>
#include <vector>

#include "gl/render_settings.h"
#include "session/session_state.h"
#include "widgets/setting_controls.h"

class QDoubleSpinBox;

namespace ensil::ui {

class RenderPanel : public QWidget {
    Q_OBJECT
public:
    explicit RenderPanel(QWidget* parent = nullptr);

    // Shows the session's values of the panel's settings without emitting anything.
    void showSession(const session::SessionState& state);
    // Writes the panel's values into `state` (every setting it shows; nothing else).
    void applyTo(session::SessionState& state) const;

    // Switches the mode as the user would (emits edited).
    void setMode(gl::RenderMode mode);

    // The largest outlyingness of the meshes on screen, in the variable's units squared: the
    // removal thresholds range over [0, maximum] (wider when they hold larger values). The
    // first range also sets a first band, the lower half: returns true then (applyTo() writes
    // thresholds that differ from the session last shown).
    bool setOutlyingnessRange(double maximum, const QString& unitsSquared);

    // The control of a setting the panel shows; nullptr for one it does not.
    [[nodiscard]] SettingControl* control(std::string_view id) const;

signals:
    void edited();  // the user changed one of the panel's settings

private:
    SettingControl* add(std::string_view id, QWidget* parent, SettingControl::Options options = {});
    [[nodiscard]] QDoubleSpinBox* numberBox(std::string_view id) const;
    void keepRemovalBandOrdered(bool minimumMoved);
    void updateEnabled();

    std::vector<SettingControl*> m_controls;
};

}  // namespace ensil::ui
