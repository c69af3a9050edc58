#pragma once
// The module's parts, one per room of the engine it exposes (Module.cpp calls each once).
#include <pybind11/pybind11.h>

namespace fm::py {

void bindVolume(pybind11::module_& m);    // volumes, label maps, one bone
void bindGeometry(pybind11::module_& m);  // projection geometry, cameras, the 2011 scene
void bindPoses(pybind11::module_& m);     // .tra, .jts, xyzypr and JointTrack angles
void bindDrr(pybind11::module_& m);       // exact DRRs of volumes and meshes
void bindRadiograph(pybind11::module_& m);  // realistic radiographs (spectrum, detector)
void bindMesh(pybind11::module_& m);      // marching cubes, mesh files
void bindImages(pybind11::module_& m);    // radiographs, their preparation, similarity
void bindRegister(pybind11::module_& m);  // register (real X-ray and 2011 scene)
void bindTrack(pybind11::module_& m);     // track a trial

}  // namespace fm::py
