#include "session/setting_table.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace ensil::session {
namespace {

constexpr std::array<std::string_view, 4> kModes{"shaded", "spaghetti", "surfaces", "opaque"};
constexpr std::array<std::string_view, 2> kProjections{"perspective", "orthographic"};
// In gl::FloorContent's order.
constexpr std::array<std::string_view, 5> kFloorContents{"none", "column-maximum", "mean-at-level",
                                                         "spread-maximum", "probability-maximum"};
// In gl::ContextSurface's order.
constexpr std::array<std::string_view, 3> kContextSurfaces{"mean", "median", "probability"};
// In gl::SectionField's order.
constexpr std::array<std::string_view, 5> kSectionFields{"none", "member", "mean", "stddev",
                                                         "probability"};
// In SectionsFill's order.
constexpr std::array<std::string_view, 6> kSectionsFills{"mean",   "spread",  "probability",
                                                         "member", "anomaly", "none"};
// In SectionsColourMap's order; the names matplotlib and ColorBrewer give them.
constexpr std::array<std::string_view, 5> kSectionsColourMaps{"automatic", "viridis", "greys",
                                                              "rdbu", "ylgnbu"};
// In data::VerticalAxis's order.
constexpr std::array<std::string_view, 3> kVerticalAxes{"log-pressure", "pressure", "height"};
// In prep::Linkage's order.
constexpr std::array<std::string_view, 4> kLinkages{"average", "single", "complete", "ward"};

float asFloat(double v) { return static_cast<float>(v); }

// The table. Ranges are what the method allows and a user could want, not what one widget
// happened to hold: the panels, projects and the command line all take them from here.
const std::array<Setting, 37> kSettings{{
    {"mode", SettingKind::Choice, "rendering.mode", "mode", "rendering/mode", "Mode", "",
     "How members are drawn: shaded silhouettes, 3D spaghetti plot, semi-transparent or opaque "
     "surfaces",
     0, 3, 0, 1, kModes, [](const SessionState& s) { return static_cast<double>(s.render.mode); },
     [](SessionState& s, double v) { s.render.mode = static_cast<gl::RenderMode>(v); }},
    {"thickness",
     SettingKind::Number,
     "rendering.thickness",
     "thickness",
     "rendering/thickness",
     "Thickness \u03c4",
     "",
     "Silhouette thickness tau, in units of the data box's width: thicker shows more of each "
     "member where it curves away",
     0.0001,
     0.5,
     4,
     0.001,
     {},
     [](const SessionState& s) { return double(s.render.thickness); },
     [](SessionState& s, double v) { s.render.thickness = asFloat(v); }},
    {"surface_opacity",
     SettingKind::Number,
     "rendering.surface_opacity",
     "surface-opacity",
     "rendering/opacity",
     "Surface opacity",
     "",
     "Opacity of each member in the semi-transparent surfaces mode",
     0.01,
     1.0,
     2,
     0.05,
     {},
     [](const SessionState& s) { return double(s.render.surfaceAlpha); },
     [](SessionState& s, double v) { s.render.surfaceAlpha = asFloat(v); }},
    {"show_mean",
     SettingKind::Flag,
     "rendering.show_mean",
     "mean",
     "rendering/mean",
     "Show the context surface",
     "",
     "The context surface (the mean member's isosurface unless Context surface says otherwise) "
     "in gray",
     0,
     1,
     0,
     1,
     {},
     [](const SessionState& s) { return s.render.showMean ? 1.0 : 0.0; },
     [](SessionState& s, double v) { s.render.showMean = v != 0.0; }},
    {"context", SettingKind::Choice, "rendering.context", "context", "rendering/context",
     "Context surface", "",
     "The gray surface shown for context: the mean member's isosurface, the median member's "
     "(the contour boxplot's deepest), or where half the members exceed the isovalue",
     0, 2, 0, 1, kContextSurfaces,
     [](const SessionState& s) { return static_cast<double>(s.render.context); },
     [](SessionState& s, double v) { s.render.context = static_cast<gl::ContextSurface>(v); }},
    {"context_spread",
     SettingKind::Flag,
     "rendering.context_spread",
     "context-spread",
     "rendering/contextSpread",
     "Colour the context by the spread",
     "",
     "The context surface coloured by the members' standard deviation where it lies, with a "
     "colour bar, instead of gray",
     0,
     1,
     0,
     1,
     {},
     [](const SessionState& s) { return s.render.contextBySpread ? 1.0 : 0.0; },
     [](SessionState& s, double v) { s.render.contextBySpread = v != 0.0; }},
    {"band",
     SettingKind::Flag,
     "rendering.band",
     "band",
     "rendering/band",
     "Contour boxplot band",
     "",
     "The contour boxplot's 50 % band as a translucent envelope between its two bounding "
     "surfaces (shaded on the sections, the median's contour drawn thick), with the outlying "
     "members' silhouettes and contours dashed",
     0,
     1,
     0,
     1,
     {},
     [](const SessionState& s) { return s.render.showBand ? 1.0 : 0.0; },
     [](SessionState& s, double v) { s.render.showBand = v != 0.0; }},
    {"mean_opacity",
     SettingKind::Number,
     "rendering.mean_opacity",
     "mean-opacity",
     "rendering/meanOpacity",
     "Mean opacity",
     "",
     "Opacity of the mean member's surface: below 1 it is translucent context that never hides "
     "the members; 1 draws it solid",
     0.05,
     1.0,
     2,
     0.05,
     {},
     [](const SessionState& s) { return double(s.render.meanOpacity); },
     [](SessionState& s, double v) { s.render.meanOpacity = asFloat(v); }},
    {"axis_labels",
     SettingKind::Flag,
     "rendering.axis_labels",
     "axis-labels",
     "rendering/axes",
     "Axis labels",
     "",
     "Tick labels in data units along the edges of the data box",
     0,
     1,
     0,
     1,
     {},
     [](const SessionState& s) { return s.render.showAxes ? 1.0 : 0.0; },
     [](SessionState& s, double v) { s.render.showAxes = v != 0.0; }},
    {"legend",
     SettingKind::Flag,
     "rendering.legend",
     "legend",
     "rendering/legend",
     "Cluster legend",
     "",
     "The cluster colours and sizes in the view's corner",
     0,
     1,
     0,
     1,
     {},
     [](const SessionState& s) { return s.render.showLegend ? 1.0 : 0.0; },
     [](SessionState& s, double v) { s.render.showLegend = v != 0.0; }},
    {"title",
     SettingKind::Flag,
     "rendering.title",
     "title",
     "rendering/title",
     "Title line",
     "",
     "A line above the picture saying the variable, isovalue, time and members (in the view, "
     "screenshots and ensil render)",
     0,
     1,
     0,
     1,
     {},
     [](const SessionState& s) { return s.render.showTitle ? 1.0 : 0.0; },
     [](SessionState& s, double v) { s.render.showTitle = v != 0.0; }},
    {"floor", SettingKind::Choice, "rendering.floor.content", "floor", "rendering/floor", "Floor",
     "",
     "What the box's floor shows: nothing, the mean's column maximum, the mean at a level, or "
     "the column maximum of the members' standard deviation or of the probability of exceeding "
     "the isovalue",
     0, 4, 0, 1, kFloorContents,
     [](const SessionState& s) { return static_cast<double>(s.render.floor); },
     [](SessionState& s, double v) { s.render.floor = static_cast<gl::FloorContent>(v); }},
    {"floor_level",
     SettingKind::Integer,
     "rendering.floor.level",
     "floor-level",
     "rendering/floorLevel",
     "Floor level",
     "",
     "The vertical grid index (0 = the first level in the file) whose mean the floor shows",
     0,
     10000,
     0,
     1,
     {},
     [](const SessionState& s) { return double(s.render.floorLevel); },
     [](SessionState& s, double v) { s.render.floorLevel = static_cast<int>(v); }},
    {"coastlines",
     SettingKind::Flag,
     "rendering.map.coastlines",
     "coastlines",
     "map/coastlines",
     "Coastlines",
     "",
     "Natural Earth coastlines on the floor, for grids with longitudes and latitudes (also rotated "
     "and projected grids)",
     0,
     1,
     0,
     1,
     {},
     [](const SessionState& s) { return s.render.showCoastlines ? 1.0 : 0.0; },
     [](SessionState& s, double v) { s.render.showCoastlines = v != 0.0; }},
    {"borders",
     SettingKind::Flag,
     "rendering.map.borders",
     "borders",
     "map/borders",
     "Country borders",
     "",
     "Natural Earth country borders on the floor",
     0,
     1,
     0,
     1,
     {},
     [](const SessionState& s) { return s.render.showBorders ? 1.0 : 0.0; },
     [](SessionState& s, double v) { s.render.showBorders = v != 0.0; }},
    {"graticule",
     SettingKind::Flag,
     "rendering.map.graticule",
     "graticule",
     "map/graticule",
     "Graticule",
     "",
     "True meridians and parallels on the floor of a rotated or projected grid",
     0,
     1,
     0,
     1,
     {},
     [](const SessionState& s) { return s.render.showGraticule ? 1.0 : 0.0; },
     [](SessionState& s, double v) { s.render.showGraticule = v != 0.0; }},
    {"rims",
     SettingKind::Flag,
     "rendering.rims",
     "rims",
     "rendering/rims",
     "Rims at the box",
     "",
     "Each surface's outline where it meets the data box: on the top and bottom levels, the "
     "member's contour line there (essential with few levels)",
     0,
     1,
     0,
     1,
     {},
     [](const SessionState& s) { return s.render.showRims ? 1.0 : 0.0; },
     [](SessionState& s, double v) { s.render.showRims = v != 0.0; }},
    {"removal",
     SettingKind::Flag,
     "rendering.removal.enabled",
     "",
     "",
     "Density-based removal",
     "",
     "Thins silhouettes where members agree: members are split into groups of s_G, and each "
     "group fades out over its own slice of [o*min, o*max] of outlyingness",
     0,
     1,
     0,
     1,
     {},
     [](const SessionState& s) { return s.render.removal ? 1.0 : 0.0; },
     [](SessionState& s, double v) { s.render.removal = v != 0.0; }},
    {"removal_min",
     SettingKind::Number,
     "rendering.removal.min",
     "",
     "",
     "o*min",
     "the variable's units squared",
     "Outlyingness below which every silhouette is drawn",
     0,
     1e30,
     6,
     0.01,
     {},
     [](const SessionState& s) { return double(s.render.removalMin); },
     [](SessionState& s, double v) { s.render.removalMin = asFloat(v); }},
    {"removal_max",
     SettingKind::Number,
     "rendering.removal.max",
     "",
     "",
     "o*max",
     "the variable's units squared",
     "Outlyingness above which every silhouette is drawn",
     0,
     1e30,
     6,
     0.01,
     {},
     [](const SessionState& s) { return double(s.render.removalMax); },
     [](SessionState& s, double v) { s.render.removalMax = asFloat(v); }},
    {"group_size",
     SettingKind::Integer,
     "rendering.removal.group_size",
     "group-size",
     "rendering/groupSize",
     "Group size s_G",
     "",
     "Group size s_G of the density-based removal: how many slices the range is cut into",
     1,
     256,
     0,
     1,
     {},
     [](const SessionState& s) { return double(s.render.groupSize); },
     [](SessionState& s, double v) { s.render.groupSize = static_cast<int>(v); }},
    {"vertical_exaggeration",
     SettingKind::Number,
     "rendering.vertical_exaggeration",
     "exaggeration",
     "",
     "Vertical exaggeration",
     "",
     "Stretches the vertical axis (flat atmospheric grids); the surfaces' attributes are rebuilt",
     0.01,
     1000,
     2,
     0.5,
     {},
     [](const SessionState& s) { return double(s.verticalExaggeration); },
     [](SessionState& s, double v) { s.verticalExaggeration = asFloat(v); }},
    {"vertical_axis", SettingKind::Choice, "rendering.vertical_axis", "vertical-axis",
     "rendering/verticalAxis", "Vertical axis", "",
     "How a pressure axis is drawn: through log-pressure (about height), linearly in pressure, or "
     "at the heights of the standard atmosphere; other vertical axes are drawn as they are",
     0, 2, 0, 1, kVerticalAxes,
     [](const SessionState& s) { return static_cast<double>(s.render.verticalAxis); },
     [](SessionState& s, double v) { s.render.verticalAxis = static_cast<data::VerticalAxis>(v); }},
    {"background",
     SettingKind::Colour,
     "rendering.background",
     "background",
     "rendering/background",
     "Background",
     "",
     "The view's background colour, as #rrggbb",
     0,
     0xFFFFFF,
     0,
     1,
     {},
     [](const SessionState& s) { return packColour(s.background); },
     [](SessionState& s, double v) { s.background = unpackColour(v); }},
    {"projection", SettingKind::Choice, "camera.projection", "projection", "rendering/projection",
     "Projection", "", "Perspective, or orthographic (parallel: sizes compare across the view)", 0,
     1, 0, 1, kProjections, [](const SessionState& s) { return s.camera.orthographic ? 1.0 : 0.0; },
     [](SessionState& s, double v) { s.camera.orthographic = v != 0.0; }},
    {"azimuth",
     SettingKind::Number,
     "camera.azimuth",
     "azimuth",
     "",
     "Azimuth",
     "degrees",
     "Camera azimuth: the compass direction it looks from, turned from the data box's south side",
     -360,
     360,
     1,
     5,
     {},
     [](const SessionState& s) { return double(s.camera.azimuth); },
     [](SessionState& s, double v) { s.camera.azimuth = asFloat(v); }},
    {"elevation",
     SettingKind::Number,
     "camera.elevation",
     "elevation",
     "",
     "Elevation",
     "degrees",
     "Camera elevation above the horizontal plane",
     -90,
     90,
     1,
     5,
     {},
     [](const SessionState& s) { return double(s.camera.elevation); },
     [](SessionState& s, double v) { s.camera.elevation = asFloat(v); }},
    {"clusters",
     SettingKind::Integer,
     "clusters.count",
     "clusters",
     "",
     "Clusters",
     "",
     "Number of clusters the members are coloured by (at most the number of members; "
     "default: 5, and no more than about half the members)",
     1,
     10000,
     0,
     1,
     {},
     [](const SessionState& s) { return double(s.clusters); },
     [](SessionState& s, double v) { s.clusters = static_cast<int>(v); }},
    {"linkage", SettingKind::Choice, "clusters.linkage", "linkage", "", "Linkage", "",
     "How the distance between two clusters is taken: average, single, complete or Ward", 0, 3, 0,
     1, kLinkages, [](const SessionState& s) { return static_cast<double>(s.linkage); },
     [](SessionState& s, double v) { s.linkage = static_cast<prep::Linkage>(v); }},
    {"plane",
     SettingKind::Flag,
     "cutting_plane.enabled",
     "",
     "",
     "Cut",
     "",
     "Cut the scene with a plane and draw each member's intersection curve",
     0,
     1,
     0,
     1,
     {},
     [](const SessionState& s) { return s.render.plane.enabled ? 1.0 : 0.0; },
     [](SessionState& s, double v) { s.render.plane.enabled = v != 0.0; }},
    {"plane_thickness",
     SettingKind::Number,
     "cutting_plane.thickness",
     "plane-thickness",
     "",
     "Curve width \u03b5",
     "",
     "Width eps of the intersection curves, in units of the data box's width",
     0.0001,
     0.1,
     4,
     0.001,
     {},
     [](const SessionState& s) { return double(s.render.plane.thickness); },
     [](SessionState& s, double v) { s.render.plane.thickness = asFloat(v); }},
    {"section", SettingKind::Choice, "cutting_plane.fill", "section", "", "Fill", "",
     "What the cutting plane's cut face shows, with a colour bar: nothing, the hovered (else the "
     "first selected) member, the mean, the members' standard deviation, or the probability of "
     "exceeding the isovalue",
     0, 4, 0, 1, kSectionFields,
     [](const SessionState& s) { return static_cast<double>(s.render.plane.fill); },
     [](SessionState& s, double v) { s.render.plane.fill = static_cast<gl::SectionField>(v); }},
    {"sections_fill", SettingKind::Choice, "sections.fill", "", "sections/fill", "Sections Fill",
     "",
     "What fills the Sections dock's map and cross-section: the mean, the members' standard "
     "deviation, the probability of exceeding the isovalue, the first selected member, its "
     "difference from the mean, or nothing",
     0, 5, 0, 1, kSectionsFills,
     [](const SessionState& s) { return static_cast<double>(s.sectionsFill); },
     [](SessionState& s, double v) { s.sectionsFill = static_cast<SectionsFill>(v); }},
    {"sections_colour_map", SettingKind::Choice, "sections.colour_map", "colour-map",
     "sections/colourMap", "Sections Colours", "",
     "The colour map of the sections' fill: automatic (viridis for values, RdBu centred on zero "
     "for differences, YlGnBu for probabilities), or one of viridis, greys, rdbu, ylgnbu",
     0, 4, 0, 1, kSectionsColourMaps,
     [](const SessionState& s) { return static_cast<double>(s.sectionsColours.map); },
     [](SessionState& s, double v) { s.sectionsColours.map = static_cast<SectionsColourMap>(v); }},
    // A fixed range belongs to one variable: projects keep it, the remembered settings do not.
    {"sections_fixed_range",
     SettingKind::Flag,
     "sections.fixed_range",
     "",
     "",
     "Fixed colour range",
     "",
     "Colour the sections' fill over the range from sections_range_min to sections_range_max "
     "instead of the shown section's own values",
     0,
     1,
     0,
     1,
     {},
     [](const SessionState& s) { return s.sectionsColours.fixedRange ? 1.0 : 0.0; },
     [](SessionState& s, double v) { s.sectionsColours.fixedRange = v != 0.0; }},
    {"sections_range_min",
     SettingKind::Number,
     "sections.range_min",
     "range-min",
     "",
     "From",
     "",
     "The fixed colour range's lower end, in the variable's units",
     -1e12,
     1e12,
     3,
     1,
     {},
     [](const SessionState& s) { return s.sectionsColours.minimum; },
     [](SessionState& s, double v) { s.sectionsColours.minimum = v; }},
    {"sections_range_max",
     SettingKind::Number,
     "sections.range_max",
     "range-max",
     "",
     "To",
     "",
     "The fixed colour range's upper end, in the variable's units",
     -1e12,
     1e12,
     3,
     1,
     {},
     [](const SessionState& s) { return s.sectionsColours.maximum; },
     [](SessionState& s, double v) { s.sectionsColours.maximum = v; }},
}};

std::string number(double v) {
    std::ostringstream text;
    text << v;
    return text.str();
}

}  // namespace

