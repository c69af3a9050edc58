#pragma once
// The default scene: a procedural CT of a knee, standing in for the 128x128x141 knee CT
// (22.0 x 22.0 x 28.1 cm) the 2011 program shipped. No patient data; generated in milliseconds.
//
// Anatomy model (a right knee unless `leftKnee`), in the MODEL frame: LPS millimetres with the
// origin at the centre of the joint line (midway between femoral condyles and tibial plateau),
// x = patient left (medial for a right knee), y = posterior, z = superior. The volume is placed
// so that Volume::center() is this origin; its direction is identity.
//   femur   shaft (radius kFemurShaftRadius, ~6 deg valgus tilt) flaring through a metaphysis
//           into a trochlea block and two condyles (sagittal radius kCondyleRadius);
//   tibia   plateau (elliptic, 76 x 52 mm) with intercondylar eminence, metaphysis, tuberosity
//           and shaft;
//   fibula  head lateral-posterior below the plateau, thin shaft;
//   patella flattened ellipsoid anterior to the trochlea;
// each with a cortical shell (corticalThicknessMm: 2.5 mm near the joint, thickening to 5 mm
// along the shafts, as real long bones do) around cancellous bone; soft tissue is an elliptic
// limb cross-section, muscle inside a fat layer, with popliteal and infrapatellar fat pads;
// air outside. Edges are anti-aliased analytically (fraction inside ~ 0.5 - distance / voxel
// width) so that isosurfaces are not staircase-like.
//
// Flexion rotates tibia and fibula about the flexion axis (through kFlexionAxisPoint, along x);
// the patella follows at kPatellaFlexionRatio of that angle and sinks towards the condyles; the
// soft tissue bends with the bone (each side of the bisecting plane uses its segment's frame).
#include <string>

#include <glm/glm.hpp>

#include "volume/Volume.h"

namespace fm {

struct KneeTissueHU {
    float air = -1000.0f;
    float fat = -100.0f;
    float muscle = 40.0f;
    float cancellous = 350.0f;  // above 300 so that the 300 HU level set is solid bone
    float cortical = 1500.0f;
};

struct KneePhantomParams {
    glm::ivec3 dims{128, 128, 141};           // as the 2011 knee CT
    glm::dvec3 fieldMm{220.0, 220.0, 281.0};  // field of view; spacing = fieldMm / dims
    double flexionDeg = 0.0;                  // 0 = straight leg; kKneeMin..MaxFlexionDeg
    bool leftKnee = false;                    // mirror x: fibula on the patient's left
    KneeTissueHU hu;
    int threads = 0;  // 0 = all cores; the result does not depend on it
};

inline constexpr double kKneeMinFlexionDeg = -10.0;  // slight hyperextension
inline constexpr double kKneeMaxFlexionDeg = 120.0;  // deep flexion, still anatomical

// --- Model landmarks (model frame, right knee, flexion 0). Tests and target points use them.
// Flexion axis: the centre of the condyles' posterior-distal circle.
inline constexpr glm::dvec3 kFlexionAxisPoint{0.0, 8.0, 24.0};
inline constexpr double kCondyleRadius = 22.0;
// Femoral shaft axis runs from kFemurShaftStart upwards through kFemurShaftEnd.
inline constexpr glm::dvec3 kFemurShaftStart{0.0, -2.0, 60.0};
inline constexpr glm::dvec3 kFemurShaftEnd{-16.0, 0.0, 240.0};
inline constexpr double kFemurShaftRadius = 13.5;
// Tibial shaft axis, in the tibia's own (unflexed) frame.
inline constexpr glm::dvec3 kTibiaShaftStart{2.0, -2.0, -55.0};
inline constexpr glm::dvec3 kTibiaShaftEnd{4.0, 0.0, -240.0};
inline constexpr double kTibiaShaftRadius = 12.5;
inline constexpr double kTibialPlateauTopZ = -3.0;
// Fibular shaft axis, in the tibia's frame.
inline constexpr glm::dvec3 kFibulaShaftStart{-36.0, 22.0, -40.0};
inline constexpr glm::dvec3 kFibulaShaftEnd{-30.0, 20.0, -240.0};
inline constexpr double kFibulaShaftRadius = 7.5;
// Patella (ellipsoid) at flexion 0.
inline constexpr glm::dvec3 kPatellaCenter{-2.0, -44.0, 38.0};
inline constexpr glm::dvec3 kPatellaSemiAxes{22.0, 10.5, 22.0};
inline constexpr double kPatellaFlexionRatio = 0.7;

// Cortical thickness at a distance (mm, along the bone axis) from the joint line.
double corticalThicknessMm(double distanceFromJointMm);

// Throws fm::Error naming the parameter if dims, field, flexion or the HU values are unusable.
void validateKneeParams(const KneePhantomParams& params);

// One line describing the parameters (stored as the volume's description).
std::string describeKnee(const KneePhantomParams& params);

// Which rigid part of the knee a model point belongs to.
enum class KneeSegment { Femur, Tibia, Patella };

// World position (in the generated volume) of a model point attached to `segment`, for the
// given flexion and side: rotates tibia/fibula and patella, mirrors x for a left knee.
glm::dvec3 kneeModelToWorld(const KneePhantomParams& params, KneeSegment segment,
                            const glm::dvec3& modelPoint);

Volume makeKneePhantom(const KneePhantomParams& params = {});

// The bones of the phantom as labels (the label map of makeKneePhantom(params), same grid):
// a voxel carries the label of the nearest bone when any of that bone covers it (so the
// partial-volume voxels at a bone's edge belong to the bone), 0 for soft tissue and air.
enum class KneeBoneLabel { None = 0, Femur = 1, Tibia = 2, Fibula = 3, Patella = 4 };
Volume makeKneeBoneLabels(const KneePhantomParams& params = {});

}  // namespace fm
