// Draws a map or a cross-section (engine/ensemble_section.h) as a figure: the title, the
// filled field over the plot with its colour bar (ticks at round numbers), every member's
// contour in its cluster's colour over a thin dark halo (readable on any fill), the mean's
// contour, coastlines on top, framed axes with ticks in degrees, hPa or km, and the clusters'
// legend. The same drawing serves the workbench's Sections dock and `ensil section`, whose
// PNG, SVG (text as text, contours as paths, the fill an embedded image) and PDF come from one
// QPainter path. GUI thread or any thread with a QGuiApplication (fonts).
#pragma once

#include <QColor>
#include <QRectF>
#include <QSize>
#include <QString>
#include <vector>

#include "engine/ensemble_section.h"

class QPainter;

namespace ensil::engine {

struct SectionEmphasis {
    std::vector<std::size_t> selected;  // drawn wider and last; the others fade while any is
    int hovered = -1;                   // drawn widest
    std::vector<bool> hidden;           // per member: not drawn (members beyond it are drawn)
};

struct SectionStyle {
    QColor background = Qt::white;
    QColor text = Qt::black;
    double fontPoints = 9.0;
    // For a dock: no title lines, the colour bar alone beside the plot, thin margins.
    bool compact = false;
};

// Where the plot lies in `page` when paintSection draws it there (for the pointer's place).
QRectF sectionPlotRect(const SectionView& view, const QRectF& page, const SectionStyle& style = {});
// A picture `width` wide and as high as the section's proportions need (the colour bar and
// the legend fitting beside it).
QSize sectionPictureSize(const SectionView& view, int width, const SectionStyle& style = {});
void paintSection(QPainter& painter, const SectionView& view, const QRectF& page,
                  const SectionEmphasis& emphasis = {}, const SectionStyle& style = {});

// One member's contour as paintSection draws the hovered one, over a picture drawn before
// (the dock keeps the rest as an image, so the pointer's moves redraw only this).
void paintHoveredMember(QPainter& painter, const SectionView& view, const QRectF& page,
                        std::size_t member, const SectionStyle& style = {});

// Whether writeSectionPicture writes a picture of this name (.png, .svg or .pdf): what a
// command checks before it reads any data.
bool isSectionPictureName(const QString& path);

// Writes the figure as PNG, SVG or PDF by the path's suffix, `size` in pixels (PDF: points).
// Throws data::Error naming the file when the suffix is none of these or it cannot be written.
void writeSectionPicture(const SectionView& view, const QString& path, QSize size);

}  // namespace ensil::engine
