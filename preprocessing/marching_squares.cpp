#include "preprocessing/marching_squares.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>

#include "data/error.h"

namespace ensil::prep {
namespace {

// A cell's sides: bottom (v), right (u + 1), top (v + 1), left (u).
enum Side : std::uint8_t { B, R, T, L, None };

// The segments of each case, corners' bits: 1 bottom-left, 2 bottom-right, 4 top-right,
// 8 top-left. Each segment joins two sides; the saddles (5, 10) are resolved below.
constexpr std::array<std::array<Side, 4>, 16> kSegments{{
    {None, None, None, None},  // 0
    {L, B, None, None},        // 1
    {B, R, None, None},        // 2
    {L, R, None, None},        // 3
    {R, T, None, None},        // 4
    {L, B, R, T},              // 5: centre outside (the inside corners apart)
    {B, T, None, None},        // 6
    {L, T, None, None},        // 7
    {L, T, None, None},        // 8
    {B, T, None, None},        // 9
    {B, R, L, T},              // 10: centre outside
    {R, T, None, None},        // 11
    {L, R, None, None},        // 12
    {B, R, None, None},        // 13
    {L, B, None, None},        // 14
    {None, None, None, None},  // 15
}};

}  // namespace

std::vector<ContourLine> contourLines(std::span<const float> values, std::size_t columns,
                                      std::size_t rows, float level) {
    if (columns == 0 || rows == 0 || values.size() != columns * rows) {
        throw data::Error(data::ErrorKind::InvalidArgument,
                          "contour lines: " + std::to_string(values.size()) +
                              " values for a section of " + std::to_string(columns) + " x " +
                              std::to_string(rows));
    }
    if (columns < 2 || rows < 2) return {};
    const auto at = [&](std::size_t u, std::size_t v) { return values[u + columns * v]; };
    // An edge by its lower-left end and direction: 2 (u + columns v) along u, + 1 along v.
    const auto edgeOf = [columns](std::size_t u, std::size_t v, Side side) -> std::uint64_t {
        switch (side) {
            case B:
                return 2 * (u + columns * v);
            case T:
                return 2 * (u + columns * (v + 1));
            case L:
                return 2 * (u + columns * v) + 1;
            default:
                return 2 * (u + 1 + columns * v) + 1;
        }
    };
    std::unordered_map<std::uint64_t, glm::dvec2> crossing;  // where each edge is cut
    const auto crossingAt = [&](std::uint64_t edge) {
        if (const auto found = crossing.find(edge); found != crossing.end()) return;
        const std::size_t cell = edge / 2;
        const std::size_t u = cell % columns, v = cell / columns;
        const bool alongU = edge % 2 == 0;
        const double a = at(u, v);
        const double b = alongU ? at(u + 1, v) : at(u, v + 1);
        const double t = (static_cast<double>(level) - a) / (b - a);
        crossing.emplace(edge, alongU ? glm::dvec2(static_cast<double>(u) + t, v)
                                      : glm::dvec2(u, static_cast<double>(v) + t));
    };
    struct Segment {
        std::uint64_t a, b;
    };
    std::vector<Segment> segments;
    for (std::size_t v = 0; v + 1 < rows; ++v) {
        for (std::size_t u = 0; u + 1 < columns; ++u) {
            const std::array<float, 4> c{at(u, v), at(u + 1, v), at(u + 1, v + 1), at(u, v + 1)};
            if (std::isnan(c[0]) || std::isnan(c[1]) || std::isnan(c[2]) || std::isnan(c[3])) {
                continue;
            }
            unsigned index = 0;
            for (unsigned i = 0; i < 4; ++i) index |= c[i] > level ? 1U << i : 0U;
            std::array<Side, 4> sides = kSegments[index];
            // A saddle whose centre is inside joins its inside corners: the other pairing.
            const double centre = (static_cast<double>(c[0]) + c[1] + c[2] + c[3]) / 4.0;
            if (index == 5 && centre > level) sides = {B, R, L, T};
            if (index == 10 && centre > level) sides = {L, B, R, T};
            for (std::size_t s = 0; s < 4 && sides[s] != None; s += 2) {
                const Segment segment{edgeOf(u, v, sides[s]), edgeOf(u, v, sides[s + 1])};
                crossingAt(segment.a);
                crossingAt(segment.b);
                segments.push_back(segment);
            }
        }
    }
    // Joined into lines: an edge is shared by at most two cells, so by at most two segments.
    std::unordered_map<std::uint64_t, std::array<int, 2>> byEdge;
    for (std::size_t s = 0; s < segments.size(); ++s) {
        for (const std::uint64_t e : {segments[s].a, segments[s].b}) {
            auto [it, added] = byEdge.try_emplace(e, std::array<int, 2>{-1, -1});
            it->second[it->second[0] < 0 ? 0 : 1] = static_cast<int>(s);
        }
    }
    std::vector<bool> used(segments.size(), false);
    // From `edge`, leaving segment `from`, along unused segments; the edges passed, in order.
    const auto walk = [&](std::uint64_t edge, int from, std::vector<std::uint64_t>& edges) {
        for (;;) {
            const std::array<int, 2>& pair = byEdge.at(edge);
            const int next = pair[0] == from ? pair[1] : pair[0];
            if (next < 0 || used[static_cast<std::size_t>(next)]) return;
            used[static_cast<std::size_t>(next)] = true;
            const Segment& s = segments[static_cast<std::size_t>(next)];
            edge = s.a == edge ? s.b : s.a;
            edges.push_back(edge);
            from = next;
        }
    };
    std::vector<ContourLine> lines;
    for (std::size_t s = 0; s < segments.size(); ++s) {
        if (used[s]) continue;
        used[s] = true;
        std::vector<std::uint64_t> forward{segments[s].a, segments[s].b};
        walk(segments[s].b, static_cast<int>(s), forward);
        ContourLine line;
        if (forward.size() > 2 && forward.back() == forward.front()) {
            line.closed = true;
            forward.pop_back();
        } else {
            std::vector<std::uint64_t> backward;
            walk(segments[s].a, static_cast<int>(s), backward);
            forward.insert(forward.begin(), backward.rbegin(), backward.rend());
        }
        line.points.reserve(forward.size());
        for (const std::uint64_t e : forward) line.points.push_back(crossing.at(e));
        lines.push_back(std::move(line));
    }
    return lines;
}

}  // namespace ensil::prep
