// Ensemble.preprocess and its result: what `ensil preprocess --json` gives, as NumPy arrays,
// through the same code (engine::preprocessEnsemble), plus the meshes and the ensemble statistics.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <QString>

#include "data/error.h"
#include "engine/isovalue_job.h"
#include "engine/preprocess_run.h"
#include "engine/surface_export.h"
#include "preprocessing/ensemble_statistics.h"
#include "preprocessing/mesh_packing.h"
#include "python/src/bindings.h"
#include "python/src/errors.h"
#include "python/src/interruptible.h"
#include "python/src/numpy_arrays.h"
#include "python/src/py_ensemble.h"
#include "python/src/py_preprocess.h"
#include "python/src/settings.h"

namespace py = pybind11;

namespace ensil::python {
namespace {

// One isosurface, decoded from the 20-byte GPU vertices (what the vertex shader computes).
// coordinates='data' or 'display', as `ensil preprocess --coordinates` takes it.
bool displayCoordinates(const std::string& coordinates) {
    if (coordinates != "data" && coordinates != "display") {
        throw data::Error(data::ErrorKind::InvalidArgument,
                          "coordinates '" + coordinates + "' is not data or display");
    }
    return coordinates == "display";
}

struct PyMesh {
    std::shared_ptr<const engine::PreprocessResult> owner;
    const data::PackedMesh* mesh;
};

}  // namespace

void runPreprocessing(const std::function<void(const std::stop_token&, const data::Progress&,
                                               const engine::PreprocessNotice&)>& step,
                      const py::object& progress) {
    std::vector<std::string> notices;
    std::mutex noticesMutex;
    runInterruptible(
        [&](const std::stop_token& stop, const data::Progress& report) {
            step(stop, report, [&](const std::string& kind, const std::string& text) {
                const std::lock_guard lock(noticesMutex);
                notices.push_back(kind + ": " + text);
            });
        },
        progress);
    for (const std::string& n : notices) warn(n);
}

engine::PreprocessRequest preprocessRequestOf(const PyEnsemble& self,
                                              const std::optional<double>& iso,
                                              const py::object& clusters, const py::object& linkage,
                                              double error, bool decimate, bool cache,
                                              const std::optional<std::string>& cacheDir) {
    engine::PreprocessRequest request;
    if (iso) request.isovalue = boundedNumber("--iso", *iso, -1e30, 1e30);
    request.clustersGiven = !clusters.is_none();
    request.clusters =
        clusters.is_none()
            ? session::SessionState{}.clusters
            : static_cast<int>(settingFromPython(session::setting("clusters"), clusters));
    request.linkage =
        static_cast<prep::Linkage>(settingFromPython(session::setting("linkage"), linkage));
    request.errorCells = boundedNumber("--error", error, 0.001, 10.0);  // the command line's range
    request.decimate = decimate;
    if (cache) {
        if (cacheDir && cacheDir->empty()) {
            throw ArgumentError("cache_dir '' is refused: name a folder, or use cache=False");
        }
        request.cacheDirectory = cacheDir ? *cacheDir : engine::defaultMeshCacheDirectory();
    }
    request.sourceKey = self.sourceKey();
    if (request.sourceKey.empty()) request.cacheDirectory.reset();  // arrays are not cached
    return request;
}

namespace {

PyPreprocessResult preprocess(const PyEnsemble& self, const std::optional<double>& iso,
                              const py::object& clusters, const py::object& linkage, double error,
                              bool decimate, bool cache, const std::optional<std::string>& cacheDir,
                              const py::object& progress) {
    const engine::PreprocessRequest request =
        preprocessRequestOf(self, iso, clusters, linkage, error, decimate, cache, cacheDir);
    auto result = std::make_shared<engine::PreprocessResult>();
    runPreprocessing(
        [&](const std::stop_token& stop, const data::Progress& report,
            const engine::PreprocessNotice& notice) {
            *result = engine::preprocessEnsemble(self.data, request, notice, stop, report);
        },
        progress);
    return {std::move(result), request.linkage};
}

py::array_t<double> linkageMatrix(const prep::MergeTree& tree) {
    const auto rows = static_cast<py::ssize_t>(tree.merges.size());
    py::array_t<double> z({rows, py::ssize_t{4}});
    auto out = z.mutable_unchecked<2>();
    for (py::ssize_t i = 0; i < rows; ++i) {
        const prep::Merge& merge = tree.merges[static_cast<std::size_t>(i)];
        out(i, 0) = merge.a;
        out(i, 1) = merge.b;
        out(i, 2) = merge.height;
        out(i, 3) = merge.size;
    }
    return z;
}

py::dict statisticsOf(const std::shared_ptr<const data::Ensemble>& ensemble, double iso,
                      const std::optional<std::vector<long long>>& members,
                      const py::object& progress) {
    std::vector<std::size_t> chosen;
    if (members) {
        for (const long long m : *members) {
            if (m < 0) {
                throw ArgumentError("members: " + std::to_string(m) +
                                    " is not a member index (they start at 0)");
            }
            chosen.push_back(static_cast<std::size_t>(m));
        }
    }
    auto stats = std::make_shared<prep::EnsembleStatistics>();
    runInterruptible(
        [&](const std::stop_token& stop, const data::Progress& report) {
            *stats = members ? prep::computeEnsembleStatistics(*ensemble, static_cast<float>(iso),
                                                               chosen, stop, report)
                             : prep::computeEnsembleStatistics(*ensemble, static_cast<float>(iso),
                                                               stop, report);
        },
        progress);
    const data::Grid& g = ensemble->grid;
    const py::capsule owner(new std::shared_ptr<prep::EnsembleStatistics>(stats), [](void* p) {
        delete static_cast<std::shared_ptr<prep::EnsembleStatistics>*>(p);
    });
    const auto f = static_cast<py::ssize_t>(sizeof(float));
    const auto field = [&](const data::FieldValues& v, std::size_t nx, std::size_t ny,
                           std::size_t nz) {
        const auto x = static_cast<py::ssize_t>(nx), y = static_cast<py::ssize_t>(ny);
        return readOnlyView(v.data(), {static_cast<py::ssize_t>(nz), y, x}, {x * y * f, x * f, f},
                            owner);
    };
    const auto point = [&](const data::FieldValues& v) { return field(v, g.nx(), g.ny(), g.nz()); };
    py::dict d;
    d["isovalue"] = stats->isovalue;
    d["members"] = copyOf<long long>(stats->members.empty() ? chosen : stats->members);
    d["count"] = point(stats->count);
    d["mean"] = point(stats->mean);
    d["stddev"] = point(stats->stddev);
    d["minimum"] = point(stats->minimum);
    d["maximum"] = point(stats->maximum);
    d["range"] = point(stats->range);
    d["exceedance_probability"] = point(stats->exceedance);
    d["level_crossing_probability"] =
        field(stats->levelCrossing, g.nx() - 1, g.ny() - 1, g.nz() - 1);
    return d;
}

constexpr const char* kStatsDoc = R"doc(
The ensemble's statistics per grid point at isovalue `iso` over all members or over
`members` (0-based indices), as `ensil stats` writes them: a dict of read-only float32 arrays
shaped (z, y, x): count, mean, stddev (sample), minimum, maximum, range,
exceedance_probability P(f > iso); and level_crossing_probability on the cells,
(z-1, y-1, x-1). NaN where no member has a value (stddev: fewer than two).)doc";

void bindMesh(py::module_& m) {
    py::class_<PyMesh>(m, "Mesh", R"doc(
One member's isosurface as preprocessing made it (decimated unless asked not to). Vertices in
grid index space (x, y, z), as the renderer takes them; `coordinates` maps them onto the axes,
and `save` writes the surface for ParaView, MeshLab or Blender.)doc")
        .def_property_readonly(
            "coordinates",
            [](const PyMesh& self) {
                const data::Grid& g = self.owner->ensemble->grid;
                const auto n = static_cast<py::ssize_t>(self.mesh->vertices.size());
                py::array_t<double> out({n, py::ssize_t{3}});
                auto o = out.mutable_unchecked<2>();
                for (py::ssize_t i = 0; i < n; ++i) {
                    const glm::vec3 p = prep::unpackPosition(
                        *self.mesh, self.mesh->vertices[static_cast<std::size_t>(i)]);
                    o(i, 0) = g.x().valueAt(p.x);
                    o(i, 1) = g.y().valueAt(p.y);
                    o(i, 2) = g.z().valueAt(p.z);
                }
                return out;
            },
            "(n, 3) float64: each vertex in the data's coordinates, the axes' values (x, y, z: "
            "longitude, latitude and level, or a projection's metres), linear between grid "
            "points; what `save` writes.")
        .def(
            "save",
            [](const PyMesh& self, const std::filesystem::path& path,
               const std::string& coordinates) {
                engine::SurfaceSet set = engine::surfaceSetOf(*self.owner);
                if (displayCoordinates(coordinates)) {
                    set.displayFrame = data::DisplayFrame(self.owner->ensemble->grid, 1.0F);
                }
                return engine::writeSurface(set, *self.mesh, path);
            },
            py::arg("path"), py::arg("coordinates") = "data",
            R"doc(Writes this surface to `path` in the format its suffix names: .vtp (ParaView,
through VTK's writer), .ply (MeshLab, CloudCompare, Blender; binary, with each vertex's member,
cluster, depth, outlyingness and curvatures), .obj or .stl (through OpenMesh). Vertices in the
data's coordinates (`coordinates`), or with coordinates='display' in the workbench's box, its
sides in proportion (for MeshLab or Blender). Returns the triangles the .ply/.obj/.stl writer had to
leave out to keep the surface manifold (0 almost always). Raises ensil.Error for another
suffix or a file that cannot be written.)doc")
        .def_property_readonly(
            "vertices",
            [](const PyMesh& self) {
                const auto n = static_cast<py::ssize_t>(self.mesh->vertices.size());
                py::array_t<float> out({n, py::ssize_t{3}});
                auto o = out.mutable_unchecked<2>();
                for (py::ssize_t i = 0; i < n; ++i) {
                    const glm::vec3 p = prep::unpackPosition(
                        *self.mesh, self.mesh->vertices[static_cast<std::size_t>(i)]);
                    o(i, 0) = p.x;
                    o(i, 1) = p.y;
                    o(i, 2) = p.z;
                }
                return out;
            },
            "(n, 3) float32: each vertex in grid index space (x, y, z), fractional.")
        .def_property_readonly(
            "triangles",
            [](const py::object& self) {
                const auto& mesh = self.cast<const PyMesh&>();
                const auto n = static_cast<py::ssize_t>(mesh.mesh->indices.size() / 3);
                const auto u = static_cast<py::ssize_t>(sizeof(std::uint32_t));
                return readOnlyView(mesh.mesh->indices.data(), {n, py::ssize_t{3}}, {3 * u, u},
                                    self);
            },
            "(m, 3) uint32: each triangle's three vertex indices (a read-only view).")
        .def_property_readonly(
            "attributes",
            [](const PyMesh& self) {
                const auto n = static_cast<py::ssize_t>(self.mesh->vertices.size());
                py::array_t<float> normal({n, py::ssize_t{3}}), direction({n, py::ssize_t{3}});
                py::array_t<float> k1(n), k2(n), outlying(n);
                auto no = normal.mutable_unchecked<2>(), di = direction.mutable_unchecked<2>();
                auto a = k1.mutable_unchecked<1>(), b = k2.mutable_unchecked<1>(),
                     o = outlying.mutable_unchecked<1>();
                for (py::ssize_t i = 0; i < n; ++i) {
                    const data::PackedVertex& v = self.mesh->vertices[static_cast<std::size_t>(i)];
                    const glm::vec3 nn = prep::unpackUnitVector(v.normal);
                    const glm::vec3 dd = prep::unpackUnitVector(v.direction);
                    for (int c = 0; c < 3; ++c) {
                        no(i, c) = nn[c];
                        di(i, c) = dd[c];
                    }
                    a(i) = prep::unpackHalf(v.kappa1);
                    b(i) = prep::unpackHalf(v.kappa2);
                    o(i) = prep::unpackHalf(v.outlyingness) * self.mesh->outlyingnessScale;
                }
                py::dict d;
                d["normal"] = normal;
                d["kappa1"] = k1;
                d["kappa2"] = k2;
                d["curvature_direction"] = direction;
                d["outlyingness"] = outlying;
                return d;
            },
            R"doc(The per-vertex attributes the silhouettes are drawn from, as float32 arrays:
normal (n, 3) and curvature_direction (n, 3) (unit vectors in display space), kappa1 and kappa2
(principal curvatures), outlyingness (n,) (METHODS.md).)doc")
        .def("__len__", [](const PyMesh& self) { return self.mesh->vertices.size(); })
        .def("__repr__", [](const PyMesh& self) {
            return "<ensil.Mesh: " + std::to_string(self.mesh->vertices.size()) + " vertices, " +
                   std::to_string(self.mesh->indices.size() / 3) + " triangles>";
        });
}

}  // namespace

