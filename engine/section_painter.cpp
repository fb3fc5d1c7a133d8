#include "engine/section_painter.h"

#include <QFileInfo>
#include <QFontMetricsF>
#include <QImage>
#include <QPainter>
#include <QPainterPath>
#include <QPdfWriter>
#include <QSvgGenerator>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "data/error.h"
#include "gl/palette.h"
#include "gl/view_overlay.h"

namespace ensil::engine {
namespace {

// A figure's proportions; a compact one (a dock) has no title lines, a narrow side column
// (the colour bar alone: the clusters' legend is the Clusters panel) and thin margins.
struct Proportions {
    double margin;
    double sideColumn;  // the colour bar and the legend, right of the plot
    double linesAbove;  // margin, title, subtitle, gap, in lines of text
    bool titled;
    bool legend;
};

Proportions proportionsOf(const SectionStyle& style) {
    return style.compact ? Proportions{4.0, 96.0, 0.6, false, false}
                         : Proportions{12.0, 200.0, 3.0, true, true};
}
constexpr double kTickLength = 4.0;
const QColor kMissing(0xd9, 0xd9, 0xd9);

QColor toColour(glm::vec3 c) {
    return QColor::fromRgbF(std::clamp(c.r, 0.0F, 1.0F), std::clamp(c.g, 0.0F, 1.0F),
                            std::clamp(c.b, 0.0F, 1.0F));
}

// ColorBrewer's RdBu (blue below zero, red above), YlGnBu (probabilities: pale at 0, so the
// contours stay readable where little is likely) and Greys (for print), by Cynthia Brewer,
// colorbrewer2.org; the anchors are the published colours, interpolated linearly between.
constexpr std::array<unsigned, 11> kDiverging{0x053061, 0x2166ac, 0x4393c3, 0x92c5de,
                                              0xd1e5f0, 0xf7f7f7, 0xfddbc7, 0xf4a582,
                                              0xd6604d, 0xb2182b, 0x67001f};
constexpr std::array<unsigned, 9> kProbability{0xffffd9, 0xedf8b1, 0xc7e9b4, 0x7fcdbb, 0x41b6c4,
                                               0x1d91c0, 0x225ea8, 0x253494, 0x081d58};
constexpr std::array<unsigned, 9> kGreys{0xffffff, 0xf0f0f0, 0xd9d9d9, 0xbdbdbd, 0x969696,
                                         0x737373, 0x525252, 0x252525, 0x000000};

template <std::size_t N>
QRgb fromAnchors(const std::array<unsigned, N>& anchors, double t) {
    const double x = std::clamp(t, 0.0, 1.0) * static_cast<double>(N - 1);
    const auto i = std::min(static_cast<std::size_t>(x), N - 2);
    const double f = x - static_cast<double>(i);
    const auto channel = [&](int shift) {
        const double a = (anchors[i] >> shift) & 0xff, b = (anchors[i + 1] >> shift) & 0xff;
        return static_cast<int>(std::lround(a + f * (b - a)));
    };
    return qRgb(channel(16), channel(8), channel(0));
}

QRgb colourAt(SectionColourMap map, double t) {
    switch (map) {
        case SectionColourMap::RdBu:
            return fromAnchors(kDiverging, t);
        case SectionColourMap::YlGnBu:
            return fromAnchors(kProbability, t);
        case SectionColourMap::Greys:
            return fromAnchors(kGreys, t);
        case SectionColourMap::Viridis:
        case SectionColourMap::Automatic:  // resolved by buildSection; never in a view
            break;
    }
    return toColour(gl::viridis(static_cast<float>(std::clamp(t, 0.0, 1.0)))).rgb();
}

// An image of `width` x `height` pixels covering the plot, each pixel `colourOf(column, row)` at
// its centre's fractional lattice index.
template <typename ColourOf>
QImage latticeImage(const SectionView& view, int width, int height, QImage::Format format,
                    ColourOf colourOf) {
    QImage image(width, height, format);
    // Each pixel column's lattice column, found once (not per pixel).
    std::vector<double> columnAt(static_cast<std::size_t>(width));
    for (int x = 0; x < width; ++x) {
        columnAt[static_cast<std::size_t>(x)] =
            latticeIndexAt(view.columnPositions, (x + 0.5) / width);
    }
    for (int y = 0; y < height; ++y) {
        const double row = latticeIndexAt(view.rowPositions, 1.0 - (y + 0.5) / height);
        auto* line = reinterpret_cast<QRgb*>(image.scanLine(y));
        for (int x = 0; x < width; ++x)
            line[x] = colourOf(columnAt[static_cast<std::size_t>(x)], row);
    }
    return image;
}

// The filled field.
QImage fillImage(const SectionView& view, int width, int height) {
    const double range = static_cast<double>(view.fillMaximum) - view.fillMinimum;
    return latticeImage(view, width, height, QImage::Format_RGB32, [&](double column, double row) {
        const float v = sectionValueAtIndex(view, view.fill, column, row);
        return std::isnan(v) ? kMissing.rgb()
                             : colourAt(view.colourMap, (v - view.fillMinimum) / range);
    });
}

// The contour boxplot's 50 % band, translucent over the plot: where the band members' highest
// value exceeds the isovalue and their lowest does not (as SectionView::inBand, bilinear between
// samples, so its edges are those fields' contours).
QImage bandImage(const SectionView& view, int width, int height, QColor colour) {
    const QRgb inside = qPremultiply(colour.rgba());
    return latticeImage(
        view, width, height, QImage::Format_ARGB32_Premultiplied, [&](double column, double row) {
            const float high = sectionValueAtIndex(view, view.bandHighest, column, row);
            const float low = sectionValueAtIndex(view, view.bandLowest, column, row);
            return high > view.isovalue && !(low > view.isovalue) ? inside : QRgb{0};
        });
}

// Line by line: QPainter strokes a path by filling its outline, and the outline of many lines
// in one path (crossing each other) costs several times what the lines do one by one
// (measured with ensil_section_benchmark: 720 against 260 ms for the demo's map).
void strokeLines(QPainter& painter, const std::vector<SectionLine>& lines, const QRectF& plot,
                 const QPen& pen) {
    painter.setPen(pen);
    painter.setBrush(Qt::NoBrush);
    for (const SectionLine& line : lines) {
        QPainterPath path;
        for (std::size_t i = 0; i < line.points.size(); ++i) {
            const QPointF p(plot.left() + line.points[i].x * plot.width(),
                            plot.bottom() - line.points[i].y * plot.height());
            if (i == 0) {
                path.moveTo(p);
            } else {
                path.lineTo(p);
            }
        }
        if (line.closed) path.closeSubpath();
        painter.drawPath(path);
    }
}

// A member drawn above the others: outlined in black, `width` wide.
void strokeEmphasised(QPainter& painter, const MemberContour& c, const QRectF& plot, double width) {
    strokeLines(painter, c.lines, plot, QPen(Qt::black, width + 1.6));
    strokeLines(painter, c.lines, plot, QPen(toColour(c.colour), width));
}

// A dark halo about two pixels wide under every member's line, so that a line reads on any
// fill. In a vector picture each line is stroked wide; on screen and in a PNG the lines are
// drawn one pixel wide into a mask that is then widened by a pixel each way (a 3 x 3 maximum):
// stroking 50 members' wide antialiased lines took 110 of the 250 ms a map of the demo took to
// draw (ensil_section_benchmark), the mask a few.
template <typename Hidden>
void drawHalo(QPainter& painter, const SectionView& view, const QRectF& plot, int alpha,
              const Hidden& isHidden) {
    const int type = painter.device()->devType();
    const bool raster =
        type == QInternal::Image || type == QInternal::Pixmap || type == QInternal::Widget;
    if (!raster) {
        const QPen wide(QColor(0, 0, 0, alpha), 2.6);
        for (const MemberContour& c : view.members) {
            if (!isHidden(c.member)) strokeLines(painter, c.lines, plot, wide);
        }
        return;
    }
    const QRect device = painter.deviceTransform().mapRect(plot).toAlignedRect();
    if (device.width() < 3 || device.height() < 3) return;
    QImage mask(device.size(), QImage::Format_Grayscale8);
    mask.fill(0);
    {
        QPainter lines(&mask);
        lines.setTransform(painter.deviceTransform() *
                           QTransform::fromTranslate(-device.left(), -device.top()));
        QPen pen(Qt::white, 1.0);
        pen.setCosmetic(true);
        for (const MemberContour& c : view.members) {
            if (!isHidden(c.member)) strokeLines(lines, c.lines, plot, pen);
        }
    }
    // The 3 x 3 maximum, separably: along rows, then along columns.
    const int w = mask.width(), h = mask.height();
    std::vector<std::uint8_t> across(static_cast<std::size_t>(w) * h);
    for (int y = 0; y < h; ++y) {
        const uchar* row = mask.constScanLine(y);
        for (int x = 0; x < w; ++x) {
            across[static_cast<std::size_t>(y) * w + x] =
                std::max({row[std::max(x - 1, 0)], row[x], row[std::min(x + 1, w - 1)]});
        }
    }
    QImage halo(device.size(), QImage::Format_ARGB32_Premultiplied);
    for (int y = 0; y < h; ++y) {
        auto* out = reinterpret_cast<QRgb*>(halo.scanLine(y));
        const auto at = [&](int yy, int x) {
            return across[static_cast<std::size_t>(std::clamp(yy, 0, h - 1)) * w + x];
        };
        for (int x = 0; x < w; ++x) {
            const int m = std::max({at(y - 1, x), at(y, x), at(y + 1, x)});
            out[x] = qRgba(0, 0, 0, m * alpha / 255);  // black: premultiplied as it is
        }
    }
    painter.save();
    painter.resetTransform();
    painter.drawImage(device.topLeft(), halo);
    painter.restore();
}

constexpr double kSelectedWidth = 2.4;
// The contour boxplot's marks: outliers' contours dashed; the median's a dark line in a light
// casing, apart from every member's colour, from the dashed mean and from a selection.
const QList<qreal> kOutlierDashes{3.0, 2.0};
std::array<QPen, 2> medianPens(const SectionStyle& style) {
    return {QPen(style.background, 4.4), QPen(style.text, 2.2)};
}
// The band: lighter over a fill, a pale shade of the text colour over none.
QColor bandColour(const SectionView& view, const SectionStyle& style) {
    QColor c = view.fill.empty() ? style.text : style.background;
    c.setAlphaF(view.fill.empty() ? 0.16 : 0.45);
    return c;
}
constexpr double kHoveredWidth = 3.0;

struct Layout {
    QRectF title, plot, side;
};

// Below the plot (ticks, axis title), in lines of text.
constexpr double kLinesBelow = 2.8;

QFont sectionFont(const SectionStyle& style) {
    QFont font;
    font.setPointSizeF(style.fontPoints);
    return font;
}

Layout layoutOf(const SectionView& view, const QRectF& page, const QFontMetricsF& metrics,
                const Proportions& p) {
    const double kMargin = p.margin;
    const double line = metrics.height();
    Layout l;
    l.title =
        QRectF(page.left() + kMargin, page.top() + kMargin, page.width() - 2 * kMargin, 2.4 * line);
    const double left = page.left() + kMargin + 3.2 * line + metrics.horizontalAdvance("1000");
    const double top = page.top() + kMargin + p.linesAbove * line;
    const double right = page.right() - kMargin - p.sideColumn;
    const double bottom = page.bottom() - kMargin - kLinesBelow * line;
    QRectF available(left, top, std::max(10.0, right - left), std::max(10.0, bottom - top));
    // The plot keeps the data's proportions, centred in the room it has.
    double w = available.width(), h = w / view.aspect;
    if (h > available.height()) {
        h = available.height();
        w = h * view.aspect;
    }
    l.plot = QRectF(available.left() + (available.width() - w) / 2,
                    available.top() + (available.height() - h) / 2, w, h);
    l.side =
        QRectF(l.plot.right() + 1.5 * line, l.plot.top(), p.sideColumn - 1.5 * line + kMargin, h);
    return l;
}

void drawAxes(QPainter& painter, const SectionView& view, const QRectF& plot,
              const QFontMetricsF& metrics, const SectionStyle& style) {
    painter.setPen(QPen(style.text, 1.0));
    painter.setBrush(Qt::NoBrush);
    painter.drawRect(plot);
    const double line = metrics.height();
    double previousRight = -1e9;
    for (const SectionTick& tick : view.bottom.ticks) {
        const double x = plot.left() + tick.position * plot.width();
        painter.drawLine(QPointF(x, plot.bottom()), QPointF(x, plot.bottom() + kTickLength));
        const QString text = QString::fromStdString(tick.label);
        const double w = metrics.horizontalAdvance(text);
        if (x - w / 2 < previousRight + 6) continue;  // labels never touch
        painter.drawText(QRectF(x - w / 2, plot.bottom() + kTickLength + 1, w, line),
                         Qt::AlignCenter, text);
        previousRight = x + w / 2;
    }
    painter.drawText(
        QRectF(plot.left(), plot.bottom() + kTickLength + 1.2 * line, plot.width(), line),
        Qt::AlignCenter, QString::fromStdString(view.bottom.title));
    double widest = 0.0;
    // Labels in the ticks' order of importance (1000, 500, 250 hPa before 925): one that would
    // touch a label already written is left out, its tick kept.
    std::vector<double> labelled;
    for (const SectionTick& tick : view.left.ticks) {
        const double y = plot.bottom() - tick.position * plot.height();
        if (y < plot.top() - 0.5 || y > plot.bottom() + 0.5) continue;
        painter.drawLine(QPointF(plot.left() - kTickLength, y), QPointF(plot.left(), y));
        const QString text = QString::fromStdString(tick.label);
        const double w = metrics.horizontalAdvance(text);
        if (std::any_of(labelled.begin(), labelled.end(),
                        [&](double other) { return std::abs(y - other) < line; })) {
            continue;
        }
        widest = std::max(widest, w);
        painter.drawText(QRectF(plot.left() - kTickLength - 3 - w, y - line / 2, w, line),
                         Qt::AlignRight | Qt::AlignVCenter, text);
        labelled.push_back(y);
    }
    painter.save();
    painter.translate(plot.left() - kTickLength - 6 - widest - 0.6 * line, plot.center().y());
    painter.rotate(-90);
    painter.drawText(QRectF(-plot.height() / 2, -line, plot.height(), line), Qt::AlignCenter,
                     QString::fromStdString(view.left.title));
    painter.restore();
}

// The colour bar (vertical, its caption above) and below it the legend; returns nothing.
void drawSide(QPainter& painter, const SectionView& view, const QRectF& side,
              const QFontMetricsF& metrics, const SectionStyle& style, bool legend) {
    const double line = metrics.height();
    double y = side.top();
    painter.setPen(style.text);
    if (!view.fill.empty()) {
        const QRectF caption(side.left(), y, side.width(), 3 * line);
        QRectF used;
        painter.drawText(caption, Qt::TextWordWrap | Qt::AlignLeft | Qt::AlignTop,
                         QString::fromStdString(view.fillCaption), &used);
        y = used.bottom() + 0.5 * line;
        const double barHeight = std::max(4 * line, std::min(side.height() * 0.55, 14 * line));
        const QRectF bar(side.left(), y, 14.0, barHeight);
        QImage gradient(1, 256, QImage::Format_RGB32);
        for (int i = 0; i < 256; ++i) {
            gradient.setPixel(0, i, colourAt(view.colourMap, 1.0 - (i + 0.5) / 256.0));
        }
        painter.drawImage(bar, gradient);
        painter.setPen(QPen(style.text, 0.8));
        painter.drawRect(bar);
        const double range = static_cast<double>(view.fillMaximum) - view.fillMinimum;
        for (const double t : view.colourTicks) {
            const double ty = bar.bottom() - (t - view.fillMinimum) / range * bar.height();
            painter.drawLine(QPointF(bar.right(), ty), QPointF(bar.right() + kTickLength, ty));
            painter.drawText(QRectF(bar.right() + kTickLength + 3, ty - line / 2, 90, line),
                             Qt::AlignLeft | Qt::AlignVCenter, gl::formatTick(t));
        }
        y = bar.bottom() + 1.2 * line;
    }
    if (!legend) return;
    // The legend: the mean's line, then each cluster's colour and size.
    const auto entry = [&](const QPen& pen, const QString& text) {
        painter.setPen(pen);
        painter.drawLine(QPointF(side.left(), y + line / 2),
                         QPointF(side.left() + 22, y + line / 2));
        painter.setPen(style.text);
        painter.drawText(QRectF(side.left() + 28, y, side.width() - 28, line),
                         Qt::AlignLeft | Qt::AlignVCenter, text);
        y += 1.25 * line;
    };
    QPen mean(style.text, 1.8, Qt::DashLine);
    mean.setDashPattern({4.0, 2.5});
    entry(mean, QStringLiteral("mean of the members"));
    if (view.medianMember >= 0) {
        const QString name =
            QString::fromStdString(view.memberNames[static_cast<std::size_t>(view.medianMember)]);
        const std::array<QPen, 2> pens = medianPens(style);
        painter.setPen(pens[0]);  // the casing, under entry()'s line
        painter.drawLine(QPointF(side.left(), y + line / 2),
                         QPointF(side.left() + 22, y + line / 2));
        entry(pens[1], QStringLiteral("median: %1").arg(name));
        // The band's swatch: its shade over the fill's middle colour (or the background).
        const QRectF swatch(side.left(), y + 0.15 * line, 22, 0.7 * line);
        if (!view.fill.empty()) painter.fillRect(swatch, QColor(colourAt(view.colourMap, 0.5)));
        painter.fillRect(swatch, bandColour(view, style));
        entry(QPen(Qt::NoPen), QStringLiteral("50 % band"));
        if (!view.outliers.empty()) {
            QPen dashed(style.text, 1.0);
            dashed.setDashPattern(kOutlierDashes);
            entry(dashed, QStringLiteral("outliers (%1)").arg(view.outliers.size()));
        }
    }
    for (const SectionView::LegendEntry& e : view.legend) {
        entry(QPen(toColour(e.colour), 2.0),
              QStringLiteral("cluster %1 (%2)").arg(e.cluster).arg(e.members));
    }
}

}  // namespace

namespace {
// The legend's lines for the contour boxplot: the median, the band, the outliers.
std::size_t boxplotRows(const SectionView& view) {
    if (view.medianMember < 0) return 0;
    return view.outliers.empty() ? 2 : 3;
}
}  // namespace

QRectF sectionPlotRect(const SectionView& view, const QRectF& page, const SectionStyle& style) {
    return layoutOf(view, page, QFontMetricsF(sectionFont(style)), proportionsOf(style)).plot;
}

void paintHoveredMember(QPainter& painter, const SectionView& view, const QRectF& page,
                        std::size_t member, const SectionStyle& style) {
    if (member >= view.members.size()) return;
    const QRectF plot = sectionPlotRect(view, page, style);
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setClipRect(plot);
    strokeEmphasised(painter, view.members[member], plot, kHoveredWidth);
    painter.restore();
}

QSize sectionPictureSize(const SectionView& view, int width, const SectionStyle& style) {
    const QFontMetricsF metrics(sectionFont(style));
    const double line = metrics.height();
    const Proportions p = proportionsOf(style);
    const QRectF wide = layoutOf(view, QRectF(0, 0, width, 1e6), metrics, p).plot;
    // The side column needs its caption, a colour bar and the legend's lines.
    const double side =
        (view.fill.empty() ? 0.0 : 3.0 + 6.0 + 1.2) * line +
        (p.legend ? 1.25 * line * static_cast<double>(view.legend.size() + 1 + boxplotRows(view))
                  : 0.0);
    const double plotHeight = std::max(wide.width() / view.aspect, side);
    return {width, static_cast<int>(
                       std::ceil(plotHeight + 2 * p.margin + (p.linesAbove + kLinesBelow) * line))};
}

void paintSection(QPainter& painter, const SectionView& view, const QRectF& page,
                  const SectionEmphasis& emphasis, const SectionStyle& style) {
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing);
    painter.fillRect(page, style.background);
    const QFont font = sectionFont(style);
    painter.setFont(font);
    const QFontMetricsF metrics(font, painter.device());
    const Proportions proportions = proportionsOf(style);
    const Layout layout = layoutOf(view, page, metrics, proportions);
    const QRectF& plot = layout.plot;

