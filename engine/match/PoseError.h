#pragma once
// How far one 2011 pose is from another: per parameter, and as the mean target registration
// error (mTRE) over points on the bone.
//
// In the 2011 parameterisation the CT stays put and the source and film move around it. What
// an X-ray shows depends only on where the CT sits relative to the source and film, so every
// target point is expressed in the CAMERA frame of each pose: relative to the source, along the
// film's column direction u, row direction v and the beam axis n = u x v (from the source
// towards the film). The error of a point is the distance between its camera coordinates under
// the two poses: a pure offset change of d mm moves every point by |d|; a change of azimuth,
// elevation or film rotation turns the points about the isocenter (or the central ray).
// "In plane" is the part parallel to the film (u, v), "depth" the part along the beam (n),
// which a single X-ray hardly shows (it only changes magnification).
#include <array>
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "geometry/Pose.h"
#include "volume/Volume.h"

namespace fm {

inline constexpr int kPoseParameterCount = 6;
// Display names, in Pose::toArray() order: "x offset", "y offset", "z offset", "azimuth",
// "elevation", "rotation".
const char* poseParameterName(int index);
// "mm" for the offsets, "deg" for the angles.
const char* poseParameterUnit(int index);
bool isAngleParameter(int index);

// An angle in degrees wrapped to [-180, 180).
double wrapDegrees(double degrees);

// candidate - reference per parameter (Pose::toArray() order); angle differences wrapped to
// [-180, 180), so azimuth 179 vs -179 is 2 degrees apart, not 358.
std::array<double, kPoseParameterCount> poseDifference(const Pose& reference,
                                                       const Pose& candidate);

// Bone points to measure the mTRE on: world positions of the centres of voxels at or above
// `threshold`, evenly subsampled in storage order (every ceil(count / maxPoints)-th voxel) so
// that the set is deterministic and spread over all bones. Throws fm::Error if no voxel
// reaches the threshold or maxPoints is 0.
std::vector<glm::dvec3> boneTargetPoints(const Volume& volume, double threshold = 300.0,
                                         std::size_t maxPoints = 2000);

// A world point in the camera frame of a projection: ((p-s).u, (p-s).v, (p-s).n), with s the
// source and n = u x v the unit beam direction (source towards film).
glm::dvec3 toCameraFrame(const ProjectionGeometry& geometry, const glm::dvec3& world);

struct TargetRegistrationError {
    double meanMm = 0.0;         // mean |camera(A) - camera(B)|: the mTRE
    double meanInPlaneMm = 0.0;  // mean of the film-parallel part (u, v)
    double meanDepthMm = 0.0;    // mean of |part along the beam|
    double maxMm = 0.0;          // the worst point
};

// mTRE between two projections of the same CT: each point in the camera frame of `a` and of
// `b` (serves calibrated geometries and the search's pose models). Throws fm::Error if
// `points` is empty.
TargetRegistrationError targetRegistrationError(const ProjectionGeometry& a,
                                                const ProjectionGeometry& b,
                                                const std::vector<glm::dvec3>& points);

// mTRE between two poses of the same scene. `volumeCenter` is Volume::center() of the CT the
// points lie in. Throws fm::Error if `points` is empty (or a pose or the setup is unusable).
TargetRegistrationError targetRegistrationError(const Pose& a, const Pose& b,
                                                const SceneSetup& setup,
                                                const glm::dvec3& volumeCenter,
                                                const std::vector<glm::dvec3>& points);

}  // namespace fm
