#pragma once
// A scene of several bones cut from one CT by a label map: one SceneObject per bone (its own
// prepared DRR volume, in the CT's world frame, so the identity pose is where the CT has it),
// and optionally the rest of the CT (soft tissue and unnamed bones) as one static object.
// The DRR of the scene is the sum of its objects' DRRs, each traced in its own frame
// (renderView); moving a bone is setting its worldFromObject.
#include <string>
#include <vector>

#include "bones/BoneVolume.h"
#include "bones/LabelTable.h"
#include "drr/Drr.h"
#include "scene/Scene.h"
#include "volume/Volume.h"

namespace fm {

inline constexpr const char* kRestObjectName = "rest";

struct BoneSceneOptions {
    DrrValueOptions values;      // how the DRR volumes are prepared
    bool includeRest = true;     // the CT without the bones, as the object "rest"
    BoneVolumeOptions volume;    // crop margin, air value
};

// The union of several bones' labels (name "a+b"): what "without these bones" removes.
BoneSelection unionOf(const std::vector<BoneSelection>& bones);

// Throws fm::Error for an empty bone, two bones sharing a label, or a name used twice.
Scene makeBoneScene(const Volume& ct, const Volume& labels, const std::vector<BoneSelection>& bones,
                    const BoneSceneOptions& options = {});

// The pose of bone `b` in the frame of bone `a` (aFromB = worldFromA^-1 worldFromB): relative
// kinematics, independent of where the scene's world or its cameras are.
RigidTransform relativePose(const Scene& scene, const std::string& a, const std::string& b);

}  // namespace fm