double packColour(const glm::vec3& rgb) {
    const auto channel = [](float c) {
        return static_cast<int>(std::lround(std::clamp(c, 0.0F, 1.0F) * 255.0F));
    };
    return static_cast<double>((channel(rgb.r) << 16) | (channel(rgb.g) << 8) | channel(rgb.b));
}

glm::vec3 unpackColour(double packed) {
    const auto bits = static_cast<unsigned>(packed);
    return {static_cast<float>((bits >> 16) & 0xFFU) / 255.0F,
            static_cast<float>((bits >> 8) & 0xFFU) / 255.0F,
            static_cast<float>(bits & 0xFFU) / 255.0F};
}

std::string Setting::allowed() const {
    switch (kind) {
        case SettingKind::Flag:
            return "true or false";
        case SettingKind::Colour:
            return "a colour #rrggbb";
        case SettingKind::Choice: {
            std::string names;
            for (std::size_t i = 0; i < choices.size(); ++i) {
                if (i > 0) names += i + 1 == choices.size() ? " or " : ", ";
                names += choices[i];
            }
            return names;
        }
        case SettingKind::Integer:
            return "a whole number from " + number(minimum) + " to " + number(maximum);
        case SettingKind::Number:
            break;
    }
    return "a number from " + number(minimum) + " to " + number(maximum) +
           (unit.empty() ? "" : " (" + std::string(unit) + ")");
}

