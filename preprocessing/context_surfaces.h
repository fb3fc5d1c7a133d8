// The surfaces that summarise an ensemble at one isovalue, drawn as context around the members
// (METHODS.md section 17): the surface where half the members exceed the isovalue (P(f > c) =
// 0.5, the isosurface of the members' median), the two surfaces that bound the
// contour boxplot's 50 % band, and the boxplot itself (depths, median member, outliers).
// Pure function; any thread.
#pragma once

#include <stop_token>

#include "data/display_frame.h"
#include "data/ensemble.h"
#include "data/job.h"
#include "data/packed_mesh.h"
#include "preprocessing/inclusion_depth.h"
#include "preprocessing/isosurface_pipeline.h"

namespace ensil::prep {

struct ContextSurfaces {
    data::PackedMesh probability;  // P(f > c) = 0.5: the members' median at c
    data::PackedMesh bandInner;    // inside every member of the 50 % band
    data::PackedMesh bandOuter;    // inside any of them
    ContourBoxplot boxplot;
    // The column maximum of P(f > c) (nx * ny, NaN where the column has no value): where any
    // level is likely to exceed the isovalue, for the floor.
    std::vector<float> exceedanceColumnMaximum;
    // P(f > c) itself on the grid's points, for a section through it (NaN where no member has
    // a value).
    data::FieldValues exceedance;
};

// Which parts buildContextSurfaces makes: the boxplot and P(f > c) always (the member table,
// the floor and a section show them), the three meshes only when asked for (the workbench
// draws them only with the band or the P = 0.5 context surface on, and they are most of the
// work: on the demo 120 ms of one core of 180).
enum class ContextParts { FiguresOnly, FiguresAndSurfaces };

// Meshes the three surfaces at options.isovalue, as the members' are meshed (decimated alike,
// no outlyingness); with ContextParts::FiguresOnly they are left empty. Throws data::Cancelled
// and the errors of computeExceedance and computeContourBoxplot.
ContextSurfaces buildContextSurfaces(const data::Ensemble& ensemble,
                                     const data::DisplayFrame& frame,
                                     const PipelineOptions& options,
                                     const std::stop_token& stop = {},
                                     const data::Progress& progress = {},
                                     ContextParts parts = ContextParts::FiguresAndSurfaces);

// Copies the surfaces and the boxplot's median and outliers into the renderer's mesh set.
void addContextSurfaces(data::MeshSet& meshes, const ContextSurfaces& context);

}  // namespace ensil::prep
