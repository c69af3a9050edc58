#pragma once
// Registering one object of a calibrated scene against a real radiograph: the object's pose
// in the camera's frame (ObjectPoseParameterization, pivot at the centre of its bounds) is
// searched from a start pose; the other objects are hidden meanwhile (their outlines are not
// this object's evidence). Several objects, each confirmed by searches from independent starts:
// xray/ConfirmedRegistration.h.
#include <cstdint>
#include <string>
#include <vector>

#include "scene/Scene.h"
#include "search/PoseUncertainty.h"
#include "search/Registration.h"

namespace fm {

// The search for a real radiograph and a mesh (docs/real-xray.md gives the figures):
// edge-distance similarity (implants) or gradient NCC (CT volumes), levels 4, 2, 1 of a
// 1024-pixel image, a start within 5 mm in-plane, 20 mm in depth and 5 deg, each candidate
// rendered only where the model projects; for edge distance also out-of-plane hypotheses
// after the coarsest level and wider polishes.
RegistrationSettings realXraySettings(SimilarityMeasure similarity = SimilarityMeasure::EdgeDistance);

// The measure a model is registered with against a real radiograph when none is asked for:
// edge distance for meshes (an implant's outline is what the image shows best; a mesh's chords
// are traced, its footprint rasterised ~30x faster), gradient NCC for volumes (docs/real-xray.md
// compares them).
SimilarityMeasure defaultSimilarityFor(const XrayModel& model);

struct ObjectRegistrationResult {
    RigidTransform worldFromObject;
    double similarity = 0.0;  // at the finest level
    int evaluations = 0;
    double seconds = 0.0;
    bool stopped = false;
    EvaluationProfile profile;
};

// One object searched from any start, and its uncertainty measured at any answer, over one
// preparation of the view (its pyramid, edges and distance maps): `prepared` comes from
// prepareObjectRegistration; each call rebinds it to the object alone (the others hidden) in
// the camera's frame around its own pose (ObjectPoseParameterization, pivot at the centre of
// its bounds, depth along the pivot's ray) on `threads`, with the results of a registration
// constructed anew there (xray/ConfirmedRegistration.h runs a confirmation's searches and the
// uncertainty so). The uncertainty is search/PoseUncertainty's at the finest level. Throw
// fm::Error if the object or the view's camera does not exist (and as Registration).
Registration prepareObjectRegistration(const Scene& scene, std::size_t object, const RegistrationView& view,
                                       const RegistrationSettings& settings);
ObjectRegistrationResult registerObject(const Registration& prepared, const Scene& scene, std::size_t object,
                                        const RegistrationView& view, const RigidTransform& start,
                                        std::uint64_t seed, int threads,
                                        const RegistrationCallback& progress = {},
                                        const std::atomic<bool>* stop = nullptr);
PoseUncertainty objectPoseUncertainty(const Registration& prepared, const Scene& scene, std::size_t object,
                                      const RegistrationView& view, const RigidTransform& answer, int threads);

// The object's silhouette: pixels of `camera` whose ray crosses it (line integral > 0).
Mask objectSilhouette(const SceneObject& object, const ProjectionGeometry& camera, int threads = 0);

// |a and b| / |a or b|; 0 if both are empty. Throws fm::Error for masks of different sizes.
double silhouetteIoU(const Mask& a, const Mask& b);

}  // namespace fm
