#include "engine/ensemble_section.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "data/ascii_case.h"
#include "data/ensemble_reader.h"
#include "data/error.h"
#include "data/number_text.h"
#include "data/units_text.h"
#include "engine/picture_title.h"
#include "engine/preprocess_run.h"
#include "engine/section_place.h"
#include "geo/map_projection.h"
#include "gl/axis_ticks.h"
#include "gl/palette.h"
#include "preprocessing/field_section.h"

namespace ensil::engine {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// Lattice coordinates (fractional column, row) to the plot's unit square.
double across(const std::vector<double>& positions, double index) {
    const double i = std::clamp(index, 0.0, static_cast<double>(positions.size() - 1));
    const auto lo = std::min(static_cast<std::size_t>(i), positions.size() - 2);
    const double f = i - static_cast<double>(lo);
    return positions[lo] + f * (positions[lo + 1] - positions[lo]);
}

std::vector<SectionLine> toPlot(const std::vector<prep::ContourLine>& lines,
                                const SectionLayout& layout) {
    std::vector<SectionLine> out;
    out.reserve(lines.size());
    for (const prep::ContourLine& line : lines) {
        SectionLine plotted{{}, line.closed};
        plotted.points.reserve(line.points.size());
        for (const glm::dvec2& p : line.points) {
            plotted.points.emplace_back(across(layout.columnPositions, p.x),
                                        across(layout.rowPositions, p.y));
        }
        out.push_back(std::move(plotted));
    }
    return out;
}

// Per sample, over the members with a value there: the mean, the sample standard deviation
// (NaN below two members), the share above the isovalue.
struct SampleMoments {
    std::vector<float> mean, spread, probability;
};

SampleMoments momentsOf(const std::vector<std::vector<float>>& members, std::size_t samples,
                        float isovalue) {
    SampleMoments m{std::vector<float>(samples, kNaN), std::vector<float>(samples, kNaN),
                    std::vector<float>(samples, kNaN)};
    for (std::size_t s = 0; s < samples; ++s) {
        double sum = 0.0, squares = 0.0;
        int n = 0, above = 0;
        for (const std::vector<float>& member : members) {
            const float v = member[s];
            if (std::isnan(v)) continue;
            sum += v;
            ++n;
            above += v > isovalue ? 1 : 0;
        }
        if (n == 0) continue;
        const double mean = sum / n;
        for (const std::vector<float>& member : members) {
            if (!std::isnan(member[s])) squares += (member[s] - mean) * (member[s] - mean);
        }
        m.mean[s] = static_cast<float>(mean);
        m.probability[s] = static_cast<float>(above) / static_cast<float>(n);
        if (n > 1) m.spread[s] = static_cast<float>(std::sqrt(squares / (n - 1)));
    }
    return m;
}

}  // namespace

void applySectionColours(SectionRequest& request, const session::SectionsColours& colours) {
    request.colourMap = colours.map;
    request.range.reset();
    if (colours.fixedRange) request.range = std::pair{colours.minimum, colours.maximum};
}

namespace {

// The band's bounding fields over the band members, as section 17's band surfaces take them:
// the lowest value is missing where any band member is (such a point is in no intersection),
// the highest only where all are.
void addBoxplot(SectionView& view, const SectionBoxplot& boxplot) {
    const std::size_t samples = view.columns * view.rows;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    view.bandLowest.assign(samples, std::numeric_limits<float>::infinity());
    view.bandHighest.assign(samples, nan);
    for (const std::size_t m : boxplot.bandMembers) {
        const std::vector<float>& values = view.memberValues[m];
        for (std::size_t s = 0; s < samples; ++s) {
            const float v = values[s];
            view.bandLowest[s] = std::isnan(v) ? nan : std::min(view.bandLowest[s], v);
            if (!std::isnan(v)) {
                view.bandHighest[s] =
                    std::isnan(view.bandHighest[s]) ? v : std::max(view.bandHighest[s], v);
            }
        }
    }
    for (const std::vector<float>* field : {&view.bandLowest, &view.bandHighest}) {
        std::vector<SectionLine> edges =
            toPlot(prep::contourLines(*field, view.columns, view.rows, view.isovalue), view);
        view.bandEdges.insert(view.bandEdges.end(), edges.begin(), edges.end());
    }
    view.medianMember = boxplot.median;
    view.outliers = boxplot.outliers;
}

}  // namespace

