#include "vtk_reference.h"

#include <vtkCurvatures.h>
#include <vtkFloatArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkQuadricDecimation.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <chrono>
#include <vector>

namespace {

// The member as a VTK image, read in place (save = 1: VTK must not free it).
vtkNew<vtkImageData> imageOf(const ensil::data::Ensemble& e, std::size_t m) {
    vtkNew<vtkImageData> image;
    image->SetDimensions(static_cast<int>(e.grid.nx()), static_cast<int>(e.grid.ny()),
                         static_cast<int>(e.grid.nz()));
    vtkNew<vtkFloatArray> values;
    values->SetArray(const_cast<float*>(e.members[m].values.data()),
                     static_cast<vtkIdType>(e.members[m].values.size()), 1);
    image->GetPointData()->SetScalars(values);
    return image;
}

// vtkFlyingEdges3D's surface of one member, without the normals and gradients it could add
// (the reference computes its attributes later, timed on their own).
vtkSmartPointer<vtkPolyData> flyingEdges(vtkImageData* image, float isovalue) {
    vtkNew<vtkFlyingEdges3D> edges;
    edges->SetInputData(image);
    edges->SetValue(0, isovalue);
    edges->ComputeNormalsOff();
    edges->ComputeGradientsOff();
    edges->Update();
    return edges->GetOutput();
}

}  // namespace

VtkIsosurfaceTime timeVtkFlyingEdges(const ensil::data::Ensemble& e, float isovalue,
                                     std::size_t members) {
    VtkIsosurfaceTime out;
    std::vector<vtkNew<vtkImageData>> images;
    for (std::size_t m = 0; m < std::min(members, e.memberCount()); ++m) {
        images.push_back(imageOf(e, m));
    }
    const auto start = std::chrono::steady_clock::now();
    for (auto& image : images) {
        out.triangles += static_cast<std::size_t>(flyingEdges(image, isovalue)->GetNumberOfPolys());
    }
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

VtkReferenceTimes runVtkReference(const ensil::data::Ensemble& e, float isovalue,
                                  std::size_t members, std::size_t target) {
    using Clock = std::chrono::steady_clock;
    const auto seconds = [](Clock::time_point t) {
        return std::chrono::duration<double>(Clock::now() - t).count();
    };
    // vtkCurvatures warns for every vertex where its estimate is poor; those lines would bury
    // the figures.
    vtkObject::GlobalWarningDisplayOff();
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_ERROR);
    VtkReferenceTimes times;
    for (std::size_t m = 0; m < std::min(members, e.memberCount()); ++m) {
        vtkNew<vtkImageData> image = imageOf(e, m);

        auto t = Clock::now();
        const vtkSmartPointer<vtkPolyData> surface = flyingEdges(image, isovalue);
        times.isosurface += seconds(t);
        const auto in = static_cast<std::size_t>(surface->GetNumberOfPolys());
        times.trianglesIn += in;
        if (in == 0) continue;

        t = Clock::now();
        vtkNew<vtkQuadricDecimation> decimate;
        decimate->SetInputData(surface);
        decimate->SetTargetReduction(1.0 - static_cast<double>(std::min(target, in)) /
                                               static_cast<double>(in));
        decimate->Update();
        times.decimation += seconds(t);
        times.trianglesOut += static_cast<std::size_t>(decimate->GetOutput()->GetNumberOfPolys());

        t = Clock::now();
        vtkNew<vtkCurvatures> curvatures;
        curvatures->SetInputConnection(decimate->GetOutputPort());
        curvatures->SetCurvatureTypeToMaximum();
        curvatures->Update();
        vtkNew<vtkCurvatures> minimum;
        minimum->SetInputConnection(decimate->GetOutputPort());
        minimum->SetCurvatureTypeToMinimum();
        minimum->Update();
        times.curvature += seconds(t);
    }
    return times;
}
