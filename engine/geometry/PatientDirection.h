#pragma once
// Orientation letters of a direction in the patient frame (LPS: +x Left, +y Posterior,
// +z Superior), as radiology viewers print them at the image edges: the letter of the
// strongest component first, then those of the others that are at least half as strong
// (DICOM's "RA", "LPS" style). 3D Slicer's RAS has x and y negated: the letters are the same.
#include <string>

#include <glm/glm.hpp>

#include "geometry/ProjectionGeometry.h"

namespace fm {

// "" for a zero vector.
std::string patientDirectionLetters(const glm::dvec3& lps);

// The letters at the four edges of a projection image (column 0 at the left, row 0 at the
// top): left = -u, right = +u, top = -v, bottom = +v of the detector.
struct ImageEdgeLetters {
    std::string left, right, top, bottom;
};
ImageEdgeLetters imageEdgeLetters(const ProjectionGeometry& geometry);
// The same for any image whose columns run along `u` and rows along `v` (an MRI slice).
ImageEdgeLetters imageEdgeLetters(const glm::dvec3& u, const glm::dvec3& v);

}  // namespace fm