    painter.setPen(style.text);
    if (proportions.titled) {
        QFont heading = font;
        heading.setPointSizeF(style.fontPoints * 1.25);
        heading.setBold(true);
        painter.setFont(heading);
        painter.drawText(layout.title, Qt::AlignLeft | Qt::AlignTop,
                         QString::fromStdString(view.title));
        painter.setFont(font);
        painter.drawText(layout.title, Qt::AlignLeft | Qt::AlignBottom,
                         QString::fromStdString(view.subtitle));
    }

    painter.save();
    painter.setClipRect(plot);
    if (view.fill.empty() || view.columns < 2 || view.rows < 2) {
        painter.fillRect(plot, style.background);
    } else {
        // At the plot's size on screen and in a PNG; an embedded image of at most 1200 pixels
        // across in an SVG or PDF.
        const QTransform t = painter.deviceTransform();
        const double scale = std::max(1.0, std::sqrt(std::abs(t.determinant())));
        const int w = std::clamp(static_cast<int>(plot.width() * scale), 2, 1200);
        const int h = std::clamp(static_cast<int>(plot.height() * scale), 2, 1200);
        painter.drawImage(plot, fillImage(view, w, h));
    }
    strokeLines(painter, view.graticule, plot, QPen(QColor(128, 128, 128, 150), 0.6));
    // The graticule's degrees where each line enters the map, nudged inside it, over a pale
    // underlay so they read on the fill.
    for (const SectionView::PlaceLabel& label : view.graticuleLabels) {
        const QString text = QString::fromStdString(label.text);
        const QFontMetricsF small(painter.font());
        const QSizeF size(small.horizontalAdvance(text) + 4, small.height());
        QPointF at(plot.left() + label.at.x * plot.width(),
                   plot.bottom() - label.at.y * plot.height());
        at.setX(std::clamp(at.x() - size.width() / 2, plot.left() + 1,
                           plot.right() - size.width() - 1));
        at.setY(std::clamp(at.y() - size.height() / 2, plot.top() + 1,
                           plot.bottom() - size.height() - 1));
        const QRectF box(at, size);
        painter.fillRect(box, QColor(255, 255, 255, 170));
        painter.setPen(QColor(60, 60, 60));
        painter.drawText(box, Qt::AlignCenter, text);
    }
    const bool boxplot = !view.bandHighest.empty();
    if (boxplot && view.columns >= 2 && view.rows >= 2) {
        const QTransform t = painter.deviceTransform();
        const double scale = std::max(1.0, std::sqrt(std::abs(t.determinant())));
        const int w = std::clamp(static_cast<int>(plot.width() * scale), 2, 1200);
        const int h = std::clamp(static_cast<int>(plot.height() * scale), 2, 1200);
        painter.drawImage(plot, bandImage(view, w, h, bandColour(view, style)));
        QColor edge = style.text;
        edge.setAlphaF(0.55);
        strokeLines(painter, view.bandEdges, plot, QPen(edge, 0.8));
    }
    // Members: a dark halo under every line first, then the colours, the selected last.
    const bool anySelected = !emphasis.selected.empty();
    const auto isHidden = [&](std::size_t m) {
        return m < emphasis.hidden.size() && emphasis.hidden[m];
    };
    const auto isSelected = [&](std::size_t m) {
        return std::find(emphasis.selected.begin(), emphasis.selected.end(), m) !=
               emphasis.selected.end();
    };
    // Over a fill only: on a plain background the lines read as they are.
    // With the contour boxplot the members step back, as in the 3D view: the band, the median
    // and the outliers summarise them.
    const bool stepBack = anySelected || boxplot;
    if (!view.fill.empty()) drawHalo(painter, view, plot, stepBack ? 40 : 100, isHidden);
    for (const MemberContour& c : view.members) {
        if (isHidden(c.member) || isSelected(c.member) ||
            static_cast<int>(c.member) == emphasis.hovered) {
            continue;
        }
        QColor colour = toColour(c.colour);
        if (anySelected || (boxplot && !view.isOutlier(c.member))) colour.setAlphaF(0.35);
        QPen thin(colour, 1.0);
        thin.setCosmetic(true);
        if (view.isOutlier(c.member)) thin.setDashPattern(kOutlierDashes);
        strokeLines(painter, c.lines, plot, thin);
    }
    if (view.medianMember >= 0 && !isHidden(static_cast<std::size_t>(view.medianMember))) {
        for (const QPen& pen : medianPens(style)) {
            strokeLines(painter, view.members[static_cast<std::size_t>(view.medianMember)].lines,
                        plot, pen);
        }
    }
    for (const MemberContour& c : view.members) {
        if (!isHidden(c.member) && isSelected(c.member) &&
            static_cast<int>(c.member) != emphasis.hovered) {
            strokeEmphasised(painter, c, plot, kSelectedWidth);
        }
    }
    if (emphasis.hovered >= 0 && static_cast<std::size_t>(emphasis.hovered) < view.members.size() &&
        !isHidden(static_cast<std::size_t>(emphasis.hovered))) {
        strokeEmphasised(painter, view.members[static_cast<std::size_t>(emphasis.hovered)], plot,
                         kHoveredWidth);
    }
    // The mean's contour dashed, so the members' lines under it show between the dashes.
    QPen mean(style.text, 1.8, Qt::DashLine);
    mean.setDashPattern({4.0, 2.5});
    strokeLines(painter, view.meanContour, plot, mean);
    // Coastlines and borders on top of everything.
    strokeLines(painter, view.mapLines, plot, QPen(QColor(20, 20, 20), 0.9));
    painter.restore();
    drawAxes(painter, view, plot, metrics, style);
    drawSide(painter, view, layout.side, metrics, style, proportions.legend);
    painter.restore();
}

