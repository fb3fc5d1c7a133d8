// The whole state of a session, as one value: what is shown (the data, or the demo), the
// isovalue, the clusters, every rendering setting, the camera, the cutting plane, which members
// are hidden and selected, and the window layout. A project file (.ensil) is its serialisation
// (project_file.h); the command line builds one (setting_options.h); headless rendering draws
// one; the workbench keeps its panels in step with one. Every scalar setting in it is defined
// once, with its range and names, in setting_table.h. A plain value; any thread.
#pragma once

#include <QByteArray>
#include <algorithm>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "data/demo_ensemble.h"
#include "data/ensemble_reader.h"
#include "gl/render_settings.h"
#include "preprocessing/clustering.h"

namespace ensil::session {

struct CameraState {
    float azimuth = -75.0F;   // degrees
    float elevation = 30.0F;  // degrees
    bool orthographic = false;
    // Where the camera stands: none means "fitted to the data box" (what the workbench's Reset
    // Camera does); set once a user moved it, or a picture was drawn.
    struct Placement {
        float distance = 3.0F;
        glm::vec3 target{0.5F};
        bool operator==(const Placement&) const = default;
    };
    std::optional<Placement> placement;
};

// The clusters data open with when none are asked for: 5, and no more than about half the
// members, since a cluster of one member says nothing of where members agree (4 members: 2,
// 6: 3, 10 or more: 5). The workbench, `ensil preprocess`, `ensil render` and Python share it.
inline int defaultClusters(int members) { return std::clamp((members + 1) / 2, 1, 5); }

// Where the Sections dock's map and cross-section lie (engine/section_place.h reads the texts),
// as the user typed them; empty: where the members' contours are (engine::defaultSections).
struct SectionPlaces {
    enum class Cross { Latitude, Longitude, Path };
    std::string level;  // "500 hPa", "index:3"
    Cross crossKind = Cross::Latitude;
    std::string cross;  // "45N", "10W", "-10,50:20,40"
    bool operator==(const SectionPlaces&) const = default;
};

// What fills the maps and cross-sections (the setting "sections_fill").
enum class SectionsFill { Mean, Spread, Probability, SelectedMember, SelectedAnomaly, None };

// How the fill is coloured (the settings "sections_colour_map", "sections_fixed_range",
// "sections_range_min" and "sections_range_max"). Automatic picks the map by the fill: viridis
// for values, RdBu centred on zero for differences from the mean, YlGnBu for probabilities.
// Without a fixed range the colour bar spans the shown section's own values (a difference:
// symmetric about 0; a probability: 0 to 1).
enum class SectionsColourMap { Automatic, Viridis, Greys, RdBu, YlGnBu };
struct SectionsColours {
    SectionsColourMap map = SectionsColourMap::Automatic;
    bool fixedRange = false;
    double minimum = 0.0;  // the fixed range, in the variable's units
    double maximum = 1.0;
    bool operator==(const SectionsColours&) const = default;
};

struct SessionState {
    // Either the built-in demo (with its parameters) or files; paths are absolute in memory.
    bool demo = false;
    data::DemoEnsembleParams demoParams;
    data::DataSelection data;
    std::optional<float> isovalue;  // none: the variable's default (METHODS.md section 14)
    CameraState camera;
    gl::RenderSettings render;
    float verticalExaggeration = 1.0F;
    glm::vec3 background{0.11F, 0.12F, 0.14F};
    int clusters = 5;
    prep::Linkage linkage = prep::Linkage::Average;
    std::vector<int> hiddenMembers;
    std::vector<int> hiddenClusters;
    // Each member's cluster by its number when the project was saved (the stable identity + 1,
    // METHODS.md "Numbers of members and clusters"), so that reopening numbers and colours the
    // clusters as they were, whatever the isovalue, k and linkage changes before saving made of
    // them. Empty: numbered from the tree. Projects keep it; the undo history does not.
    std::vector<int> memberClusters;
    std::vector<int> selection;
    SectionPlaces sections;
    SectionsFill sectionsFill = SectionsFill::Mean;
    SectionsColours sectionsColours;
    QByteArray windowGeometry;  // QMainWindow::saveGeometry / saveState, kept as they are
    QByteArray windowState;
};

}  // namespace ensil::session
