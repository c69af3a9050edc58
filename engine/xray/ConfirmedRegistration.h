#pragma once
// Registering every object of a calibrated scene against one radiograph, each answer confirmed
// by searches from independent starts (issue 30: "agreement between restarts"; "a result that is
// not ok is searched again before it is reported"):
//   1. each object is searched from its start and from `runs - 1` starts drawn around it
//      (seeded: run r uses seed + r), side by side, one search per core;
//   2. the answer is the run with the best similarity; the runs that end within the agreement
//      bounds of it (in-plane and rotation as the camera sees them: single-view depth is weak
//      and reported by the uncertainty instead) confirm it;
//   3. an object that no second run confirms is searched again, from further draws, until two
//      agree or `maxRuns` have run (the re-search's budget);
//   4. the curvature of the cost at the answer (search/PoseUncertainty) says how well the image
//      fixes each coordinate.
// With edge distance, the answer's similarity is evidence too (against a perfect outline match's
// 1: kConfirmedOutlineRatio). The evidence goes into checkAnswer (xray/AnswerCheck.h) with the
// caller's mask, if any.
// Results depend on the seeds only, not on the thread count.
#include <functional>
#include <vector>

#include "search/ConfirmedSearch.h"
#include "xray/AnswerCheck.h"
#include "xray/CameraPoseDifference.h"
#include "xray/ObjectRegistration.h"

namespace fm {


struct ConfirmedObject {
    // The best run; evaluations, seconds and profile are the runs' sums (the uncertainty's
    // evaluations are its own: evidence.uncertainty->evaluations).
    ObjectRegistrationResult answer;
    std::vector<ObjectRegistrationResult> runs;
    AnswerEvidence evidence;  // runs, agreeing, uncertainty, stopped (the caller adds a mask's IoU)
};

struct ObjectsRegistration {
    std::vector<ConfirmedObject> objects;  // per object of the scene
    bool sideBySide = false;
    double wallSeconds = 0.0;
};

// The start of run `run` of an object (run 0: `start` itself).
RigidTransform confirmationStart(const ProjectionGeometry& camera, const RigidTransform& start,
                                 const glm::dvec3& pivot, const RegistrationSettings& settings,
                                 const ConfirmationSettings& confirmation, int run);

// Whether two poses of an object agree in 3D (several cameras fix depth too): its pivot within
// agreeInPlaneMm of each other and the relative rotation within agreeRotationDeg.
bool posesAgree(const RigidTransform& a, const RigidTransform& b, const glm::dvec3& pivot,
                const ConfirmationSettings& bounds);

// Whether two answers are one as a camera sees them: the in-plane shift and the rotation of
// their difference within the agreement bounds (depth, which one view hardly fixes, aside).
bool sameAnswerInView(const CameraPoseDifference& d, const ConfirmationSettings& bounds = {});

// Whether searches run side by side (several searches and cores) or one after the other.
bool registersSideBySide(std::size_t searches, const RegistrationSettings& settings);

// Every object of `scene` from its pose in `scene`. progressFor(k), if given, is object k's
// progress callback (its first run's). Throws as registerObject.
ObjectsRegistration registerObjects(const Scene& scene, const RegistrationView& view,
                                    const RegistrationSettings& settings,
                                    const ConfirmationSettings& confirmation = {},
                                    const std::function<RegistrationCallback(std::size_t)>& progressFor = {},
                                    const std::atomic<bool>* stop = nullptr);

}  // namespace fm
