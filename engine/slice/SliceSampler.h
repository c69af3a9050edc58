#pragma once
// Sampling a volume on a slice. Only the part of the plane that cuts the volume's box (the
// voxel boxes, index -0.5 .. dims - 0.5 along each axis) is sampled: each row's run of
// columns inside the box is found analytically and only those pixels are computed. Everything
// else is "no data": masked out (and 0 in the image), never an extrapolated value.
//
//   trilinear: for interactive display; the half-voxel border takes the edge voxels' values.
//   cubic B-spline: for registration (BSplinePrefilter.h; smoother cost).
//   thickness: a thick slice averages a box profile across the plane, thickness / finest
//     voxel spacing * 2 samples (at least 2) spread evenly over [-t/2, t/2] along the normal.
//     A pixel holds data when its centre on the plane lies in the box; the profile samples
//     outside the box are left out of its average.
#include <memory>
#include <vector>

#include "core/Image.h"
#include "similarity/Mask.h"
#include "slice/SliceGeometry.h"
#include "volume/Volume.h"

namespace fm {

enum class SliceInterpolation { Trilinear, CubicBSpline };
const char* toString(SliceInterpolation interpolation);  // "linear", "cubic"
// "linear" (or "trilinear"), "cubic" (or "bspline"); fm::Error otherwise.
SliceInterpolation parseSliceInterpolation(const std::string& text);

// A volume ready for slicing: its values and, once asked for, its B-spline coefficients.
struct SliceVolume {
    std::shared_ptr<const Volume> volume;
    std::vector<float> bsplineCoefficients;  // empty unless prepared with cubic
};
using SliceVolumePtr = std::shared_ptr<const SliceVolume>;

// Throws fm::Error if the volume is empty or invalid. `cubic` computes the coefficients.
SliceVolumePtr prepareSliceVolume(std::shared_ptr<const Volume> volume, bool cubic,
                                  int threads = 0);

struct SampledSlice {
    Image image;  // values; 0 where there is no data
    Mask mask;    // 1 where the plane (pixel centre) lies in the volume's box
    std::size_t dataPixels() const { return mask.count(); }
    bool empty() const { return dataPixels() == 0; }
};

// Samples `slice` from `volume`. Throws fm::Error for an invalid geometry or for cubic
// sampling of a volume prepared without coefficients. A plane that misses the box gives a
// fully masked slice (no error: the caller says so).
SampledSlice sampleSlice(const SliceVolume& volume, const SliceGeometry& slice,
                         SliceInterpolation interpolation, int threads = 0);

// The columns [first, last] of a row that lie in the box, for the line origin + c * step in
// continuous index coordinates; first > last when none. Exposed for tests.
struct ColumnRun {
    int first = 0, last = -1;
};
ColumnRun columnsInBox(const glm::dvec3& origin, const glm::dvec3& step, const glm::ivec3& dims,
                       int columns);

}  // namespace fm
