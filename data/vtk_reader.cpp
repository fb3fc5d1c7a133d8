#include "data/vtk_reader.h"

#include <vtkAlgorithm.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkDataArraySelection.h>
#include <vtkDataObject.h>
#include <vtkDataSet.h>
#include <vtkExecutive.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkRectilinearGridReader.h>
#include <vtkSmartPointer.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkStructuredPointsReader.h>
#include <vtkXMLImageDataReader.h>

#include <algorithm>
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "data/error.h"
#include "data/reader_support.h"
#include "data/vtk_legacy_header.h"

namespace ensil::data {
namespace {

enum class Format { Legacy, XmlImage };

// Collects the messages VTK raises on one reader, its executive and its XML parser. VTK prints
// a message only when the object raising it has no observer for it, so watching is silencing.
class MessageLog final : public vtkCommand {
public:
    static MessageLog* New() { return new MessageLog; }

    void Execute(vtkObject* /*caller*/, unsigned long /*event*/, void* callData) override {
        // "ERROR: In file.cxx, line 42\nvtkClass (0x1234): message\n...": keep the message.
        std::string text = callData ? static_cast<const char*>(callData) : "";
        const auto body = text.find("): ", text.find('\n'));
        if (body != std::string::npos) text = text.substr(body + 3);
        m_messages.push_back(text.substr(0, text.find('\n')));
    }

    void watch(vtkAlgorithm& algorithm) {
        for (vtkObject* object : {static_cast<vtkObject*>(&algorithm),
                                  static_cast<vtkObject*>(algorithm.GetExecutive())}) {
            object->AddObserver(vtkCommand::ErrorEvent, this);
            object->AddObserver(vtkCommand::WarningEvent, this);
        }
    }
    void watch(vtkXMLReader& reader) {
        watch(static_cast<vtkAlgorithm&>(reader));
        reader.SetReaderErrorObserver(this);
        reader.SetParserErrorObserver(this);
    }

