#include "gl/view_overlay.h"

#include <QFont>
#include <QFontMetricsF>
#include <QImage>
#include <QLinearGradient>
#include <QPainter>
#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <map>

#include "data/number_text.h"
#include "data/vertical_scale.h"
#include "gl/axis_ticks.h"
#include "gl/palette.h"

namespace ensil::gl {
namespace {
constexpr float kTickOffsetPx = 8.0F;    // from the edge to a tick label
constexpr float kTitleOffsetPx = 30.0F;  // from the edge to the axis title

struct Projector {
    glm::mat4 viewProjection;
    float width, height;
    // Pixel position (top-left origin) and whether the point is in front of the camera.
    [[nodiscard]] std::pair<glm::vec2, bool> operator()(const glm::vec3& p) const {
        const glm::vec4 c = viewProjection * glm::vec4(p, 1.0F);
        if (c.w <= 1e-6F) return {{0.0F, 0.0F}, false};
        return {{(c.x / c.w * 0.5F + 0.5F) * width, (0.5F - c.y / c.w * 0.5F) * height}, true};
    }
};

QString axisTitle(const data::Axis& axis, const std::string& units) {
    const QString name = QString::fromStdString(axis.name);
    return units.empty() ? name
                         : QStringLiteral("%1 (%2)").arg(name, QString::fromStdString(units));
}

// The vertical axis's title says how much the box stretches heights (data/vertical_scale.h):
// "plev (hPa), vertical ×480", the factor to two significant digits (for pressure levels through
// the standard atmosphere's heights, which METHODS.md and --json say). A pressure axis drawn
// other than through log-pressure says how: "plev (hPa), linear in pressure, vertical ×480".
QString verticalAxisTitle(const QString& given, const OverlayInput& in) {
    QString title = given;
    if (in.frame->pressureAxis() && in.frame->verticalAxis() == data::VerticalAxis::Pressure) {
        title += QStringLiteral(", linear in pressure");
    } else if (in.frame->pressureAxis() &&
               in.frame->verticalAxis() == data::VerticalAxis::StandardHeight) {
        title += QStringLiteral(", at standard-atmosphere heights");
    }
    const auto scale = data::verticalScaleOf(*in.grid, *in.frame);
    if (!scale) return title;
    const double f = scale->factor;
    const double magnitude = std::pow(10.0, std::floor(std::log10(f)) - 1.0);
    const double rounded =
        f >= 10.0 ? std::round(f / magnitude) * magnitude : std::round(f * 10.0) / 10.0;
    return QStringLiteral("%1, vertical \u00d7%2")
        .arg(title, QString::fromStdString(data::readableNumber(rounded)));
}

// An edge seen end-on (the vertical one from straight above) has no room for labels: they
// would pile up on one point.
constexpr float kShortestLabelledEdgePx = 40.0F;

// Tick labels and the title of axis `a` along the box edge through `corner` parallel to it.
void labelAxis(int a, glm::vec3 corner, const OverlayInput& in, const Projector& project,
               const glm::vec2& centrePx, std::vector<OverlayLabel>& labels) {
    const data::Axis& axis = in.grid->axis(a);
    glm::vec3 far = corner;
    far[a] = in.frame->boxMax()[a];
    glm::vec3 near = corner;
    near[a] = in.frame->boxMin()[a];
    const auto [nearPx, nearVisible] = project(near);
    const auto [farPx, farVisible] = project(far);
    if (nearVisible && farVisible && glm::distance(nearPx, farPx) < kShortestLabelledEdgePx) {
        return;
    }
    const auto place = [&](float displayCoordinate, QString text, float offset, bool title) {
        glm::vec3 p = corner;
        p[a] = displayCoordinate;
        const auto [pixel, visible] = project(p);
        if (!visible) return;
        glm::vec2 away = pixel - centrePx;
        away = glm::length(away) > 1e-3F ? glm::normalize(away) : glm::vec2(0.0F, 1.0F);
        labels.push_back(
            {pixel + offset * away, away, std::move(text), title, a, title ? 0 : (a == 2 ? 1 : 2)});
    };
    const glm::dvec3 origin{in.grid->x().front(), in.grid->y().front(), in.grid->z().front()};
    const AxisLabelling labelling = labellingFor(axis);
    for (const double tick : labelling.ticks) {
        glm::dvec3 point = origin;
        point[a] = tick;
        place(in.frame->toDisplay(point)[a], formatTick(tick * labelling.shownPerUnit),
              kTickOffsetPx, false);
    }
    const QString title = axisTitle(axis, labelling.units);
    place(0.5F * (in.frame->boxMin()[a] + in.frame->boxMax()[a]),
          a == 2 ? verticalAxisTitle(title, in) : title, kTitleOffsetPx, true);
}
// The legend's place: the first corner (top left, top right, bottom left, bottom right) where
// it keeps clear of the data box on screen, else the corner where it covers least of it.
constexpr double kLabelGap = 4.0;  // logical pixels between two labels side by side

QRectF legendPlace(QSizeF size, double top, const QRectF& dataBox, QSizeF picture, double margin) {
    const double right = picture.width() - margin - size.width();
    const double bottom = picture.height() - margin - size.height();
    const std::array<QPointF, 4> corners{QPointF(margin, top), QPointF(right, top),
                                         QPointF(margin, bottom), QPointF(right, bottom)};
    QRectF best(corners[0], size);
    double leastCovered = std::numeric_limits<double>::max();
    for (const QPointF& corner : corners) {
        const QRectF place(corner, size);
        const QRectF covered = place.intersected(dataBox);
        const double area = covered.isEmpty() ? 0.0 : covered.width() * covered.height();
        if (area < leastCovered) {
            leastCovered = area;
            best = place;
        }
        if (area == 0.0) break;
    }
    return best;
}

constexpr double kMargin = 10.0;         // from the picture's edge to a panel
constexpr double kTextPoints = 9.0;      // labels, legend, colour bar
constexpr double kHeadingPoints = 10.5;  // the title line
constexpr double kPad = 6.0;             // inside a panel
constexpr double kBarHeight = 10.0;

QColor panelColour(const ViewOverlay& overlay) {
    return overlay.text.lightness() > 128 ? QColor(0, 0, 0, 110) : QColor(255, 255, 255, 150);
}

// One colour bar: caption, a viridis gradient, the values at its ends.
double colourScaleHeight(const QFontMetricsF& metrics) {
    return 2 * metrics.height() + kBarHeight + 2 * kPad;
}

QSizeF colourScalesSize(const std::vector<ColourScale>& scales, const QFontMetricsF& metrics) {
    double width = 160.0;
    for (const ColourScale& scale : scales) {
        width = std::max(width, metrics.horizontalAdvance(scale.caption));
    }
    return {width + 2 * kPad,
            static_cast<double>(scales.size()) * colourScaleHeight(metrics) + 1.5 * kPad};
}

// The colour bars, one under the other in one panel.
void drawColourScales(QPainter& painter, const ViewOverlay& overlay, const QFont& font,
                      const QRectF& place) {
    const QFontMetricsF metrics(font);
    painter.setPen(Qt::NoPen);
    painter.setBrush(panelColour(overlay));
    painter.drawRoundedRect(place, 4.0, 4.0);
    painter.setFont(font);
    const double inner = place.width() - 2 * kPad;
    double top = place.top() + kPad;
    for (const ColourScale& scale : overlay.colourScales) {
        painter.setPen(overlay.text);
        const QRectF caption(place.left() + kPad, top, inner, metrics.height());
        painter.drawText(caption, Qt::AlignLeft | Qt::AlignVCenter, scale.caption);
        const QRectF bar(place.left() + kPad, caption.bottom() + kPad / 2, inner, kBarHeight);
        QLinearGradient gradient(bar.topLeft(), bar.topRight());
        for (int i = 0; i <= 16; ++i) {
            const float t = static_cast<float>(i) / 16.0F;
            const glm::vec3 c = glm::clamp(viridis(t), glm::vec3(0.0F), glm::vec3(1.0F));
            gradient.setColorAt(t, QColor::fromRgbF(c.r, c.g, c.b));
        }
        painter.setPen(Qt::NoPen);
        painter.setBrush(gradient);
        painter.drawRect(bar);
        painter.setPen(overlay.text);
        const QRectF ends(bar.left(), bar.bottom() + kPad / 2, bar.width(), metrics.height());
        painter.drawText(ends, Qt::AlignLeft | Qt::AlignTop,
                         QString::fromStdString(data::readableNumber(scale.minimum)));
        painter.drawText(ends, Qt::AlignRight | Qt::AlignTop,
                         QString::fromStdString(data::readableNumber(scale.maximum)));
        top += colourScaleHeight(metrics);
    }
}

QSizeF legendSize(const std::vector<LegendEntry>& legend, const QFontMetricsF& metrics) {
    const double row = metrics.height() + 4.0, swatch = metrics.height() - 2.0;
    double textWidth = 0.0;
    for (const LegendEntry& e : legend) {
        textWidth = std::max(textWidth, metrics.horizontalAdvance(e.text));
    }
    return {kPad * 3 + swatch + textWidth + 2.0,
            kPad * 2 + row * static_cast<double>(legend.size()) - 4.0};
}

void drawLegend(QPainter& painter, const ViewOverlay& overlay, const QFont& font,
                const QRectF& box) {
    const QFontMetricsF metrics(font);
    const double row = metrics.height() + 4.0, swatch = metrics.height() - 2.0;
    painter.setFont(font);
    painter.setPen(Qt::NoPen);
    painter.setBrush(panelColour(overlay));
    painter.drawRoundedRect(box, 4.0, 4.0);
    double y = box.top() + kPad;
    for (const LegendEntry& e : overlay.legend) {
        const QColor colour = QColor::fromRgbF(e.color.r, e.color.g, e.color.b);
        const QRectF square(box.left() + kPad, y + 1.0, swatch, swatch);
        switch (e.swatch) {
            case Swatch::Filled:
                painter.setPen(Qt::NoPen);
                painter.setBrush(colour);
                painter.drawRect(square);
                break;
            case Swatch::Band: {
                QColor translucent = colour;
                translucent.setAlphaF(0.4F);
                painter.setPen(QPen(colour, 1.0));
                painter.setBrush(translucent);
                painter.drawRect(square.adjusted(0.5, 0.5, -0.5, -0.5));
                break;
            }
            case Swatch::Dashed: {
                QPen dashes(colour, std::max(2.0, swatch / 5.0), Qt::CustomDashLine, Qt::FlatCap);
                dashes.setDashPattern({1.5, 1.0});
                painter.setPen(dashes);
                painter.setBrush(Qt::NoBrush);
                painter.drawLine(QPointF(square.left(), square.center().y()),
                                 QPointF(square.right(), square.center().y()));
                break;
            }
        }
        painter.setPen(overlay.text);
        painter.drawText(
            QRectF(box.left() + 2 * kPad + swatch, y, box.width() - 3 * kPad - swatch, row),
            Qt::AlignLeft | Qt::AlignTop, e.text);
        y += row;
    }
}

}  // namespace

QString formatTick(double value) {
    if (value == 0.0) return QStringLiteral("0");
    const double magnitude = std::abs(value);
    if (magnitude >= 1e-3 && magnitude < 1e6) {
        QString text = QString::number(value, 'f', 6);
        while (text.endsWith(QLatin1Char('0'))) text.chop(1);
        if (text.endsWith(QLatin1Char('.'))) text.chop(1);
        return text;
    }
    return QString::number(value, 'g', 4);
}

ViewOverlay computeOverlay(const OverlayInput& in) {
    ViewOverlay overlay;
    const float luminance = glm::dot(in.background, glm::vec3(0.2126F, 0.7152F, 0.0722F));
    overlay.text = luminance > 0.5F ? QColor(30, 30, 30) : QColor(225, 225, 225);
    overlay.title = in.title;
    overlay.colourScales = in.colourScales;
    if (in.width <= 0 || in.height <= 0) return overlay;

    if (in.showAxes && in.grid != nullptr && in.frame != nullptr) {
        const Projector project{in.viewProjection, static_cast<float>(in.width),
                                static_cast<float>(in.height)};
        const glm::vec3 lo = in.frame->boxMin(), hi = in.frame->boxMax();
        const glm::vec2 centrePx = project(0.5F * (lo + hi)).first;
        glm::vec2 boxMin(std::numeric_limits<float>::max());
        glm::vec2 boxMax(-std::numeric_limits<float>::max());
        bool allVisible = true;
        for (int c = 0; c < 8; ++c) {
            const auto [px, visible] =
                project({c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z});
            allVisible = allVisible && visible;
            boxMin = glm::min(boxMin, px);
            boxMax = glm::max(boxMax, px);
        }
        if (allVisible) {
            overlay.box = QRectF(QPointF(boxMin.x, boxMin.y), QPointF(boxMax.x, boxMax.y));
        }
        // x along the bottom edge on the viewer's side in y, y along the bottom edge on the
        // viewer's side in x, z up the vertical edge furthest left on screen.
        const float nearY = std::abs(in.eye.y - lo.y) < std::abs(in.eye.y - hi.y) ? lo.y : hi.y;
        const float nearX = std::abs(in.eye.x - lo.x) < std::abs(in.eye.x - hi.x) ? lo.x : hi.x;
        labelAxis(0, {lo.x, nearY, lo.z}, in, project, centrePx, overlay.labels);
        labelAxis(1, {nearX, lo.y, lo.z}, in, project, centrePx, overlay.labels);
        glm::vec3 left{lo.x, lo.y, lo.z};
        float leftmost = std::numeric_limits<float>::max();
        for (const float x : {lo.x, hi.x}) {
            for (const float y : {lo.y, hi.y}) {
                const float px = project({x, y, lo.z}).first.x;
                if (px < leftmost) {
                    leftmost = px;
                    left = {x, y, lo.z};
                }
            }
        }
        labelAxis(2, left, in, project, centrePx, overlay.labels);
        for (const auto& [point, text] : in.floorLabels) {
            const auto [pixel, visible] = project(point);
            if (!visible) continue;
            glm::vec2 away = pixel - centrePx;
            away = glm::length(away) > 1e-3F ? glm::normalize(away) : glm::vec2(0.0F, 1.0F);
            overlay.labels.push_back(
                {pixel + 0.5F * kTickOffsetPx * away, away, text, false, -1, 3});
        }
    }

    if (in.showLegend && in.appearance != nullptr) {
        // cluster (its stable number) -> colour, visible members
        std::map<int, std::pair<glm::vec3, int>> clusters;
        for (const MemberAppearance& a : *in.appearance) {
            if (a.cluster < 0) continue;
            auto [it, added] = clusters.try_emplace(a.cluster, a.color, 0);
            if (a.visible) ++it->second.second;
        }
        // Beyond the palette: one entry for every cluster drawn in the "other" colour.
        int otherClusters = 0, otherMembers = 0;
        for (auto it = clusters.begin(); it != clusters.end();) {
            if (static_cast<std::size_t>(it->first) < kClusterPalette.size()) {
                ++it;
                continue;
            }
            ++otherClusters;
            otherMembers += it->second.second;
            it = clusters.erase(it);
        }
        for (const auto& [cluster, entry] : clusters) {
            const int n = entry.second;
            // With the band shown the members (but its outliers and any selected) step back,
            // and their swatch shows them so.
            overlay.legend.push_back(
                {in.band ? steppedBack(entry.first, in.background) : entry.first,
                 n == 0 ? QStringLiteral("Cluster %1 \u00b7 hidden").arg(cluster + 1)
                 : n == 1
                     ? QStringLiteral("Cluster %1 \u00b7 1 member").arg(cluster + 1)
                     : QStringLiteral("Cluster %1 \u00b7 %2 members").arg(cluster + 1).arg(n)});
        }
        if (otherClusters > 0) {
            overlay.legend.push_back(
                {kOtherClustersColor, QStringLiteral("%1 other clusters \u00b7 %2 members")
                                          .arg(otherClusters)
                                          .arg(otherMembers)});
        }
        if (in.showMean) overlay.legend.push_back({kMeanSurfaceColor, in.contextName});
        if (in.band) {
            overlay.legend.push_back({in.bandColor, QStringLiteral("50 % band"), Swatch::Band});
            if (in.outliers > 0) {
                overlay.legend.push_back(
                    {in.bandColor,
                     in.outliers == 1 ? QStringLiteral("1 outlier (dashed)")
                                      : QStringLiteral("%1 outliers (dashed)").arg(in.outliers),
                     Swatch::Dashed});
            }
        }
        if (in.planeCurves) {
            overlay.legend.push_back(
                {in.planeColor, QStringLiteral("Plane curves (dashed)"), Swatch::Dashed});
        }
    }
    return overlay;
}

double exportTextScale(int height) { return std::max(1.0, height / kReferenceHeight); }

void paintOverlay(QPainter& painter, const ViewOverlay& overlay, double pixelRatio) {
    paintOverlay(painter, overlay, pixelRatio,
                 QSizeF(painter.device()->width(), painter.device()->height()));
}

namespace {
// Text is measured for the device it is painted on, never for "the screen": without a display
// server the platform's screen has another resolution, and the same picture would be laid out
// differently. Without a device (framing the camera), as for a picture, which a QImage is.
QFont overlayFont(const QPaintDevice* device) {
    static const QImage picture(1, 1, QImage::Format_RGB32);
    QFont font(QFont(), device != nullptr ? device : &picture);
    font.setPointSizeF(kTextPoints);
    return font;
}

QFont headingFont(const QPaintDevice* device) {
    QFont heading = overlayFont(device);
    heading.setPointSizeF(kHeadingPoints);
    heading.setBold(true);
    return heading;
}

QFontMetricsF headingMetrics(const QPaintDevice* device) {
    return QFontMetricsF(headingFont(device));
}

// The title's strip: its lines' height at this width.
double titleHeight(const QString& title, const QPaintDevice* device, double width) {
    const QFontMetricsF metrics = headingMetrics(device);
    const auto lines = static_cast<double>(titleLines(title, metrics, width).size());
    return metrics.height() + (lines - 1.0) * metrics.lineSpacing();
}
}  // namespace

QStringList titleLines(const QString& title, const QFontMetricsF& metrics, double width) {
    if (metrics.horizontalAdvance(title) <= width) return {title};
    const QString separator = QStringLiteral(" \u00b7 ");
    // The longest first line of whole facts that fits; the first fact alone if none does.
    qsizetype cut = title.indexOf(separator);
    if (cut < 0) return {metrics.elidedText(title, Qt::ElideMiddle, width)};
    for (qsizetype next = title.indexOf(separator, cut + 1);
         next >= 0 && metrics.horizontalAdvance(title.left(next)) <= width;
         next = title.indexOf(separator, next + 1)) {
        cut = next;
    }
    return {metrics.elidedText(title.left(cut), Qt::ElideMiddle, width),
            metrics.elidedText(title.mid(cut + separator.size()), Qt::ElideMiddle, width)};
}

PanelPlaces placePanels(const ViewOverlay& overlay, QSizeF logicalSize, const QRectF& dataBox,
                        const QPaintDevice* device) {
    // The title line centred at the top (elided when the picture is narrower), the legend in a
    // corner clear of the data box, the floor's colour bar in another corner clear of both
    // (left out when none is).
    PanelPlaces places;
    const QFontMetricsF metrics(overlayFont(device));
    double panelTop = kMargin;
    if (!overlay.title.isEmpty()) {
        const double width = logicalSize.width() - 2 * kMargin;
        places.title = QRectF(kMargin, 6.0, width, titleHeight(overlay.title, device, width));
        panelTop = places.title.bottom() + 6.0;
    }
    if (!overlay.legend.empty()) {
        places.legend = legendPlace(legendSize(overlay.legend, metrics), panelTop, dataBox,
                                    logicalSize, kMargin);
    }
    if (!overlay.colourScales.empty()) {
        const QSizeF size = colourScalesSize(overlay.colourScales, metrics);
        const QRectF& legend = places.legend;
        const QRectF taken = legend.isEmpty()    ? dataBox
                             : dataBox.isEmpty() ? legend
                                                 : dataBox.united(legend);
        QRectF bar = legendPlace(size, panelTop, dataBox, logicalSize, kMargin);
        if (!legend.isEmpty() && bar.intersects(legend)) {
            bar = legendPlace(size, panelTop, taken, logicalSize, kMargin);
        }
        if (!legend.isEmpty() && bar.intersects(legend)) bar = QRectF();
        places.colourBar = bar;
    }
    return places;
}

PanelRoom panelRoom(const ViewOverlay& overlay, double logicalWidth) {
    const QFontMetricsF metrics(overlayFont(nullptr));
    PanelRoom room;
    if (!overlay.title.isEmpty()) {
        room.top = 6.0 + titleHeight(overlay.title, nullptr, logicalWidth - 2 * kMargin) + 6.0;
    }
    if (!overlay.legend.empty()) room.legend = legendSize(overlay.legend, metrics);
    if (!overlay.colourScales.empty()) {
        room.colourBar = colourScalesSize(overlay.colourScales, metrics);
    }
    if (!overlay.labels.empty()) room.axisLabels = 2.0 * metrics.height() + kTickOffsetPx;
    room.margin = kMargin;
    return room;
}

void paintOverlay(QPainter& painter, const ViewOverlay& overlay, double pixelRatio,
                  QSizeF logicalSize, std::vector<PaintedItem>* painted) {
    const auto record = [&](const QRectF& rect, const QString& text) {
        if (painted != nullptr) painted->push_back({rect, text});
    };
    if (overlay.labels.empty() && overlay.legend.empty() && overlay.message.isEmpty() &&
        overlay.title.isEmpty()) {
        return;
    }
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setRenderHint(QPainter::TextAntialiasing);
    const auto scale = static_cast<float>(1.0 / std::max(pixelRatio, 1e-3));
    const QFont font = overlayFont(painter.device());
    QFont titleFont = font;
    titleFont.setBold(true);
    const QRectF dataBox = overlay.box.isEmpty()
                               ? QRectF()
                               : QRectF(overlay.box.topLeft() * scale, overlay.box.size() * scale);
    const PanelPlaces panels = placePanels(overlay, logicalSize, dataBox, painter.device());
    std::vector<QRectF> placed;
    if (!panels.title.isEmpty()) {
        const QFont heading = headingFont(painter.device());
        painter.setFont(heading);
        const QFontMetricsF headingMetrics(heading);
        const QStringList lines = titleLines(overlay.title, headingMetrics, panels.title.width());
        painter.setPen(overlay.text);
        double widest = 0.0;
        for (qsizetype i = 0; i < lines.size(); ++i) {
            const QRectF line(
                panels.title.left(),
                panels.title.top() + static_cast<double>(i) * headingMetrics.lineSpacing(),
                panels.title.width(), headingMetrics.height());
            painter.drawText(line, Qt::AlignHCenter | Qt::AlignTop, lines[i]);
            widest = std::max(widest, headingMetrics.horizontalAdvance(lines[i]));
        }
        record(QRectF(panels.title.center().x() - 0.5 * widest, panels.title.top(), widest,
                      panels.title.height()),
               QStringLiteral("title"));
        placed.push_back(panels.title);
    }
    const QRectF legendRect = panels.legend;
    if (!legendRect.isEmpty()) placed.push_back(legendRect);
    const QRectF barRect = panels.colourBar;
    if (!barRect.isEmpty()) placed.push_back(barRect);
    // Where edges meet (or the box is seen edge-on) labels would pile up: the first one
    // placed keeps its place and later ones that would overlap it are left out. Titles
    // first: where space is short, a title says more than one tick value; then the vertical
    // levels (OverlayLabel::priority).
    std::vector<const OverlayLabel*> order;
    for (const OverlayLabel& label : overlay.labels) order.push_back(&label);
    std::stable_sort(order.begin(), order.end(), [](const OverlayLabel* a, const OverlayLabel* b) {
        return a->priority < b->priority;
    });
    // The vertical axis's title beside an upright edge (a side view, most oblique ones) is
    // written upwards beyond its tick values, as a plot's y axis: level by level, written
    // across, it covered a tick value (and the tick was left out) or ran off the picture.
    double widestVerticalTick = 0.0;
    for (const OverlayLabel& label : overlay.labels) {
        if (label.axis == 2 && !label.title) {
            widestVerticalTick =
                std::max(widestVerticalTick, QFontMetricsF(font).horizontalAdvance(label.text));
        }
    }
    for (const OverlayLabel* entry : order) {
        const OverlayLabel& label = *entry;
        painter.setFont(label.title ? titleFont : font);
        const bool upright = label.title && label.axis == 2 &&
                             std::abs(label.direction.x) > std::abs(label.direction.y);
        QSizeF size = QFontMetricsF(painter.font()).size(Qt::TextSingleLine, label.text);
        if (upright) size.transpose();
        // The anchor sits on the label's side facing the box: a label pushed right starts at
        // the anchor, one pushed left ends there, and likewise vertically.
        glm::vec2 p = label.pixel * scale;
        if (upright) {
            p += label.direction * (static_cast<float>(widestVerticalTick + kLabelGap) +
                                    (kTickOffsetPx - kTitleOffsetPx) * scale);
        }
        const double x = p.x - 0.5 * size.width() * (1.0 - label.direction.x);
        const double y = p.y - 0.5 * size.height() * (1.0 - label.direction.y);
        // Kept inside the picture: a title beside a box edge near the border would be cut.
        const double maxX = logicalSize.width() - size.width() - 2.0;
        const double maxY = logicalSize.height() - size.height() - 2.0;
        const QRectF rect(QPointF(std::clamp(x, 2.0, std::max(2.0, maxX)),
                                  std::clamp(y, 2.0, std::max(2.0, maxY))),
                          size);
        // Labels that merely touch read as one ("359" beside "4°W" read "3594°W"): each
        // keeps a gap of a few pixels to the others.
        const QRectF spaced = rect.adjusted(-kLabelGap, -1.0, kLabelGap, 1.0);
        if (std::any_of(placed.begin(), placed.end(),
                        [&](const QRectF& other) { return other.intersects(spaced); })) {
            continue;
        }
        placed.push_back(rect);
        record(rect, label.text);
        painter.setPen(overlay.text);
        if (upright) {
            painter.save();
            painter.translate(rect.center());
            painter.rotate(-90.0);
            painter.drawText(
                QRectF(-0.5 * rect.height(), -0.5 * rect.width(), rect.height(), rect.width()),
                Qt::AlignCenter, label.text);
            painter.restore();
        } else {
            painter.drawText(rect, Qt::AlignCenter, label.text);
        }
    }
    if (!overlay.message.isEmpty()) {
        QFont large = font;
        large.setPointSizeF(12.0);
        painter.setFont(large);
        painter.setPen(overlay.text);
        painter.drawText(QRectF(QPointF(0.0, 0.0), logicalSize), Qt::AlignCenter | Qt::TextWordWrap,
                         overlay.message);
    }
    if (!legendRect.isEmpty()) {
        drawLegend(painter, overlay, font, legendRect);
        record(legendRect, QStringLiteral("legend"));
    }
    if (!barRect.isEmpty()) {
        drawColourScales(painter, overlay, font, barRect);
        record(barRect, QStringLiteral("colour bar"));
    }
    painter.restore();
}

}  // namespace ensil::gl