bool SectionView::isOutlier(std::size_t member) const {
    return std::find(outliers.begin(), outliers.end(), member) != outliers.end();
}

std::size_t bandSampleCount(const SectionView& view) {
    std::size_t count = 0;
    for (std::size_t s = 0; s < view.bandHighest.size(); ++s) count += view.inBand(s) ? 1 : 0;
    return count;
}

std::optional<SectionBoxplot> sectionBoxplotOf(const PreprocessResult& result) {
    if (result.boxplot.bandMembers.empty()) return std::nullopt;
    return SectionBoxplot{result.boxplot.bandMembers, static_cast<int>(result.boxplot.median),
                          result.boxplot.outliers};
}

SectionView buildSection(const data::Ensemble& ensemble, const SectionRequest& request) {
    const std::size_t memberCount = ensemble.members.size();
    if (memberCount == 0) {
        throw data::Error(data::ErrorKind::InvalidArgument, "a section needs members");
    }
    const bool oneMember =
        request.fill == SectionFill::Member || request.fill == SectionFill::Anomaly;
    if (oneMember &&
        (request.member < 0 || static_cast<std::size_t>(request.member) >= memberCount)) {
        throw data::Error(data::ErrorKind::InvalidArgument,
                          "member " + std::to_string(request.member + 1) + " is not one of the " +
                              std::to_string(memberCount) + " members (1 to " +
                              std::to_string(memberCount) + ")");
    }
    if (request.boxplot) {
        const SectionBoxplot& b = *request.boxplot;
        bool inRange = b.median < static_cast<int>(memberCount);
        for (const auto* list : {&b.bandMembers, &b.outliers}) {
            for (const std::size_t m : *list) inRange = inRange && m < memberCount;
        }
        if (!inRange) {
            throw data::Error(data::ErrorKind::InvalidArgument,
                              "the contour boxplot names members beyond the " +
                                  std::to_string(memberCount) + " the section has");
        }
    }
    if (request.range &&
        !(std::isfinite(request.range->first) && std::isfinite(request.range->second) &&
          request.range->first < request.range->second)) {
        throw data::Error(data::ErrorKind::InvalidArgument,
                          "the fixed colour range " +
                              data::readableNumber(request.range->first, 6) + " to " +
                              data::readableNumber(request.range->second, 6) +
                              " is refused: its lower end must lie below its upper end");
    }
    PlacedSection placed = placeSection(ensemble, request.place);
    const prep::SectionLattice lattice = std::move(placed.lattice);
    SectionView view;
    static_cast<SectionLayout&>(view) = std::move(placed);
    view.columns = lattice.columns;
    view.rows = lattice.rows;
    const std::string& name = ensemble.variable;
    const char* joint = request.place.kind == SectionKind::Map    ? " at "
                        : request.place.kind == SectionKind::Path ? " from "
                                                                  : " along ";
    view.title = name + joint + view.placeText;

    // Every member's samples are kept (hover, Python): refused before they are taken when they
    // would not fit (1,000 members on a 1440 x 721 map are 4 GB).
    const std::size_t samples = lattice.indices.size();
    data::checkMemoryFor((memberCount + 4) * samples * sizeof(float),
                         "a section of " + std::to_string(memberCount) + " members x " +
                             std::to_string(samples) + " samples");
    view.memberValues.reserve(memberCount);
    view.units = data::readableUnits(ensemble.units);
    for (const data::Member& member : ensemble.members) {
        view.memberNames.push_back(member.name);
        view.memberValues.push_back(prep::sampleSection(ensemble.grid, member.values, lattice));
    }
    const SampleMoments moments = momentsOf(view.memberValues, samples, request.isovalue);
    const std::string units = unitsInBrackets(ensemble);
    const auto memberName = [&](int m) {
        return ensemble.members[static_cast<std::size_t>(m)].name;
    };
    switch (request.fill) {
        case SectionFill::None:
            break;
        case SectionFill::Member:
            view.fill = view.memberValues[static_cast<std::size_t>(request.member)];
            view.fillCaption = memberName(request.member) + ": " + name + units;
            break;
        case SectionFill::Mean:
            view.fill = moments.mean;
            view.fillCaption = "mean " + name + units;
            break;
        case SectionFill::Spread:
            view.fill = moments.spread;
            view.fillCaption = "standard deviation of " + name + units;
            break;
        case SectionFill::Probability:
            view.fill = moments.probability;
            view.fillCaption = exceedanceText(ensemble, request.isovalue);
            view.colourMap = SectionColourMap::YlGnBu;
            break;
        case SectionFill::Anomaly: {
            view.fill = view.memberValues[static_cast<std::size_t>(request.member)];
            for (std::size_t s = 0; s < samples; ++s) view.fill[s] -= moments.mean[s];
            view.fillCaption = memberName(request.member) + " minus the mean, " + name + units;
            view.colourMap = SectionColourMap::RdBu;
            break;
        }
    }
    // The colour bar spans the section's own values (a difference: symmetric about 0; a
    // probability: 0 to 1; a spread: from 0), so the map has the contrast its values allow,
    // unless the user fixed it (to compare sections, or times, on one scale).
    if (request.colourMap != SectionColourMap::Automatic) view.colourMap = request.colourMap;
    if (!view.fill.empty() && request.range) {
        view.fillMinimum = static_cast<float>(request.range->first);
        view.fillMaximum = static_cast<float>(request.range->second);
        view.colourTicks = gl::niceTicks(request.range->first, request.range->second, 6);
    } else if (!view.fill.empty()) {
        float lo = std::numeric_limits<float>::max(), hi = std::numeric_limits<float>::lowest();
        for (const float v : view.fill) {
            if (std::isnan(v)) continue;
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
        if (lo > hi) lo = hi = 0.0F;  // nothing but missing values
        if (request.fill == SectionFill::Probability) {
            lo = 0.0F;
            hi = 1.0F;
        } else if (request.fill == SectionFill::Anomaly) {
            hi = std::max(std::abs(lo), std::abs(hi));
            lo = -hi;
        } else if (request.fill == SectionFill::Spread) {
            lo = 0.0F;
        }
        if (!(hi > lo)) {
            const float pad = std::max(1.0F, std::abs(hi)) * 0.5F;
            lo -= pad;
            hi += pad;
        }
        view.fillMinimum = lo;
        view.fillMaximum = hi;
        view.colourTicks = gl::niceTicks(lo, hi, 6);
    }

    // Every member's contour, and the mean's; the colours and legend as colourSection gives.
    for (std::size_t m = 0; m < memberCount; ++m) {
        MemberContour contour;
        contour.member = m;
        contour.lines = toPlot(
            prep::contourLines(view.memberValues[m], view.columns, view.rows, request.isovalue),
            view);
        view.members.push_back(std::move(contour));
    }
    colourSection(view, request.memberColours, request.clusterNumbers);
    view.meanContour =
        toPlot(prep::contourLines(moments.mean, view.columns, view.rows, request.isovalue), view);
    view.isovalue = request.isovalue;
    if (request.boxplot && !request.boxplot->bandMembers.empty())
        addBoxplot(view, *request.boxplot);

    view.subtitle = "isovalue " + data::readableNumber(request.isovalue) +
                    (ensemble.units.empty() ? "" : " " + data::readableUnits(ensemble.units)) +
                    " · " + std::to_string(memberCount) + " members" +
                    (view.fill.empty() ? "" : " · fill: " + view.fillCaption);
    return view;
}

std::optional<std::pair<SectionFill, int>> parseSectionFill(const std::string& text,
                                                            std::string& problem) {
    const std::string t = data::asciiLower(text);
    if (t == "mean") return std::pair{SectionFill::Mean, -1};
    if (t == "spread") return std::pair{SectionFill::Spread, -1};
    if (t == "probability") return std::pair{SectionFill::Probability, -1};
    if (t == "none") return std::pair{SectionFill::None, -1};
    for (const auto& [prefix, fill] : {std::pair{std::string("member:"), SectionFill::Member},
                                       std::pair{std::string("anomaly:"), SectionFill::Anomaly}}) {
        if (!t.starts_with(prefix)) continue;
        const std::string digits = t.substr(prefix.size());
        if (digits.empty() || digits.size() > 9 ||
            !std::all_of(digits.begin(), digits.end(),
                         [](char c) { return c >= '0' && c <= '9'; })) {
            break;
        }
        const int number = std::stoi(digits);
        if (number >= 1) return std::pair{fill, number - 1};
    }
    problem = "'" + text +
              "' is not a fill: give mean, spread, probability, member:N, anomaly:N (members "
              "count from 1) or none";
    return std::nullopt;
}

SectionRequest sectionRequestFor(const PreprocessResult& clusters, const SectionPlace& place,
                                 SectionFill fill, int member) {
    SectionRequest r;
    r.place = place;
    r.fill = fill;
    r.member = member;
    r.isovalue = clusters.meshes.isovalue;
    r.clusterNumbers = clusters.clusterNumbers;
    for (const int number : clusters.clusterNumbers) {
        r.memberColours.push_back(gl::clusterColor(number - 1));
    }
    return r;
}

double latticeIndexAt(const std::vector<double>& positions, double t) {
    const bool ascending = positions.back() >= positions.front();
    const auto before = [ascending](double p, double v) { return ascending ? p < v : p > v; };
    const auto it = std::lower_bound(positions.begin(), positions.end(), t, before);
    if (it == positions.begin()) return 0.0;
    if (it == positions.end()) return static_cast<double>(positions.size() - 1);
    const auto i = static_cast<std::size_t>(it - positions.begin());
    const double a = positions[i - 1], b = positions[i];
    return static_cast<double>(i - 1) + (b == a ? 0.0 : (t - a) / (b - a));
}

float sectionValueAt(const SectionView& view, const std::vector<float>& values, glm::dvec2 unit) {
    if (view.columns < 2 || view.rows < 2) return kNaN;
    return sectionValueAtIndex(view, values, latticeIndexAt(view.columnPositions, unit.x),
                               latticeIndexAt(view.rowPositions, unit.y));
}

float sectionValueAtIndex(const SectionView& view, const std::vector<float>& values, double column,
                          double row) {
    if (view.columns < 2 || view.rows < 2 || values.size() != view.columns * view.rows) return kNaN;
    const auto c0 = std::min(static_cast<std::size_t>(std::max(column, 0.0)), view.columns - 2);
    const auto r0 = std::min(static_cast<std::size_t>(std::max(row, 0.0)), view.rows - 2);
    const double fc = std::clamp(column - static_cast<double>(c0), 0.0, 1.0);
    const double fr = std::clamp(row - static_cast<double>(r0), 0.0, 1.0);
    const std::size_t nearest =
        c0 + (fc >= 0.5 ? 1 : 0) + view.columns * (r0 + (fr >= 0.5 ? 1 : 0));
    if (std::isnan(values[nearest])) return kNaN;
    double sum = 0.0, weights = 0.0;
    for (int corner = 0; corner < 4; ++corner) {
        const double w = ((corner & 1) ? fc : 1 - fc) * ((corner >> 1) ? fr : 1 - fr);
        const float v = values[c0 + (corner & 1) + view.columns * (r0 + (corner >> 1))];
        if (std::isnan(v) || w <= 0.0) continue;
        sum += w * v;
        weights += w;
    }
    return weights > 0.0 ? static_cast<float>(sum / weights) : kNaN;
}

void colourSection(SectionView& view, const std::vector<glm::vec3>& memberColours,
                   const std::vector<int>& clusterNumbers) {
    std::map<int, SectionView::LegendEntry> legend;
    for (MemberContour& contour : view.members) {
        const std::size_t m = contour.member;
        contour.colour = m < memberColours.size() ? memberColours[m] : gl::kUnclusteredColor;
        if (m < clusterNumbers.size() && clusterNumbers[m] > 0) {
            SectionView::LegendEntry& entry = legend[clusterNumbers[m]];
            entry.cluster = clusterNumbers[m];
            entry.colour = contour.colour;
            ++entry.members;
        }
    }
    view.legend.clear();
    for (const auto& [number, entry] : legend) view.legend.push_back(entry);
}

DefaultSections defaultSections(const data::Ensemble& ensemble, float isovalue) {
    const data::Grid& grid = ensemble.grid;
    const std::size_t nx = grid.nx(), ny = grid.ny(), nz = grid.nz();
    // Points with members on both sides of the isovalue, per level and per row of each level.
    std::vector<std::size_t> perRow(ny * nz, 0);
    for (std::size_t k = 0; k < nz; ++k) {
        for (std::size_t j = 0; j < ny; ++j) {
            std::size_t count = 0;
            for (std::size_t i = 0; i < nx; ++i) {
                const std::size_t p = grid.index(i, j, k);
                bool above = false, below = false;
                for (const data::Member& m : ensemble.members) {
                    const float v = m.values[p];
                    above = above || v > isovalue;
                    below = below || v <= isovalue;  // NaN is neither
                    if (above && below) break;
                }
                count += above && below ? 1 : 0;
            }
            perRow[j + ny * k] = count;
        }
    }
    std::size_t level = nz / 2, best = 0;
    for (std::size_t k = 0; k < nz; ++k) {
        std::size_t count = 0;
        for (std::size_t j = 0; j < ny; ++j) count += perRow[j + ny * k];
        if (count > best) {
            best = count;
            level = k;
        }
    }
    std::size_t row = ny / 2;
    best = 0;
    for (std::size_t j = 0; j < ny; ++j) {
        if (perRow[j + ny * level] > best) {
            best = perRow[j + ny * level];
            row = j;
        }
    }
    DefaultSections d;
    d.map.kind = SectionKind::Map;
    if (grid.z().units.empty()) {
        d.map.level = static_cast<double>(level);
        d.map.levelUnits = "index";
    } else {
        d.map.level = grid.z().values[level];
        d.map.levelUnits = grid.z().units;
        // Pressure as people say it: 250 hPa rather than 25000 Pa.
        if (const double per = data::hectopascalsPer(grid.z().units); per > 0.0) {
            d.map.level = grid.z().values[level] * per;
            d.map.levelUnits = "hPa";
        }
    }
    const geo::MapProjection projection = geo::MapProjection::forGrid(grid, ensemble.gridMapping);
    const double y = grid.y().values[row];
    if (projection.kind() == geo::MapProjection::Kind::LonLat) {
        d.crossSection.kind = SectionKind::Latitude;
        d.crossSection.latitude = y;
        return d;
    }
    d.crossSection.kind = SectionKind::Path;
    std::vector<glm::dvec2> ends{{grid.x().front(), y}, {grid.x().back(), y}};
    if (projection.hasGeography()) {
        // A little inside the ends, so the great circle between them stays in the grid.
        const double inset = 0.02 * (grid.x().back() - grid.x().front());
        ends = {{grid.x().front() + inset, y}, {grid.x().back() - inset, y}};
        projection.toLonLat(ends);
    }
    d.crossSection.from = ends[0];
    d.crossSection.to = ends[1];
    return d;
}

}  // namespace ensil::engine