    [[nodiscard]] bool empty() const { return m_messages.empty(); }
    [[nodiscard]] std::string first() const { return empty() ? "" : m_messages.front(); }

private:
    MessageLog() = default;
    std::vector<std::string> m_messages;
};

struct ArrayInfo {
    std::string name;
    std::size_t components = 1;
    bool numeric = true;
};

// What one file's headers say.
struct FileHeader {
    std::string path;
    Format format = Format::Legacy;
    std::string legacyDataset;
    std::array<std::size_t, 3> dims{};
    Grid grid;
    std::vector<ArrayInfo> arrays;
};

Format formatOf(const std::string& path) {
    const std::string head = readFileStart(path, 512);
    if (startsWith(head, "# vtk DataFile")) return Format::Legacy;
    if ((startsWith(head, "<?xml") || startsWith(head, "<VTKFile")) &&
        head.find("ImageData") != std::string::npos) {
        return Format::XmlImage;
    }
    throw Error(ErrorKind::UnsupportedFormat,
                "'" + path +
                    "' is not a VTK file ensil reads: it needs a legacy VTK header "
                    "('# vtk DataFile') or a VTK XML ImageData (.vti) header");
}

Grid makeGrid(const std::string& path, std::array<Axis, 3> axes) {
    try {
        return Grid(std::move(axes[0]), std::move(axes[1]), std::move(axes[2]));
    } catch (const Error& e) {
        throw Error(e.kind(), "'" + path + "': " + e.what());
    }
}

FileHeader legacyHeader(const std::string& path) {
    const vtk::LegacyStructure s = vtk::scanLegacyFile(path);
    if (s.dataset != "STRUCTURED_POINTS" && s.dataset != "RECTILINEAR_GRID") {
        throw Error(ErrorKind::UnsupportedFormat,
                    "legacy VTK file '" + path + "' holds a " + s.dataset +
                        " dataset: ensil reads STRUCTURED_POINTS and RECTILINEAR_GRID");
    }
    FileHeader h{path, Format::Legacy, s.dataset, s.dimensions, {}, {}};
    const bool rectilinear = s.dataset == "RECTILINEAR_GRID";
    for (std::size_t a = 0; a < 3; ++a) {
        if (rectilinear && s.coordinates[a].size() != h.dims[a]) {
            throw Error(ErrorKind::CorruptFile, "legacy VTK file '" + path + "' has " +
                                                    std::to_string(s.coordinates[a].size()) + " " +
                                                    "xyz"[a] + " coordinates for " +
                                                    std::to_string(h.dims[a]) + " points");
        }
    }
    requireThreeDimensional("'" + path + "'", h.dims[0], h.dims[1], h.dims[2]);
    std::array<Axis, 3> axes;
    for (std::size_t a = 0; a < 3; ++a) {
        const std::string name(1, "xyz"[a]);
        if (rectilinear) {
            axes[a].name = name;
            axes[a].values = s.coordinates[a];
        } else {
            axes[a] = uniformAxis(name, s.origin[a], s.spacing[a], h.dims[a]);
        }
    }
    h.grid = makeGrid(path, std::move(axes));
    for (const vtk::LegacyArray& array : s.pointArrays) {
        h.arrays.push_back({array.name, array.components, true});
    }
    return h;
}

std::vector<ArrayInfo> xmlArrays(vtkInformation& info) {
    std::vector<ArrayInfo> arrays;
    vtkInformationVector* vector = info.Get(vtkDataObject::POINT_DATA_VECTOR());
    for (int i = 0; vector && i < vector->GetNumberOfInformationObjects(); ++i) {
        vtkInformation* field = vector->GetInformationObject(i);
        if (!field || !field->Has(vtkDataObject::FIELD_NAME())) continue;
        const int type = field->Get(vtkDataObject::FIELD_ARRAY_TYPE());
        arrays.push_back(
            {field->Get(vtkDataObject::FIELD_NAME()),
             static_cast<std::size_t>(field->Get(vtkDataObject::FIELD_NUMBER_OF_COMPONENTS())),
             type != VTK_STRING && type != VTK_VARIANT});
    }
    return arrays;
}

FileHeader xmlHeader(const std::string& path) {
    vtkNew<vtkXMLImageDataReader> reader;
    vtkNew<MessageLog> log;
    log->watch(*reader);
    reader->SetFileName(path.c_str());
    reader->UpdateInformation();
    vtkInformation* info = reader->GetOutputInformation(0);
    if (!log->empty() || !info || !info->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT())) {
        throw Error(ErrorKind::CorruptFile,
                    "cannot read the header of VTK XML image '" + path +
                        "': the file may be truncated or damaged (VTK: " + log->first() + ")");
    }
    std::array<int, 6> extent{};
    info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent.data());
    std::array<double, 3> origin{0, 0, 0};
    std::array<double, 3> spacing{1, 1, 1};
    if (info->Has(vtkDataObject::ORIGIN())) info->Get(vtkDataObject::ORIGIN(), origin.data());
    if (info->Has(vtkDataObject::SPACING())) info->Get(vtkDataObject::SPACING(), spacing.data());
    FileHeader h{path, Format::XmlImage, {}, {}, {}, xmlArrays(*info)};
    for (std::size_t a = 0; a < 3; ++a) {
        h.dims[a] = static_cast<std::size_t>(std::max(0, extent[2 * a + 1] - extent[2 * a] + 1));
    }
    requireThreeDimensional("'" + path + "'", h.dims[0], h.dims[1], h.dims[2]);
    std::array<Axis, 3> axes;
    for (std::size_t a = 0; a < 3; ++a) {
        axes[a] =
            uniformAxis(std::string(1, "xyz"[a]), origin[a], spacing[a], h.dims[a], extent[2 * a]);
    }
    h.grid = makeGrid(path, std::move(axes));
    return h;
}

std::string arrayList(const FileHeader& h) {
    std::string text;
    for (const ArrayInfo& a : h.arrays) {
        text += (text.empty() ? "'" : ", '") + a.name + "'";
        if (a.components != 1) text += " (" + std::to_string(a.components) + " components)";
    }
    return text.empty() ? "no point-data arrays" : text;
}

std::vector<std::string> scalarArrays(const FileHeader& h) {
    std::vector<std::string> names;
    for (const ArrayInfo& a : h.arrays) {
        if (a.components == 1 && a.numeric) names.push_back(a.name);
    }
    return names;
}