std::string Setting::problemWith(double value) const {
    const bool whole = std::isfinite(value) && value == std::floor(value);
    // Numbers are kept as floats: a bound's float (0.0001 is 0.000099999997) must read back
    // as inside the range, or a project saved at a slider's end would not reopen.
    const double low = std::min(minimum, static_cast<double>(static_cast<float>(minimum)));
    const double high = std::max(maximum, static_cast<double>(static_cast<float>(maximum)));
    const bool inRange = std::isfinite(value) && value >= low && value <= high;
    if (kind == SettingKind::Number ? inRange : inRange && whole) return {};
    return "must be " + allowed();
}

std::string Setting::format(double value) const {
    switch (kind) {
        case SettingKind::Flag:
            return value != 0.0 ? "true" : "false";
        case SettingKind::Choice: {
            const auto index = static_cast<std::size_t>(value);
            return index < choices.size() ? std::string(choices[index]) : number(value);
        }
        case SettingKind::Colour: {
            char text[8];
            std::snprintf(text, sizeof text, "#%06x", static_cast<unsigned>(value) & 0xFFFFFFU);
            return text;
        }
        case SettingKind::Number:
        case SettingKind::Integer:
            break;
    }
    return number(value);
}

std::span<const Setting> settingTable() { return kSettings; }

const Setting& setting(std::string_view id) {
    for (const Setting& s : kSettings) {
        if (s.id == id) return s;
    }
    throw std::logic_error("no setting named " + std::string(id));
}

}  // namespace ensil::session
