#pragma once
// Registering the objects of a calibrated scene against one radiograph when some have no start:
// each of those is found first (find/PoseFinder, one after the other, each on every core), then
// every object is confirmed as `register --start` confirms it (xray/ConfirmedRegistration:
// searches from independent starts, the curvature at the answer). The finder's best answer
// further from the confirmed one than the registration's start radius (a search from nearer ends
// at the answer) is the answer's rival (search/AnswerVerdict: a near-symmetric
// outline's mirror pose scores nearly as well and the verdict says so).
#include <atomic>
#include <functional>
#include <optional>
#include <vector>

#include "find/PoseFinder.h"
#include "xray/ConfirmedRegistration.h"

namespace fm {

struct FoundRegistration {
    ObjectsRegistration registration;             // evidence.rival set for the objects found
    std::vector<std::optional<FoundPose>> found;  // per object: how it was found (nullopt: it had a start)
};

// `findPose[k]`: object k has no start (its pose in `scene` is ignored). Throws as registerObjects
// and findObjectPose, and if findPose's size differs from the number of objects.
FoundRegistration registerObjectsFinding(const Scene& scene, const std::vector<bool>& findPose,
                                         const RegistrationView& view, const RegistrationSettings& settings,
                                         const FindSettings& find, const ConfirmationSettings& confirmation = {},
                                         const std::function<RegistrationCallback(std::size_t)>& progressFor = {},
                                         const std::atomic<bool>* stop = nullptr);

}  // namespace fm