std::string whyNotUsable(const ArrayInfo& a) {
    if (!a.numeric) return "array '" + a.name + "' does not hold numbers";
    if (a.components != 1) {
        return "array '" + a.name + "' has " + std::to_string(a.components) +
               " components: ensil needs a scalar (1-component) array";
    }
    return {};
}

// Throws unless `name` is a scalar point-data array of the file.
void requireArray(const FileHeader& h, const std::string& name) {
    for (const ArrayInfo& a : h.arrays) {
        if (a.name != name) continue;
        const std::string problem = whyNotUsable(a);
        if (problem.empty()) return;
        const auto others = scalarArrays(h);
        throw Error(ErrorKind::InvalidArgument,
                    "in '" + h.path + "', point-data " + problem + "; " +
                        (others.empty() ? "the file has no scalar array"
                                        : "choose one of " + quotedList(others)));
    }
    throw Error(ErrorKind::VariableNotFound, "no point-data array '" + name + "' in '" + h.path +
                                                 "'; arrays available: " + arrayList(h));
}

std::string chooseArray(const FileHeader& h, const std::string& requested) {
    if (!requested.empty()) {
        requireArray(h, requested);
        return requested;
    }
    const auto scalars = scalarArrays(h);
    if (scalars.empty()) {
        throw Error(ErrorKind::VariableNotFound, "'" + h.path +
                                                     "' has no scalar (1-component) point-data "
                                                     "array; it holds " +
                                                     arrayList(h));
    }
    return scalars.front();
}

void requireSameGrid(const FileHeader& first, const FileHeader& other) {
    const auto shape = [](const FileHeader& h) {
        return shapeText(h.dims[0], h.dims[1], h.dims[2]);
    };
    if (first.dims != other.dims) {
        throw Error(ErrorKind::GridMismatch,
                    "'" + first.path + "' is " + shape(first) + " but '" + other.path + "' is " +
                        shape(other) + " (x by y by z): every member file needs the same grid");
    }
    if (!first.grid.sameShapeAndCoordinates(other.grid)) {
        throw Error(ErrorKind::GridMismatch,
                    "'" + first.path + "' and '" + other.path + "' are both " + shape(first) +
                        " but their origin, spacing or coordinates differ: every member file "
                        "needs the same grid");
    }
}

struct Plan {
    std::vector<FileHeader> headers;
    std::string array;
};

Plan makePlan(const DataSelection& selection, const std::stop_token& stop) {
    requireFiles(selection.paths);
    Plan plan;
    for (const std::string& path : selection.paths) {
        throwIfStopped(stop);
        plan.headers.push_back(formatOf(path) == Format::Legacy ? legacyHeader(path)
                                                                : xmlHeader(path));
    }
    plan.array = chooseArray(plan.headers.front(), selection.variable);
    for (std::size_t i = 1; i < plan.headers.size(); ++i) {
        requireSameGrid(plan.headers.front(), plan.headers[i]);
        requireArray(plan.headers[i], plan.array);
    }
    return plan;
}

template <typename T>
void copyToFloat(const T* source, FieldValues& values) {
    for (std::size_t i = 0; i < values.size(); ++i) values[i] = static_cast<float>(source[i]);
}

FieldValues toFloats(vtkDataArray& array) {
    FieldValues values(static_cast<std::size_t>(array.GetNumberOfTuples()));
    switch (array.GetDataType()) {
        vtkTemplateMacro(copyToFloat(static_cast<const VTK_TT*>(array.GetVoidPointer(0)), values));
        default:  // bit arrays
            for (std::size_t i = 0; i < values.size(); ++i) {
                values[i] = static_cast<float>(array.GetComponent(static_cast<vtkIdType>(i), 0));
            }
    }
    return values;
}

// The legacy readers read every array of a kind or only the first; ask for all of them.
template <typename LegacyReader>
vtkSmartPointer<vtkAlgorithm> legacyReader(const std::string& path, MessageLog& log) {
    auto reader = vtkSmartPointer<LegacyReader>::New();
    log.watch(*reader);
    reader->SetFileName(path.c_str());
    reader->ReadAllScalarsOn();
    reader->ReadAllFieldsOn();
    reader->ReadAllColorScalarsOn();
    reader->ReadAllTCoordsOn();
    return reader;
}