void bindPreprocess(py::module_& module) {
    bindMesh(module);
    py::class_<PyPreprocessResult>(module, "PreprocessResult", R"doc(
One isovalue's preprocessing, as `ensil preprocess --json` reports it, in NumPy: meshes,
distances, the merge tree in SciPy's linkage convention, clusters and colours, and the contour
boxplot. Members without data are left out (their names in members_without_data); every
per-member figure is in the order of `members`.)doc")
        .def_property_readonly(
            "isovalue", [](const PyPreprocessResult& r) { return r.result->meshes.isovalue; },
            "The isovalue (the default one when none was given).")
        .def_property_readonly(
            "members",
            [](const PyPreprocessResult& r) {
                std::vector<std::string> names;
                const data::Ensemble& e = *r.result->ensemble;
                for (std::size_t i = 0; i < e.memberCount(); ++i) {
                    names.push_back(e.members[i].name.empty() ? "member " + std::to_string(i + 1)
                                                              : e.members[i].name);
                }
                return names;
            },
            "The members the results are of, in order.")
        .def_property_readonly(
            "members_without_data",
            [](const PyPreprocessResult& r) { return r.result->membersWithoutData; },
            "The members left out because every value of theirs is missing.")
        .def_property_readonly(
            "distance_matrix",
            [](const py::object& self) {
                const auto& d = self.cast<const PyPreprocessResult&>().result->distances;
                const auto n = static_cast<py::ssize_t>(d.size);
                const auto f = static_cast<py::ssize_t>(sizeof(double));
                return readOnlyView(d.values.data(), {n, n}, {n * f, f}, self);
            },
            "(n, n) float64: the members' distances (METHODS.md), symmetric, zero diagonal.")
        .def_property_readonly(
            "linkage", [](const PyPreprocessResult& r) { return linkageMatrix(r.result->tree); },
            R"doc((n-1, 4) float64 in SciPy's linkage convention: row i merges clusters Z[i, 0] <
Z[i, 1] (ids below n are members, n + i the cluster row i makes) at height Z[i, 2] into a
cluster of Z[i, 3] members. scipy.cluster.hierarchy.dendrogram(result.linkage) draws it.)doc")
        .def_property_readonly(
            "linkage_method",
            [](const PyPreprocessResult& r) { return prep::linkageName(r.linkage); },
            "The linkage the clustering used: average, single, complete or ward.")
        .def_property_readonly(
            "k", [](const PyPreprocessResult& r) { return r.result->k; },
            "The number of clusters (a default lowered to the members there are).")
        .def_property_readonly(
            "clusters",
            [](const PyPreprocessResult& r) { return copyOf<int>(r.result->clusterNumbers); },
            "(n,) int: each member's cluster by the number the workbench's legend, cluster "
            "list and member table show, and `ensil preprocess --json` writes (1..k here: "
            "METHODS.md, numbers of members and clusters).")
        .def_property_readonly(
            "colors", [](const PyPreprocessResult& r) { return r.result->colors; },
            "Each member's colour as the workbench draws it, '#rrggbb'.")
        .def_property_readonly(
            "meshes",
            [](const PyPreprocessResult& r) {
                std::vector<PyMesh> meshes;
                for (const data::PackedMesh& mesh : r.result->meshes.members) {
                    meshes.push_back({r.result, &mesh});
                }
                return meshes;
            },
            "Each member's isosurface (ensil.Mesh), in member order.")
        .def(
            "export",
            [](const PyPreprocessResult& r, const std::filesystem::path& directory,
               const std::string& format, const std::optional<std::vector<int>>& members,
               bool context, const std::optional<std::string>& stem,
               const std::string& coordinates) {
                const auto chosen = engine::surfaceFormatNamed(format);
                if (!chosen) {
                    throw data::Error(
                        data::ErrorKind::InvalidArgument,
                        "format '" + format + "' is not one of " + engine::surfaceFormatNames());
                }
                engine::SurfaceSet set = engine::surfaceSetOf(*r.result);
                if (members) set.members = *members;
                set.context = context;
                if (stem) set.stem = *stem;
                if (displayCoordinates(coordinates)) {
                    set.displayFrame = data::DisplayFrame(r.result->ensemble->grid, 1.0F);
                }
                std::vector<std::string> files;
                for (const auto& f : engine::exportSurfaces(set, *chosen, directory).files) {
                    files.push_back(f.string());
                }
                return files;
            },
            py::arg("directory"), py::arg("format") = "vtp", py::arg("members") = py::none(),
            py::arg("context") = true, py::arg("stem") = py::none(),
            py::arg("coordinates") = "data",
            R"doc(Writes the surfaces into `directory` for other tools, as `ensil preprocess
--export` does: every member's (or those at the 0-based positions `members`), and with
`context` the mean's and the summary surfaces. format: 'vtp' (ParaView: a .vtm gathering a .vtp
per surface), 'ply', 'obj' or 'stl' (a file per surface). Files are named from `stem`, else
VARIABLE_isoX. coordinates: 'data' (the axes' values) or 'display' (the workbench's box). Returns the paths written, the .vtm first.)doc")
        .def_property_readonly(
            "mean_mesh",
            [](const PyPreprocessResult& r) {
                return PyMesh{r.result, &r.result->meshes.mean};
            },
            "The mean member's isosurface.")
        .def_property_readonly(
            "depth",
            [](const PyPreprocessResult& r) { return copyOf<double>(r.result->boxplot.depth); },
            "(n,) float64: each member's epsilon-inclusion depth (the contour boxplot).")
        .def_property_readonly(
            "median_member", [](const PyPreprocessResult& r) { return r.result->boxplot.median; },
            "The position of the deepest member in the arrays (0-based, as NumPy indexes; its "
            "number, as the member table and the JSON name it, is one more).")
        .def_property_readonly(
            "outliers",
            [](const PyPreprocessResult& r) {
                return copyOf<long long>(r.result->boxplot.outliers);
            },
            "(k,) int: the positions (0-based) of the members whose depth is below Q1 - 1.5 "
            "IQR, in order.")
        .def_property_readonly(
            "distances_to_mean",
            [](const PyPreprocessResult& r) { return copyOf<double>(r.result->distancesToMean); },
            "(n,) float64: each member's distance to the mean member (NaN: no isosurface).")
        .def_property_readonly(
            "mean_outlyingness",
            [](const PyPreprocessResult& r) { return copyOf<double>(r.result->meanOutlyingness); },
            "(n,) float64: the mean outlyingness over each member's isosurface.")
        .def_property_readonly(
            "from_cache", [](const PyPreprocessResult& r) { return r.result->fromCache; },
            "Whether the meshes came from the mesh cache.")
        .def_property_readonly(
            "seconds", [](const PyPreprocessResult& r) { return r.result->seconds; },
            "Each stage's wall-clock seconds.")
        .def(
            "stats",
            [](const PyPreprocessResult& r, const std::optional<std::vector<long long>>& members,
               const py::object& progress) {
                return statisticsOf(r.result->ensemble, r.result->meshes.isovalue, members,
                                    progress);
            },
            py::arg("members") = py::none(), py::arg("progress") = py::none(),
            (std::string(kStatsDoc) + "\nHere `iso` is the result's isovalue.").c_str())
        .def("__repr__", [](const PyPreprocessResult& r) {
            return "<ensil.PreprocessResult: " + std::to_string(r.result->ensemble->memberCount()) +
                   " members at " + QString::number(r.result->meshes.isovalue).toStdString() +
                   ", " + std::to_string(r.result->k) + " clusters, " +
                   std::to_string(r.result->meshes.triangles) + " triangles>";
        });

    // Methods of ensil.Ensemble (ensemble_bindings.cpp) that preprocess.
    auto ensemble = py::reinterpret_borrow<py::class_<PyEnsemble>>(module.attr("Ensemble"));
    ensemble
        .def("preprocess", &preprocess, py::arg("iso") = py::none(),
             py::arg("clusters") = py::none(), py::arg("linkage") = "average",
             py::arg("error") = 0.25, py::arg("decimate") = true, py::arg("cache") = true,
             py::arg("cache_dir") = py::none(), py::arg("progress") = py::none(),
             R"doc(
Meshes every member's isosurface at `iso` and the mean's, decimates them (error bound `error`
in grid cells, 0.001 to 10; decimate=False keeps every triangle), computes the per-vertex
attributes, the distances, the clustering (`linkage`: average, single, complete or ward;
`clusters`: default 5, lowered to the members there are; more is refused) and the contour boxplot:
what `ensil preprocess` does, through the same code. `iso` defaults to the workbench's (the
90th percentile of the values). Meshes of files and the demo go through the mesh cache
(the command line's and the workbench's; cache=False or cache_dir=FOLDER to change that).
`progress`, if given, is called with the fraction done; raising from it, or Ctrl+C, stops the
work. The GIL is released meanwhile.)doc")
        .def(
            "stats",
            [](const PyEnsemble& self, double iso,
               const std::optional<std::vector<long long>>& members, const py::object& progress) {
                if (!std::isfinite(iso)) throw ArgumentError("iso must be a finite number");
                return statisticsOf(self.data, iso, members, progress);
            },
            py::arg("iso"), py::arg("members") = py::none(), py::arg("progress") = py::none(),
            kStatsDoc);
}

}  // namespace ensil::python
