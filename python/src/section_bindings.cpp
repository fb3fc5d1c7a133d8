// PreprocessResult.section (Ensemble.section in python/ensil/__init__.py): a map or a
// cross-section of the result's ensemble at its isovalue (engine/ensemble_section.h), as
// `ensil section` and the workbench's Sections dock draw it: every member's values and
// contours as NumPy arrays, the fill, and save() for the figure (PNG, SVG, PDF).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <QString>
#include <algorithm>
#include <array>
#include <memory>
#include <sstream>
#include <tuple>

#include "data/error.h"
#include "engine/ensemble_section.h"
#include "engine/section_painter.h"
#include "engine/section_place.h"
#include "python/src/bindings.h"
#include "python/src/errors.h"
#include "python/src/gui_application.h"
#include "python/src/numpy_arrays.h"
#include "python/src/py_preprocess.h"
#include "python/src/settings.h"
#include "session/setting_table.h"

namespace py = pybind11;

namespace ensil::python {
namespace {

struct PySection {
    std::shared_ptr<const engine::SectionView> view;
    std::shared_ptr<const engine::PreprocessResult> clusters;
};

// A number or a text as the command line takes it.
std::string placeText(const py::handle& value) {
    if (py::isinstance<py::str>(value)) return value.cast<std::string>();
    std::ostringstream text;
    text.precision(17);
    text << value.cast<double>();
    return text.str();
}

// The path as the command line writes it, from ((lon, lat), (lon, lat)) or the text itself.
std::string pathText(const py::handle& path) {
    if (py::isinstance<py::str>(path)) return path.cast<std::string>();
    const auto ends = path.cast<std::vector<std::pair<double, double>>>();
    if (ends.size() != 2) throw ArgumentError("path must be two (lon, lat) points");
    std::ostringstream t;
    t.precision(17);
    t << ends[0].first << "," << ends[0].second << ":" << ends[1].first << "," << ends[1].second;
    return t.str();
}

engine::SectionPlace placeOf(const py::object& level, const py::object& lat, const py::object& lon,
                             const py::object& path) {
    const std::array<std::tuple<const py::object*, const char*, engine::SectionKind>, 4> places{{
        {&level, "level", engine::SectionKind::Map},
        {&lat, "lat", engine::SectionKind::Latitude},
        {&lon, "lon", engine::SectionKind::Longitude},
        {&path, "path", engine::SectionKind::Path},
    }};
    const auto given = std::count_if(places.begin(), places.end(),
                                     [](const auto& p) { return !std::get<0>(p)->is_none(); });
    if (given != 1) {
        throw ArgumentError(
            "say where the section lies with one of level= (a map), lat=, lon= or path= (a "
            "cross-section)");
    }
    const auto& [value, name, kind] = *std::find_if(
        places.begin(), places.end(), [](const auto& p) { return !std::get<0>(p)->is_none(); });
    std::string problem;
    const auto place = engine::parseSectionPlace(
        kind, kind == engine::SectionKind::Path ? pathText(*value) : placeText(*value), problem);
    if (!place) throw ArgumentError(std::string(name) + " is refused: " + problem);
    return *place;
}

// (n, 2) arrays of a section's lines, in the plot's unit square.
py::list linesOf(const std::vector<engine::SectionLine>& lines) {
    py::list out;
    for (const engine::SectionLine& line : lines) {
        py::array_t<double> points({static_cast<py::ssize_t>(line.points.size()), py::ssize_t{2}});
        auto p = points.mutable_unchecked<2>();
        for (std::size_t i = 0; i < line.points.size(); ++i) {
            p(static_cast<py::ssize_t>(i), 0) = line.points[i].x;
            p(static_cast<py::ssize_t>(i), 1) = line.points[i].y;
        }
        out.append(points);
    }
    return out;
}

// rows x columns, row 0 at the bottom.
py::array_t<float> latticeArray(const engine::SectionView& view, const std::vector<float>& values) {
    py::array_t<float> out(
        {static_cast<py::ssize_t>(view.rows), static_cast<py::ssize_t>(view.columns)});
    std::copy(values.begin(), values.end(), out.mutable_data());
    return out;
}

// colour_map= and range=, checked as the setting table checks them.
session::SectionsColours coloursOf(const std::string& colourMap,
                                   const std::optional<std::pair<double, double>>& range) {
    session::SectionsColours colours;
    colours.map = static_cast<session::SectionsColourMap>(settingFromPython(
        session::setting("sections_colour_map"), py::str(colourMap), "colour_map"));
    if (range) {
        for (const auto& [id, value] : {std::pair{"sections_range_min", range->first},
                                        std::pair{"sections_range_max", range->second}}) {
            const std::string why = session::setting(id).problemWith(value);
            if (!why.empty()) throw ArgumentError("range is refused: each end " + why);
        }
        if (!(range->first < range->second)) {
            throw ArgumentError("range is refused: its lower end must lie below its upper end");
        }
        colours.fixedRange = true;
        colours.minimum = range->first;
        colours.maximum = range->second;
    }
    return colours;
}

PySection section(const PyPreprocessResult& self, const py::object& level, const py::object& lat,
                  const py::object& lon, const py::object& path, const std::string& fill,
                  const std::string& colourMap,
                  const std::optional<std::pair<double, double>>& range, bool band,
                  const std::string& verticalAxis) {
    engine::SectionPlace place = placeOf(level, lat, lon, path);
    place.verticalAxis = static_cast<data::VerticalAxis>(settingFromPython(
        session::setting("vertical_axis"), py::str(verticalAxis), "vertical_axis"));
    std::string problem;
    const auto chosen = engine::parseSectionFill(fill, problem);
    if (!chosen) throw ArgumentError("fill is refused: " + problem);
    engine::SectionRequest request =
        engine::sectionRequestFor(*self.result, place, chosen->first, chosen->second);
    engine::applySectionColours(request, coloursOf(colourMap, range));
    if (band) {
        request.boxplot = engine::sectionBoxplotOf(*self.result);
        if (!request.boxplot) {
            throw ArgumentError(
                "band is refused: this result has no contour boxplot (an "
                "ensemble preprocessed in slabs makes none)");
        }
    }
    engine::SectionView view;
    {
        const py::gil_scoped_release release;
        view = engine::buildSection(*self.result->ensemble, request);
    }
    return {std::make_shared<const engine::SectionView>(std::move(view)), self.result};
}

}  // namespace

void bindSection(py::module_& module) {
    py::class_<PySection>(module, "Section", R"doc(
A map or a cross-section of an ensemble at an isovalue (Ensemble.section,
PreprocessResult.section): what `ensil section` draws. Arrays are rows x columns with row 0 at
the bottom (the lowest latitude, the highest pressure); places in the plot are in its unit
square, x right and y up, laid out as the 3D view lays out the data.)doc")
        .def_property_readonly("title", [](const PySection& s) { return s.view->title; })
        .def_property_readonly("place", [](const PySection& s) { return s.view->placeText; })
        .def_property_readonly("isovalue",
                               [](const PySection& s) { return s.clusters->meshes.isovalue; })
        .def_property_readonly(
            "values",
            [](const PySection& s) {
                const engine::SectionView& v = *s.view;
                py::array_t<float> out({static_cast<py::ssize_t>(v.memberValues.size()),
                                        static_cast<py::ssize_t>(v.rows),
                                        static_cast<py::ssize_t>(v.columns)});
                float* to = out.mutable_data();
                for (const std::vector<float>& member : v.memberValues) {
                    to = std::copy(member.begin(), member.end(), to);
                }
                return out;
            },
            "Each member's values on the section: members x rows x columns (NaN: missing).")
        .def_property_readonly(
            "fill",
            [](const PySection& s) -> py::object {
                if (s.view->fill.empty()) return py::none();
                return latticeArray(*s.view, s.view->fill);
            },
            "The filled field, rows x columns; None for fill='none'.")
        .def_property_readonly("fill_caption",
                               [](const PySection& s) { return s.view->fillCaption; })
        .def_property_readonly(
            "band",
            [](const PySection& s) -> py::object {
                const engine::SectionView& v = *s.view;
                if (v.bandHighest.empty()) return py::none();
                py::array_t<bool> out(
                    {static_cast<py::ssize_t>(v.rows), static_cast<py::ssize_t>(v.columns)});
                bool* to = out.mutable_data();
                for (std::size_t i = 0; i < v.bandHighest.size(); ++i) to[i] = v.inBand(i);
                return out;
            },
            "With band=True, rows x columns: True in the contour boxplot's 50 % band (some of "
            "its members above the isovalue, not all); else None.")
        .def_property_readonly(
            "median_member",
            [](const PySection& s) -> py::object {
                if (s.view->medianMember < 0) return py::none();
                return py::int_(s.view->medianMember);
            },
            "With band=True, the median member's index (from 0), whose contour is drawn thick.")
        .def_property_readonly(
            "colour_map",
            [](const PySection& s) {
                return session::setting("sections_colour_map")
                    .format(static_cast<double>(s.view->colourMap));
            },
            "The fill's colour map: viridis, greys, rdbu or ylgnbu.")
        .def_property_readonly("fill_range",
                               [](const PySection& s) {
                                   return std::pair{s.view->fillMinimum, s.view->fillMaximum};
                               })
        .def_property_readonly(
            "contours",
            [](const PySection& s) {
                py::list out;
                for (const engine::MemberContour& c : s.view->members) out.append(linesOf(c.lines));
                return out;
            },
            "Per member, its contour lines at the isovalue: (n, 2) arrays of plot places.")
        .def_property_readonly(
            "mean_contour", [](const PySection& s) { return linesOf(s.view->meanContour); },
            "The contour lines of the members' mean.")
        .def_property_readonly(
            "column_positions",
            [](const PySection& s) { return copyOf<double>(s.view->columnPositions); },
            "Where each column lies across the plot, 0 to 1.")
        .def_property_readonly(
            "row_positions",
            [](const PySection& s) { return copyOf<double>(s.view->rowPositions); },
            "Where each row lies up the plot, 0 to 1.")
        .def_property_readonly(
            "clusters", [](const PySection& s) { return copyOf<int>(s.clusters->clusterNumbers); },
            "Each member's cluster number, as the legend shows it.")
        .def_property_readonly("colors", [](const PySection& s) { return s.clusters->colors; })
        .def(
            "save",
            [](const PySection& s, const std::string& path,
               const std::optional<std::pair<int, int>>& size) {
                ensureGuiApplication("ensil.Section.save");
                const QSize pixels = size ? QSize(size->first, size->second)
                                          : engine::sectionPictureSize(*s.view, 1400);
                if (pixels.width() < 1 || pixels.height() < 1 || pixels.width() > 16384 ||
                    pixels.height() > 16384) {
                    throw ArgumentError("size must be two whole numbers from 1 to 16384");
                }
                engine::writeSectionPicture(*s.view, QString::fromStdString(path), pixels);
            },
            py::arg("path"), py::arg("size") = py::none(),
            "Writes the figure: PNG, SVG (text as text, contours as paths) or PDF by the suffix; "
            "size (width, height) in pixels, by default 1400 wide and as high as it needs.")
        .def("__repr__", [](const PySection& s) {
            return "<ensil.Section: " + s.view->title + ", " + std::to_string(s.view->columns) +
                   " x " + std::to_string(s.view->rows) + ", " +
                   std::to_string(s.view->members.size()) + " members>";
        });

    auto result =
        py::reinterpret_borrow<py::class_<PyPreprocessResult>>(module.attr("PreprocessResult"));
    result.def("section", &section, py::arg("level") = py::none(), py::arg("lat") = py::none(),
               py::arg("lon") = py::none(), py::arg("path") = py::none(), py::arg("fill") = "mean",
               py::arg("colour_map") = "automatic", py::arg("range") = py::none(),
               py::arg("band") = false, py::arg("vertical_axis") = "log-pressure",
               R"doc(
A map or a cross-section at this result's isovalue, members in their clusters' colours:
level= a map ("500hPa", "5km", "index:3", or a number in the vertical axis's units); lat= or
lon= a cross-section along a latitude or longitude (45, "45N", "10W"); path= one along the
great circle between two points, ((lon, lat), (lon, lat)) or "LON,LAT:LON,LAT". fill= mean,
spread, probability, member:N, anomaly:N (N from 1) or none. colour_map= automatic (by the
fill), viridis, greys, rdbu or ylgnbu; range=(lower, upper) fixes the colour bar (by default the
section's own values); band=True draws the contour boxplot: its 50 % band shaded, the median's
contour thick, the outliers' dashed. vertical_axis= log-pressure, pressure or height: how a
pressure axis goes up a cross-section, as the 3D view's setting "vertical_axis". Raises
ensil.ArgumentError for a malformed place, colour map, range or vertical axis and ensil.Error
for a place outside the data.)doc");
}

}  // namespace ensil::python