bool isSectionPictureName(const QString& path) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    return suffix == QLatin1String("png") || suffix == QLatin1String("svg") ||
           suffix == QLatin1String("pdf");
}

void writeSectionPicture(const SectionView& view, const QString& path, QSize size) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    const std::string name = path.toStdString();
    const QRectF page(QPointF(0, 0), QSizeF(size));
    if (suffix == QLatin1String("png")) {
        QImage image(size, QImage::Format_ARGB32_Premultiplied);
        image.fill(Qt::white);
        {
            QPainter painter(&image);
            paintSection(painter, view, page);
        }
        if (!image.save(path)) {
            throw data::Error(data::ErrorKind::WriteFailed, "could not write " + name);
        }
    } else if (suffix == QLatin1String("svg")) {
        QSvgGenerator svg;
        svg.setFileName(path);
        svg.setSize(size);
        svg.setViewBox(page);
        svg.setTitle(QString::fromStdString(view.title));
        svg.setDescription(QString::fromStdString(view.subtitle));
        QPainter painter;
        if (!painter.begin(&svg))
            throw data::Error(data::ErrorKind::WriteFailed, "could not write " + name);
        paintSection(painter, view, page);
        painter.end();
    } else if (suffix == QLatin1String("pdf")) {
        QPdfWriter pdf(path);
        pdf.setPageSize(QPageSize(QSizeF(size), QPageSize::Point));
        pdf.setPageMargins(QMarginsF(0, 0, 0, 0));
        pdf.setResolution(72);
        pdf.setTitle(QString::fromStdString(view.title));
        QPainter painter;
        if (!painter.begin(&pdf))
            throw data::Error(data::ErrorKind::WriteFailed, "could not write " + name);
        paintSection(painter, view, page);
        painter.end();
    } else {
        throw data::Error(data::ErrorKind::InvalidArgument,
                          name + ": the picture's name must end in .png, .svg or .pdf");
    }
    if (!QFileInfo::exists(path))
        throw data::Error(data::ErrorKind::WriteFailed, "could not write " + name);
}

}  // namespace ensil::engine
