// A map or a cross-section of an ensemble, ready to draw (engine/section_painter.h): where it
// lies (a level in the vertical axis's units, a latitude, a longitude or a great-circle path
// between two points), the filled field (a member, the mean, the spread, P(f > c), a member's
// difference from the mean, or none), every member's contour of the isovalue in its cluster's
// colour, the mean's contour, the map lines and the axes' ticks. Everything is laid out in the
// plot's unit square (x right, y up), as the 3D view places the same data (data::DisplayFrame:
// true horizontal proportions, pressure through log-pressure), so a map reads as the 3D view's
// top and a cross-section as its side. The fields are sampled from the members themselves
// (prep::sampleSection), and the mean, spread and probability taken over those samples, so a
// section costs members x its samples, never a pass over the volume (METHODS.md section 22).
// Shared by `ensil section`, the workbench's Sections dock and Python. Pure; any thread.
#pragma once

#include <cstddef>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "data/display_frame.h"
#include "data/ensemble.h"
#include "preprocessing/marching_squares.h"
#include "session/session_state.h"

namespace ensil::engine {

enum class SectionKind { Map, Latitude, Longitude, Path };

struct SectionPlace {
    SectionKind kind = SectionKind::Map;
    // Map: the level, in `levelUnits`: a pressure unit ("hPa", "Pa"), a length ("km", "m"),
    // "index" (a vertical grid index from 0), or "" for the vertical axis's own units.
    double level = 0.0;
    std::string levelUnits;
    double latitude = 0.0;   // Latitude: degrees north
    double longitude = 0.0;  // Longitude: degrees east
    // Path: two points, longitude and latitude in degrees (grid axis coordinates for data
    // without geography), joined by the great circle.
    glm::dvec2 from{0.0};
    glm::dvec2 to{0.0};
    // How a pressure axis is drawn up a cross-section, and where a map's level lies in the 3D
    // view's box: the session's choice (the setting "vertical_axis"), as the 3D view draws it.
    data::VerticalAxis verticalAxis = data::VerticalAxis::LogPressure;
};

enum class SectionFill { None, Member, Mean, Spread, Probability, Anomaly };

// The fill's colour maps, the session's (the setting "sections_colour_map", whose names the
// command line, JSON and Python use): matplotlib's viridis, ColorBrewer's Greys, RdBu
// (diverging: blue below the middle, red above) and YlGnBu (pale at 0, for probabilities), or
// Automatic: chosen by the fill. A view's map is never Automatic.
using SectionColourMap = session::SectionsColourMap;

// The contour boxplot drawn on a section (METHODS.md sections 17 and 22), by member index: the
// 50 % band's members (deepest first, prep::bandMembersOf), the median and the outliers.
struct SectionBoxplot {
    std::vector<std::size_t> bandMembers;
    int median = -1;
    std::vector<std::size_t> outliers;
};

struct SectionRequest {
    SectionPlace place;
    SectionFill fill = SectionFill::Mean;
    int member = -1;  // Member and Anomaly: the member's index in the ensemble
    float isovalue = 0.0F;
    // Each member's contour colour (its cluster's) and the legend's entries; members beyond it
    // are drawn in the unclustered gray.
    std::vector<glm::vec3> memberColours;
    std::vector<int> clusterNumbers;  // as the legend numbers them, per member; may be empty
    // The fill's colours: by default chosen by the fill (viridis, RdBu for a difference from
    // the mean, YlGnBu for a probability) over the section's own range.
    SectionColourMap colourMap = SectionColourMap::Automatic;
    std::optional<std::pair<double, double>> range;  // fixed: lower below upper, both finite
    // Rendering > Contour boxplot: the band, the median's contour and the outliers dashed.
    std::optional<SectionBoxplot> boxplot;
};

struct SectionTick {
    double position = 0.0;  // along the axis, 0 to 1
    std::string label;
};

struct SectionAxis {
    std::string title;
    std::vector<SectionTick> ticks;
};

// A polyline in the plot's unit square.
struct SectionLine {
    std::vector<glm::dvec2> points;
    bool closed = false;
};

struct MemberContour {
    std::size_t member = 0;
    glm::vec3 colour{0.0F};
    std::vector<SectionLine> lines;
};

// Where a section lies and how it is laid out in its plot's unit square (x right, y up):
// what engine::placeSection finds from the place alone, before any value is sampled.
struct SectionLayout {
    // The place in words, for titles, file names and JSON: "500 hPa", "45°N", "10°W",
    // "10°W 50°N to 20°E 40°N".
    std::string placeText;
    double aspect = 1.0;  // the plot's width over its height
    // Where each lattice column and row lies across the plot (ascending or descending, 0 to 1).
    std::vector<double> columnPositions;
    std::vector<double> rowPositions;
    SectionAxis bottom;
    SectionAxis left;
    std::vector<SectionLine> mapLines;   // coastlines and borders (maps only)
    std::vector<SectionLine> graticule;  // a projected map's true meridians and parallels
    // Each graticule line's degrees ("10°W", "54°N") where it enters the map.
    struct PlaceLabel {
        glm::dvec2 at{0.0};  // the plot's unit square
        std::string text;
    };
    std::vector<PlaceLabel> graticuleLabels;
    // Where the other kind of section shows this one: a cross-section's path across a map of
    // the same data, in the map's unit square; a map's level up a cross-section, 0 to 1 (-1
    // for a cross-section).
    std::vector<glm::dvec2> pathOnMap;
    double levelHeight = -1.0;
};

struct SectionView : SectionLayout {
    std::string title;     // "t at 500 hPa", "t along 45°N", "t from 10°W 50°N to 20°E 40°N"
    std::string subtitle;  // "isovalue 260 K · fill: mean t [K] · 50 members"
    // The lattice of the fill's samples: columns x rows, column fastest.
    std::size_t columns = 0;
    std::size_t rows = 0;
    std::vector<float> fill;  // empty for SectionFill::None; NaN where missing
    std::string fillCaption;  // "mean t [K]"
    SectionColourMap colourMap = SectionColourMap::Viridis;
    float fillMinimum = 0.0F;  // the colour bar's range: the section's own values by default
    float fillMaximum = 1.0F;
    std::vector<double> colourTicks;  // round numbers inside the range
    std::vector<MemberContour> members;
    std::vector<SectionLine> meanContour;  // of the members' mean
    float isovalue = 0.0F;
    // The contour boxplot, when asked for: per sample the band members' lowest and highest
    // values (the band is where the highest exceeds the isovalue and the lowest does not: the
    // union less the intersection of their inside sets), the band's edges (both fields'
    // contours), the median member (-1: none) and the outliers.
    std::vector<float> bandLowest;
    std::vector<float> bandHighest;
    std::vector<SectionLine> bandEdges;
    int medianMember = -1;
    std::vector<std::size_t> outliers;
    [[nodiscard]] bool isOutlier(std::size_t member) const;
    // Whether sample s lies in the band: the highest value above the isovalue, the lowest not.
    [[nodiscard]] bool inBand(std::size_t s) const {
        return bandHighest[s] > isovalue && !(bandLowest[s] > isovalue);
    }
    // Legend: each cluster number with its colour and member count, ascending.
    struct LegendEntry {
        int cluster = 0;
        glm::vec3 colour{0.0F};
        int members = 0;
    };
    std::vector<LegendEntry> legend;
    // Samples of each member's field, kept for hover (value under the pointer) and for Python.
    std::vector<std::vector<float>> memberValues;
    std::vector<std::string> memberNames;  // as the file names them
    std::string units;                     // the variable's, as people read them ("m s⁻¹")
};

// The fill as the command line and Python name it: mean, spread, probability, member:N,
// anomaly:N (N counts members from 1) or none; nullopt with `problem` set otherwise. The
// member is the index from 0 (-1 for the fills of all members).
std::optional<std::pair<SectionFill, int>> parseSectionFill(const std::string& text,
                                                            std::string& problem);

// What `ensil section` and Python draw: the place and fill asked for, at the isovalue of
// `clusters` (engine::preprocessEnsemble's result), each member in its cluster's colour.
struct PreprocessResult;
SectionRequest sectionRequestFor(const PreprocessResult& clusters, const SectionPlace& place,
                                 SectionFill fill, int member);

// The session's colour settings (the setting table's sections_colour_map and fixed range) on a
// request.
void applySectionColours(SectionRequest& request, const session::SectionsColours& colours);

// Throws data::Error(InvalidArgument) naming the place when it lies outside the data (a level
// above the top, a latitude the grid does not reach), the fill's member does not exist or a
// fixed range is empty.
SectionView buildSection(const data::Ensemble& ensemble, const SectionRequest& request);

// The fractional lattice index at position t along a table of positions (ascending or
// descending), clamped to the lattice.
double latticeIndexAt(const std::vector<double>& positions, double t);
// The value of `values` (one per lattice sample: view.fill, a member's memberValues) at a place
// in the plot's unit square, bilinear between samples; NaN where the nearest sample is missing
// or the size is not the lattice's.
float sectionValueAt(const SectionView& view, const std::vector<float>& values, glm::dvec2 unit);
// The same at a fractional lattice index (column, row), for a caller that walks the lattice.
float sectionValueAtIndex(const SectionView& view, const std::vector<float>& values, double column,
                          double row);

// The boxplot of a preprocessing run (prep::computeContourBoxplot's) as a section draws it;
// nullopt when none was made (an ensemble preprocessed in slabs).
struct PreprocessResult;
std::optional<SectionBoxplot> sectionBoxplotOf(const PreprocessResult& result);
// The samples of the lattice in the band (0 without a boxplot).
std::size_t bandSampleCount(const SectionView& view);

// Gives each member's contour its colour and makes the legend (as buildSection does from the
// request), for new clusters without sampling the section again.
void colourSection(SectionView& view, const std::vector<glm::vec3>& memberColours,
                   const std::vector<int>& clusterNumbers);

// Where a section shows most by default: the map at the grid level, and the cross-section along
// the grid row of that level, where the most points have members on both sides of the isovalue
// (where the members' contours are, and differ). The level in the axis's own units (an index
// for an axis without units); the cross-section along the row's latitude on a
// longitude/latitude grid, else along the row from its first point to its last (as longitude
// and latitude through `gridMapping`, or in the grid's x, y without a map). Any thread.
struct DefaultSections {
    SectionPlace map;
    SectionPlace crossSection;
};
DefaultSections defaultSections(const data::Ensemble& ensemble, float isovalue);

}  // namespace ensil::engine
