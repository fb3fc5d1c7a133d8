// ensil.render: a picture of an ensemble, a session or a project as an RGBA NumPy array, drawn
// by the headless renderer `ensil render` uses (engine::renderSession), with no display server
// needed (Mesa's EGL surfaceless platform), and _png() for notebooks.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <QBuffer>
#include <QFileInfo>
#include <QGuiApplication>
#include <QImage>
#include <QSurfaceFormat>
#include <QThread>
#include <cstring>

#include "engine/session_renderer.h"
#include "gl/offscreen_context.h"
#include "gl/surface_format.h"
#include "python/src/bindings.h"
#include "python/src/errors.h"
#include "python/src/gui_application.h"
#include "python/src/py_ensemble.h"
#include "python/src/py_session.h"
#include "python/src/settings.h"
#include "session/project_file.h"
#include "session/setting_options.h"
#include "session/view_presets.h"

namespace py = pybind11;

namespace ensil::python {
namespace {

py::array_t<std::uint8_t> rgbaArray(const QImage& picture) {
    const QImage rgba = picture.convertToFormat(QImage::Format_RGBA8888);
    const auto h = static_cast<py::ssize_t>(rgba.height());
    const auto w = static_cast<py::ssize_t>(rgba.width());
    py::array_t<std::uint8_t> out({h, w, py::ssize_t{4}});
    for (py::ssize_t y = 0; y < h; ++y) {
        std::memcpy(out.mutable_data(y, 0, 0), rgba.constScanLine(static_cast<int>(y)),
                    static_cast<std::size_t>(w) * 4);
    }
    return out;
}

py::tuple render(const py::object& target, const std::optional<double>& iso,
                 const std::pair<int, int>& size, const std::optional<std::string>& view,
                 bool cache, const py::kwargs& settings) {
    session::SessionState state;
    const PyEnsemble* ensemble = nullptr;
    if (py::isinstance<PyEnsemble>(target)) {
        ensemble = &target.cast<const PyEnsemble&>();
        if (ensemble->selection) {
            state.data = *ensemble->selection;
            // A session holds absolute paths (projects save them relative to themselves).
            for (std::string& path : state.data.paths) {
                path = QFileInfo(QString::fromStdString(path)).absoluteFilePath().toStdString();
            }
        }
        if (ensemble->demo) {
            state.demo = true;
            state.demoParams = *ensemble->demo;
        }
    } else if (py::isinstance<PySession>(target)) {
        state = *target.cast<const PySession&>().state;
    } else if (py::isinstance<py::str>(target) || py::hasattr(target, "__fspath__")) {
        const std::string path =
            py::module_::import("os").attr("fspath")(target).cast<std::string>();
        if (!QString::fromStdString(path).endsWith(QLatin1String(".ensil"))) {
            throw ArgumentError("'" + path +
                                "' is not a project (.ensil): open data files with ensil.open() "
                                "and render the ensemble");
        }
        state = session::loadProject(QString::fromStdString(path));
    } else {
        throw ArgumentError("ensil.render draws an Ensemble, a Session or a project file (.ensil)");
    }
    // As `ensil render` takes its options: the view first, then the settings override it.
    if (view) {
        const session::ViewPreset* preset = session::findViewPreset(*view);
        if (preset == nullptr) {
            throw ArgumentError("--view '" + *view + "' is refused: it must be one of " +
                                session::viewPresetNames());
        }
        session::lookFrom(*preset, state.camera);
    }
    for (const auto& [id, value] : settings) {
        if (value.is_none()) continue;  // mode=None and the like: as the session has it
        const session::Setting& s = settingNamed(id.cast<std::string>());
        s.set(state, settingFromPython(s, value));
    }
    if (iso) state.isovalue = static_cast<float>(boundedNumber("--iso", *iso, -1e30, 1e30));
    QString problem;
    const auto checked =
        session::parseImageSize(QStringLiteral("--size"),
                                QStringLiteral("%1x%2").arg(size.first).arg(size.second), problem);
    if (!checked) throw ArgumentError(problem.toStdString());
    engine::RenderRequest request;
    // An ensemble drawn without clusters= gets the workbench's default for its members; a
    // session or project keeps its own.
    if (ensemble != nullptr) {
        request.clustersGiven =
            settings.contains("clusters") && !py::object(settings["clusters"]).is_none();
    }
    request.width = checked->first;
    request.height = checked->second;
    request.frames = 1;
    request.useCache = cache;
    ensureGuiApplication("ensil.render");
    engine::RenderOutcome outcome;
    {
        const py::gil_scoped_release released;
        outcome = ensemble != nullptr ? engine::renderEnsemble(
                                            ensemble->data, ensemble->sourceKey(), state, request)
                                      : engine::renderSession(state, request);
    }
    // Called through ensil.render (python/ensil/__init__.py): the user's line is one further up.
    if (!outcome.note.empty()) warn("note: " + outcome.note, 2);
    PySession drawn;
    *drawn.state = outcome.drawn;
    py::dict facts;
    facts["isovalue"] = outcome.drawn.isovalue.value_or(0.0F);
    facts["members"] = outcome.members;
    facts["variable"] = outcome.variable;
    facts["triangles"] = outcome.triangles;
    facts["gl_renderer"] = outcome.glRenderer;
    facts["display"] = outcome.withoutDisplay ? std::string("none (EGL surfaceless)")
                                              : QGuiApplication::platformName().toStdString();
    return py::make_tuple(rgbaArray(outcome.image), drawn, facts);
}

py::bytes png(const py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>& rgba) {
    if (rgba.ndim() != 3 || rgba.shape(2) != 4) {
        throw ArgumentError("a picture is (height, width, 4) RGBA");
    }
    const QImage image(rgba.data(), static_cast<int>(rgba.shape(1)),
                       static_cast<int>(rgba.shape(0)), static_cast<int>(rgba.strides(0)),
                       QImage::Format_RGBA8888);
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    image.save(&buffer, "PNG");
    return {bytes.constData(), static_cast<std::size_t>(bytes.size())};
}

}  // namespace

void bindRender(py::module_& module) {
    module.def("_render", &render, py::arg("target"), py::arg("iso"), py::arg("size"),
               py::arg("view"), py::arg("cache"));
    module.def("_png", &png, py::arg("rgba"), "The PNG file of an RGBA picture, as bytes.");
}

}  // namespace ensil::python
