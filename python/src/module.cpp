// The `ensil._ensil` extension module: ensil's engine (readers, preprocessing, clustering,
// statistics, headless rendering, projects) for Python. The `ensil` package (python/ensil/)
// re-exports it with the few parts that are plain Python.
#include <pybind11/pybind11.h>

#include <QCoreApplication>

#include "python/src/bindings.h"
#include "python/src/errors.h"
#include "session/version.h"

PYBIND11_MODULE(_ensil, m) {
    // The names the command line and the workbench run under, so the mesh cache is theirs
    // (QStandardPaths::CacheLocation: ~/.cache/ensil/ensil/meshes).
    QCoreApplication::setOrganizationName(QStringLiteral("ensil"));
    QCoreApplication::setApplicationName(QStringLiteral("ensil"));
    m.doc() = "ensil's engine for Python; use the `ensil` package.";
    m.attr("__version__") = ENSIL_VERSION;
    ensil::python::bindErrors(m);
    ensil::python::bindEnsemble(m);
    ensil::python::bindPreprocess(m);
    ensil::python::bindSession(m);
    ensil::python::bindRender(m);
    ensil::python::bindSection(m);
    ensil::python::bindTimeSeries(m);
}