vtkSmartPointer<vtkAlgorithm> xmlReader(const std::string& path, const std::string& array,
                                        MessageLog& log) {
    auto reader = vtkSmartPointer<vtkXMLImageDataReader>::New();
    log.watch(*reader);
    reader->SetFileName(path.c_str());
    reader->UpdateInformation();  // fills the array selections, so they can be narrowed
    reader->GetPointDataArraySelection()->DisableAllArrays();
    reader->GetPointDataArraySelection()->EnableArray(array.c_str());
    reader->GetCellDataArraySelection()->DisableAllArrays();
    return reader;
}

FieldValues readValues(const FileHeader& h, const std::string& arrayName) {
    vtkNew<MessageLog> log;
    vtkSmartPointer<vtkAlgorithm> reader;
    if (h.format == Format::XmlImage) {
        reader = xmlReader(h.path, arrayName, *log);
    } else if (h.legacyDataset == "RECTILINEAR_GRID") {
        reader = legacyReader<vtkRectilinearGridReader>(h.path, *log);
    } else {
        reader = legacyReader<vtkStructuredPointsReader>(h.path, *log);
    }
    reader->Update();
    auto* data = vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0));
    vtkDataArray* array = data ? data->GetPointData()->GetArray(arrayName.c_str()) : nullptr;
    if (!log->empty() || !array) {
        throw Error(ErrorKind::CorruptFile,
                    "cannot read array '" + arrayName + "' from '" + h.path +
                        "': the file may be truncated or damaged (VTK: " +
                        (log->empty() ? "no values returned" : log->first()) + ")");
    }
    FieldValues values = toFloats(*array);
    if (values.size() != h.grid.pointCount() || array->GetNumberOfComponents() != 1) {
        throw Error(ErrorKind::CorruptFile, "VTK read " + std::to_string(values.size()) +
                                                " values of '" + arrayName + "' from '" + h.path +
                                                "' for a grid of " +
                                                std::to_string(h.grid.pointCount()) + " points");
    }
    return values;
}

}  // namespace

bool VtkReader::recognizes(const std::string& path) const {
    const std::string head = readFileStart(path, 512);
    return startsWith(head, "# vtk DataFile") ||
           ((startsWith(head, "<?xml") || startsWith(head, "<VTKFile")) &&
            head.find("ImageData") != std::string::npos);
}

EnsembleDescription VtkReader::describe(const DataSelection& selection) const {
    const Plan plan = makePlan(selection, {});
    const FileHeader& first = plan.headers.front();
    EnsembleDescription d;
    d.format = first.format == Format::Legacy ? "VTK legacy" : "VTK XML image";
    for (const ArrayInfo& a : first.arrays) {
        VariableInfo v;
        v.name = a.name;
        v.dimensions = {"z", "y", "x"};
        v.shape = {first.dims[2], first.dims[1], first.dims[0]};
        v.whyNotUsable = whyNotUsable(a);
        v.usable = v.whyNotUsable.empty();
        d.variables.push_back(std::move(v));
    }
    d.variable = plan.array;
    d.members = selection.paths.size();
    d.memberNames = memberNamesFromPaths(selection.paths);
    d.grid = first.grid;
    return d;
}

Ensemble VtkReader::read(const DataSelection& selection, const std::stop_token& stop,
                         const Progress& progress) const {
    const Plan plan = makePlan(selection, stop);
    Ensemble e;
    e.variable = plan.array;
    e.source = sourceOf(selection.paths);
    e.grid = plan.headers.front().grid;
    const std::vector<std::string> names = memberNamesFromPaths(selection.paths);
    report(progress, 0.0);
    for (std::size_t m = 0; m < plan.headers.size(); ++m) {
        throwIfStopped(stop);
        e.members.push_back({names[m], readValues(plan.headers[m], plan.array)});
        report(progress, static_cast<double>(m + 1) / static_cast<double>(plan.headers.size()));
    }
    return e;
}

}  // namespace ensil::data
