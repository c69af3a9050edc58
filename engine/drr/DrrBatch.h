#pragma once
// Many DRRs of one volume in one run (`fluoromatch drr --poses FILE` or an angle sweep), as an
// indexed list of jobs: job i has its geometry and its output name, both functions of i alone,
// so that the volume is loaded and prepared once and the jobs can be rendered in any order or
// spread over processes (MPI ranks) with the same files as the result.
//
// A views file has one view per line: six numbers "x y z az el rot" (a pose of the 2011 scene;
// commas or spaces between them) or the path of a projection geometry JSON file (relative to
// the views file's folder). '#' starts a comment; blank lines are skipped.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "geometry/Pose.h"
#include "geometry/ProjectionGeometry.h"

namespace fm {

struct DrrView {
    std::optional<Pose> pose;            // a pose of the six-parameter scene, or ...
    std::filesystem::path geometryFile;  // ... a geometry file
    std::string origin;                  // "views.txt:3", "sweep 4 of 36"
};

// Throws fm::Error naming the file and line for a malformed line (not six numbers nor one
// path, a pose out of range), an unreadable file or one without views; more than kMaxDrrViews
// views are refused.
inline constexpr std::size_t kMaxDrrViews = 100000;
std::vector<DrrView> parseDrrViews(const std::string& text, const std::string& what,
                                   const std::filesystem::path& baseFolder);
std::vector<DrrView> readDrrViews(const std::filesystem::path& path);

// `count` views stepping the azimuth by `stepDeg` from `start` (plastimatch drr's -a and -N):
// view i has azimuth start + i * step, wrapped to [-180, 180). Throws fm::Error for count
// outside 1..kMaxDrrViews or a step that is not finite.
std::vector<DrrView> azimuthSweep(const Pose& start, int count, double stepDeg);

struct DrrJob {
    std::size_t index = 0;
    ProjectionGeometry geometry;
    std::filesystem::path output;     // numberedOutput(base output, index, count); may be empty
    std::filesystem::path rawOutput;  // the same for the exact-values file
    std::string origin;
};

// "drr.png", 7 of 36 -> "drr_007.png"; "x.nii.gz" keeps its double extension ("x_007.nii.gz").
// Digits: at least 3, more when count needs them. An empty base stays empty.
std::filesystem::path numberedOutput(const std::filesystem::path& base, std::size_t index,
                                     std::size_t count);

// The jobs of `views`: poses through sceneGeometry(pose, setup, volumeCenter), geometry files
// read as they are; every geometry downsampled by `downsample` and validated (fm::Error naming
// the view's origin).
std::vector<DrrJob> makeDrrJobs(const std::vector<DrrView>& views, const SceneSetup& setup,
                                const glm::dvec3& volumeCenter, int downsample,
                                const std::filesystem::path& output,
                                const std::filesystem::path& rawOutput);

}  // namespace fm
