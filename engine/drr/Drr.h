#pragma once
// Digitally reconstructed radiographs: line integrals of attenuation along the rays from the
// source to each detector pixel centre, traced exactly through the voxels (Siddon / Jacobs).
//
// Two steps so that nothing is done twice:
//   DrrVolume prepared = prepareDrrVolume(volume, valueOptions);   // once per volume+values
//   Image drr = renderDrr(prepared, geometry, renderOptions);       // per view
// Preparation converts values (HU -> mu, threshold), crops to the non-zero attenuation and
// builds the empty-space skipping structure; rendering is const and thread-safe.
// See docs/drr.md for the method, the units and the measured accuracy and speed.
#include <cstdint>
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
    // Compared with the stored value before any conversion (also in Raw mode).
    std::optional<double> thresholdHU;
    // Added: preparation switches. The defaults are what every caller wants; tests and the
    // benchmark turn them off to show that skipping changes nothing (or to trade accuracy).
    bool cropToContent = true;  // crop to the bounding box of the non-zero values
    int brickSize = 8;          // edge of the empty-space bricks in voxels (>= 1)
    int downsample = 1;         // >1: average f*f*f blocks first (approximate, for previews)
    int threads = 0;            // preparation threads (0 = all cores); the result is the same
    // Store the voxels as int16 when that holds them exactly (whole HU, raw integers); half the
    // memory and faster walks. false = always float (tests compare the two).
    bool compactVoxels = true;
};

// How a prepared volume stores its voxels (DrrVolumeInfo::voxelType).
enum class DrrVoxelType { Float32, Int16 };

enum class DrrOutput {
    LineIntegral,  // sum of value * length along each ray
    Intensity,     // exp(-line integral): radiograph look (only meaningful for Mu)
};

// How the exact trace walks the voxels; all give the same segments (docs/drr.md).
enum class DrrExactWalk {
    Auto,    // Dense where the volume has few empty/uniform bricks and the CPU has AVX-512 or AVX2
    Bricks,  // one ray at a time, skipping empty and uniform bricks
    Dense,   // every voxel, 16 rays at once in AVX-512 or AVX2 lanes (scalar where the CPU has neither)
};

struct DrrRenderOptions {
    DrrOutput output = DrrOutput::LineIntegral;
    // Always the exact trace. Trilinear sampling was removed: 2.6-22x slower than the exact
    // trace at a larger error (docs/benchmarks-drr.md); fast previews trace a downsampled
    // volume (DrrValueOptions::downsample, coarsenDrrVolume) or film (downsampled()) exactly.
    int threads = 0;            // 0 = all cores; the image is bit-identical for any count
    // Added: false = plain traversal of every voxel of the (cropped) box and every pixel
    // (no bricks, no projected-box pixel limit). Same result up to summation order; for tests.
    bool skipEmptySpace = true;
    DrrExactWalk walk = DrrExactWalk::Auto;  // with skipEmptySpace (without it: Dense)
};

// Linear attenuation coefficient of liquid water at an effective energy of 60 keV, in 1/mm:
// mass attenuation coefficient mu/rho = 0.2059 cm^2/g (J. H. Hubbell and S. M. Seltzer, "Tables
// of X-Ray Mass Attenuation Coefficients and Mass Energy-Absorption Coefficients", NIST Standard
// Reference Database 126, water, 60 keV) times rho = 1.000 g/cm^3, i.e. 0.2059/cm. 60 keV is
// the usual effective energy of a 100-120 kVp diagnostic beam.
inline constexpr double kMuWaterPerMm = 0.02059;

// HU -> mu (1/mm) by the definition of the Hounsfield scale, HU = 1000 (mu - mu_w) / mu_w:
//     mu = mu_water * (1 + HU / 1000), clamped at 0 (HU <= -1000 is air: no attenuation).
double huToMu(double hu);

// The value a stored voxel value contributes per mm under `options` (threshold, conversion);
// 0 for NaN ("no data"). Shared by the fast and the reference renderer.
double drrVoxelValue(double stored, const DrrValueOptions& options);

