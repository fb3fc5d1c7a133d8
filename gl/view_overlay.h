// What is written over the 3D picture: tick labels in data units along three edges of the data
// box (the edges nearest the viewer), the axis titles, and a legend of cluster colours. Computed
// from the camera and the frame (projected to pixels), painted with QPainter, so the window and
// headless rendering (`ensil render`) show the same labels. GUI thread or the render thread.
#pragma once

#include <QColor>
#include <QFontMetricsF>
#include <QRectF>
#include <QSizeF>
#include <QString>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <vector>

#include "data/display_frame.h"
#include "data/grid.h"
#include "gl/render_settings.h"

class QPainter;
class QPaintDevice;

namespace ensil::gl {

struct OverlayLabel {
    glm::vec2 pixel{0.0F};      // where the label's anchor lies, top-left origin
    glm::vec2 direction{0.0F};  // unit screen direction the label is pushed away from the box
    QString text;
    bool title = false;  // an axis title rather than a tick value
    int axis = -1;       // the axis (0 x, 1 y, 2 vertical) it labels; -1: none
    // Where labels collide the lower number is kept: titles 0, the vertical axis's ticks 1
    // (levels are few and each one matters), the horizontal axes' ticks 2, floor labels 3.
    int priority = 2;
};

// How a legend entry's swatch shows what it stands for: a filled square for surfaces drawn in a
// colour, a translucent square with its outline for the contour boxplot's band (drawn
// translucent), a dashed stroke for what the view draws dashed (outliers, plane curves).
enum class Swatch { Filled, Band, Dashed };

struct LegendEntry {
    glm::vec3 color{0.0F};
    QString text;
    Swatch swatch = Swatch::Filled;
};

// A colour bar (the floor map's, the section's): what it shows and the values at its two ends.
struct ColourScale {
    QString caption;
    float minimum = 0.0F;
    float maximum = 1.0F;
};

struct ViewOverlay {
    std::vector<OverlayLabel> labels;
    std::vector<LegendEntry> legend;
    QString message;  // centred in the view, e.g. what to do when nothing is loaded
    QString title;    // the line at the top saying what the picture shows
    // The data box's bounding rectangle on screen (pixels, top-left origin; empty when
    // unknown): the legend goes into a corner that keeps clear of it.
    QRectF box;
    // The colour bars, stacked in one panel: the floor's, then the section's.
    std::vector<ColourScale> colourScales;
    QColor text;  // readable on the background
};

struct OverlayInput {
    const data::Grid* grid = nullptr;
    const data::DisplayFrame* frame = nullptr;
    glm::mat4 viewProjection{1.0F};
    glm::vec3 eye{0.0F};
    int width = 0;
    int height = 0;
    const std::vector<MemberAppearance>* appearance = nullptr;
    bool showMean = false;
    // What the context surface is ("Mean member", "Median member", "P = 0.5 surface").
    QString contextName = QStringLiteral("Mean member");
    // The contour boxplot's band is shown, with this many outliers dashed.
    bool band = false;
    int outliers = 0;
    glm::vec3 bandColor{1.0F};
    // The cutting plane is on and cuts surfaces: its dashed curves get a legend entry, in the
    // plane's own colour.
    bool planeCurves = false;
    glm::vec3 planeColor{1.0F};
    bool showAxes = true;
    bool showLegend = true;
    QString title;                          // empty: none
    std::vector<ColourScale> colourScales;  // the floor's, then the section's
    // Labels at points on the floor (display space): the graticule's true degrees where each
    // line enters the grid. Placed after the axes' labels, where room is left.
    std::vector<std::pair<glm::vec3, QString>> floorLabels;
    glm::vec3 background{0.0F};
};

ViewOverlay computeOverlay(const OverlayInput& input);

// Paints the overlay on a device `logicalSize` big whose pixels are `pixelRatio` device pixels
// (labels were computed in device pixels).
void paintOverlay(QPainter& painter, const ViewOverlay& overlay, double pixelRatio);
// The same onto a picture `logicalSize` big in the painter's coordinates: an export drawn with
// painter.scale(s, s) and pixelRatio s has text and spacing s times larger, as the view's at
// that zoom (a picture twice the view's size looks like the view at 2x).
// `painted`, when given, receives the rectangle of every text and panel drawn (logical
// pixels), so tests can check that nothing overlaps or is cut off.
struct PaintedItem {
    QRectF rect;
    QString text;  // the label's text; the panel's kind for the title, legend and colour bar
};
void paintOverlay(QPainter& painter, const ViewOverlay& overlay, double pixelRatio,
                  QSizeF logicalSize, std::vector<PaintedItem>* painted = nullptr);

// Where paintOverlay puts its panels in a picture `logicalSize` big (logical pixels), with the
// data box's rectangle `dataBox` there: the title line at the top, the legend in the first
// corner clear of the box, the colour bars' panel in another corner clear of both. An empty
// rectangle: not shown (the colour bar when no corner is left for it).
struct PanelPlaces {
    QRectF title;
    QRectF legend;
    QRectF colourBar;
};
// Text is measured for `device` (what paintOverlay paints on); null: for a picture.
PanelPlaces placePanels(const ViewOverlay& overlay, QSizeF logicalSize, const QRectF& dataBox,
                        const QPaintDevice* device = nullptr);

// What the panels need, in logical pixels: the title line's strip at the top, the legend's and
// the colour bar's sizes (empty when not shown), the margin from the picture's edge, and the
// depth of a row of tick values with an axis title under it (0 without axis labels).
struct PanelRoom {
    double top = 0.0;
    double axisLabels = 0.0;
    QSizeF legend;
    QSizeF colourBar;
    double margin = 0.0;
};
// `logicalWidth`: the picture's, which decides whether the title takes one line or two.
PanelRoom panelRoom(const ViewOverlay& overlay, double logicalWidth);

// The title's lines within `width`: one when it fits; else two, broken after the last of its
// facts (separated by middle dots) that fits on the first, so that no fact, a date least of all,
// is cut; only a line still too wide is elided, in the middle. Measured with `metrics`.
QStringList titleLines(const QString& title, const QFontMetricsF& metrics, double width);

// The text scale for a picture of this height drawn with no window to compare it with: 1 up
// to kReferenceHeight pixels, then in proportion.
inline constexpr double kReferenceHeight = 800.0;
double exportTextScale(int height);

// Formats a tick value compactly: no trailing zeros, no exponent for everyday magnitudes.
QString formatTick(double value);

}  // namespace ensil::gl
