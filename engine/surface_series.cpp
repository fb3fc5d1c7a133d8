#include "engine/surface_series.h"

#include <cstdio>
#include <fstream>

#include "data/error.h"

namespace ensil::engine {
namespace {

std::string xmlEscaped(const std::string& text) {
    std::string out;
    for (const char c : text) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

// ParaView's collection file, written by hand: VTK 9.1 has no writer for it (vtkXMLPVDWriter
// is ParaView's own), and it is a list of files with their times. The time is the step's
// index, the number ParaView's time controls step through; its label (the date) is kept in
// the entry's name.
void writePvd(const std::filesystem::path& file,
              const std::vector<std::pair<const TimeStepResult*, std::filesystem::path>>& steps) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
           "  <Collection>\n";
    for (const auto& [step, vtm] : steps) {
        out << "    <DataSet timestep=\"" << step->index << "\" group=\"\" part=\"0\" name=\""
            << xmlEscaped(step->time) << "\" file=\""
            << xmlEscaped(vtm.lexically_relative(file.parent_path()).generic_string()) << "\"/>\n";
    }
    out << "  </Collection>\n</VTKFile>\n";
    out.close();
    if (!out) {
        throw data::Error(data::ErrorKind::WriteFailed, "could not write '" + file.string() + "'");
    }
}

bool hasSurfaces(const data::MeshSet& meshes) {
    for (const data::PackedMesh& m : meshes.members) {
        if (!m.indices.empty()) return true;
    }
    return !meshes.mean.indices.empty();
}

}  // namespace

ExportedSurfaces exportTimeSeriesSurfaces(const std::vector<TimeStepResult>& steps,
                                          SurfaceFormat format,
                                          const std::filesystem::path& directory, bool displayFrame,
                                          const std::string& stem, const std::stop_token& stop) {
    if (steps.empty()) {
        throw data::Error(data::ErrorKind::InvalidArgument, "no time steps to export");
    }
    const PreprocessResult& first = steps.front().result;
    char isovalue[32];
    std::snprintf(isovalue, sizeof isovalue, "%g", static_cast<double>(first.meshes.isovalue));
    const std::string base =
        !stem.empty() ? stem : first.ensemble->variable + "_iso" + std::string(isovalue);
    ExportedSurfaces all;
    std::vector<std::pair<const TimeStepResult*, std::filesystem::path>> indexed;
    for (const TimeStepResult& step : steps) {
        // A step where no member reaches the isovalue has nothing to write; ParaView shows
        // nothing there, as the workbench does.
        if (!hasSurfaces(step.result.meshes)) continue;
        SurfaceSet set = surfaceSetOf(step.result);
        if (displayFrame) set.displayFrame = data::DisplayFrame(step.result.ensemble->grid, 1.0F);
        char suffix[32];
        std::snprintf(suffix, sizeof suffix, "_t%03zu", step.index);
        set.stem = base + suffix;
        ExportedSurfaces written = exportSurfaces(set, format, directory, stop);
        if (format == SurfaceFormat::Vtp) indexed.emplace_back(&step, written.files.front());
        all.surfaces += written.surfaces;
        all.triangles += written.triangles;
        all.trianglesLeftOut += written.trianglesLeftOut;
        all.files.insert(all.files.end(), written.files.begin(), written.files.end());
    }
    if (all.surfaces == 0) {
        throw data::Error(data::ErrorKind::InvalidArgument,
                          "no surface to export: no member reaches the isovalue " +
                              std::string(isovalue) + " at any of the steps");
    }
    if (format == SurfaceFormat::Vtp) {
        const std::filesystem::path pvd = directory / (base + ".pvd");
        writePvd(pvd, indexed);
        all.files.insert(all.files.begin(), pvd);
    }
    return all;
}

}  // namespace ensil::engine