// Opaque prepared volume (values converted, cropped, empty-space map built).
struct DrrVolume;
using DrrVolumePtr = std::shared_ptr<const DrrVolume>;

// Throws fm::Error if the volume is unusable (geometry, size) or holds infinite values.
DrrVolumePtr prepareDrrVolume(const Volume& volume, const DrrValueOptions& options);

// A coarser copy of a prepared volume, for coarse search levels and previews: block means of
// factor^3 kept voxels (voxels beyond the kept box count as 0, so the mass along every ray
// direction is kept), in the same frame, with its own brick map. Approximate, like
// DrrValueOptions::downsample, but made from the prepared volume (no source volume needed).
// factor 1 returns a copy. Throws fm::Error for a factor outside 1..16.
DrrVolumePtr coarsenDrrVolume(const DrrVolume& volume, int factor, int threads = 0);

// Renders one DRR; the image has the detector's size and spacing, row 0 first.
// Throws fm::Error for an unusable geometry (non-finite numbers, empty or absurd detector).
Image renderDrr(const DrrVolume& volume, const ProjectionGeometry& geometry,
                const DrrRenderOptions& options);

// The line integrals of a volume's positive values and of its negative values (of -value, so
// both >= 0), from one walk that adds up |value| beside value (DenseWalk.h's WalkSums): a volume
// holding two materials, one of them negated (spectral/SpectralScene.h: a CT's soft tissue and
// bone), costs one render instead of two. positive - negative is renderDrr's image up to
// rounding. Output must be LineIntegral (fm::Error otherwise).
struct DrrSignParts {
    Image positive, negative;
};
DrrSignParts renderDrrBySign(const DrrVolume& volume, const ProjectionGeometry& geometry,
                             const DrrRenderOptions& options);

// Added: what preparation kept (for tests, the CLI and the benchmark).
struct DrrVolumeInfo {
    glm::ivec3 dims{0};       // voxels after downsampling and cropping
    glm::ivec3 cropBegin{0};  // first kept voxel, in the (downsampled) source grid
    glm::dvec3 spacing{1.0};  // mm
    int bricksTotal = 0;
    int bricksEmpty = 0;    // all values zero: skipped outright
    int bricksUniform = 0;  // all values equal and non-zero: one multiplication per ray
    bool empty = true;      // no non-zero value at all
    bool denseWalk = false;  // DrrExactWalk::Auto walks every voxel (16 rays at once)
    DrrVoxelType voxelType = DrrVoxelType::Float32;
    std::size_t voxelBytes = 0;  // the stored voxels (padded box), bytes
};
DrrVolumeInfo drrVolumeInfo(const DrrVolume& volume);

// Added: slow independent reference (tests and benchmark only). Original Siddon (1985): all
// plane crossings of each ray are computed and sorted in long double, each segment's voxel is
// found from its midpoint, directly on `volume` (no cropping, no bricks, no downsampling).
Image renderDrrReference(const Volume& volume, const DrrValueOptions& values,
                         const ProjectionGeometry& geometry, DrrOutput output, int threads = 0);
// The reference line integral of the one ray from `source` to `target` (world mm).
double drrReferenceLineIntegral(const Volume& volume, const DrrValueOptions& values,
                                const glm::dvec3& source, const glm::dvec3& target);

// Added: the fast exact line integral of one ray from `source` to `target` (world mm), in
// double (images are float): what renderDrr computes for each pixel.
double drrLineIntegral(const DrrVolume& volume, const glm::dvec3& source, const glm::dvec3& target,
                       bool skipEmptySpace = true);

// Added: the number of voxel segments the exact traversal of every pixel's ray visits in the
// kept box (Siddon steps, one per voxel entered), to state speed per step.
std::uint64_t drrTraversalSteps(const DrrVolume& volume, const ProjectionGeometry& geometry);

}  // namespace fm
