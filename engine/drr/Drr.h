#pragma once
// Digitally reconstructed radiographs: line integrals of attenuation along the rays from the
// source to each detector pixel centre, traced exactly through the voxels (Siddon / Jacobs).
//
// Two steps so that nothing is done twice:
//   DrrVolume prepared = prepareDrrVolume(volume, valueOptions);   // once per volume+values
//   Image drr = renderDrr(prepared, geometry, renderOptions);       // per view
// Preparation converts values (HU -> mu, threshold), crops to the non-zero attenuation and
// builds the empty-space skipping structure; rendering is const and thread-safe.
#include <memory>
#include <optional>

#include "core/Image.h"
#include "geometry/ProjectionGeometry.h"
#include "volume/Volume.h"

namespace fm {

enum class DrrValues {
    Raw,  // integrate the stored values as they are (result in value*mm)
    Mu,   // convert HU to linear attenuation (1/mm), documented formula; result dimensionless
};

struct DrrValueOptions {
    DrrValues values = DrrValues::Mu;
    // Ignore voxels whose stored value is below this level (HU for CTs): "bone only" images.
    std::optional<double> thresholdHU;
};

enum class DrrOutput {
    LineIntegral,  // sum of value * length along each ray
    Intensity,     // exp(-line integral): radiograph look (only meaningful for Mu)
};

enum class DrrTrace {
    Exact,   // Siddon/Jacobs exact voxel traversal with empty-space skipping
    Approx,  // trilinear sampling at stepMm (for previews; error measured in bench/)
};

struct DrrRenderOptions {
    DrrOutput output = DrrOutput::LineIntegral;
    DrrTrace trace = DrrTrace::Exact;
    double approxStepMm = 1.0;   // sample spacing along the ray for Approx
    int threads = 0;             // 0 = all cores; result identical for a given thread count
};

// Opaque prepared volume (values converted, cropped, empty-space map built).
struct DrrVolume;
using DrrVolumePtr = std::shared_ptr<const DrrVolume>;

DrrVolumePtr prepareDrrVolume(const Volume& volume, const DrrValueOptions& options);

// Renders one DRR; the image has the detector's size and spacing, row 0 first.
Image renderDrr(const DrrVolume& volume, const ProjectionGeometry& geometry,
                const DrrRenderOptions& options);

}  // namespace fm
