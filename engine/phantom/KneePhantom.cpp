#include "phantom/KneePhantom.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "core/Error.h"
#include "core/Parallel.h"

namespace fm {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;
constexpr double kFar = 1e9;  // "distance" of a point outside a bone's bounding box

// ---- Signed-distance building blocks (negative inside; mm). Ellipsoid and ellipse distances
// are the usual first-order approximations, exact on the surface and close to it.

double smoothMin(double a, double b, double k) {
    const double h = std::max(k - std::abs(a - b), 0.0) / k;
    return std::min(a, b) - h * h * k * 0.25;
}

double smoothSubtract(double a, double b, double k) {
    return -smoothMin(-a, b, k);
}

double capsule(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, double r) {
    const glm::dvec3 pa = p - a, ba = b - a;
    const double h = std::clamp(glm::dot(pa, ba) / glm::dot(ba, ba), 0.0, 1.0);
    return glm::length(pa - ba * h) - r;
}

double ellipsoid(const glm::dvec3& p, const glm::dvec3& r) {
    const double k1 = glm::length(p / (r * r));
    if (k1 == 0.0) return -std::min({r.x, r.y, r.z});
    const double k0 = glm::length(p / r);
    return k0 * (k0 - 1.0) / k1;
}

double ellipse(const glm::dvec2& p, const glm::dvec2& r) {
    const double k1 = glm::length(p / (r * r));
    if (k1 == 0.0) return -std::min(r.x, r.y);
    const double k0 = glm::length(p / r);
    return k0 * (k0 - 1.0) / k1;
}

double segment2(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b) {
    const glm::dvec2 pa = p - a, ba = b - a;
    const double h = std::clamp(glm::dot(pa, ba) / glm::dot(ba, ba), 0.0, 1.0);
    return glm::length(pa - ba * h);
}

// A 2D shape (distance d2) extruded over [-half, half] along a third coordinate `along`, with
// edges rounded by `round` mm.
double roundedExtrusion(double d2, double along, double half, double round) {
    const glm::dvec2 w{d2 + round, std::abs(along) - half + round};
    return std::min(std::max(w.x, w.y), 0.0) + glm::length(glm::max(w, glm::dvec2(0.0))) - round;
}

double smoothstep(double e0, double e1, double x) {
    const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// Rotation about the x axis by `angle` (cos c, sin s): knee flexion swings the shank posteriorly
// (+y), i.e. (0,0,-1) goes to (0, sin, -cos).
glm::dvec3 rotateX(const glm::dvec3& p, double c, double s) {
    return {p.x, p.y * c - p.z * s, p.y * s + p.z * c};
}

struct Aabb {
    glm::dvec3 lo, hi;
    bool contains(const glm::dvec3& p) const {
        return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z &&
               p.z <= hi.z;
    }
};

Aabb grown(Aabb box, double margin) {
    box.lo -= margin;
    box.hi += margin;
    return box;
}

constexpr double kInfZ = std::numeric_limits<double>::infinity();
// Bone bounding boxes in each bone's own frame (smooth unions may bulge a few mm beyond).
const Aabb kFemurBox{{-37.0, -31.0, 1.0}, {39.0, 31.0, kInfZ}};
const Aabb kTibiaBox{{-38.0, -29.0, -kInfZ}, {40.0, 31.0, 4.0}};
const Aabb kFibulaBox{{-47.0, 11.0, -kInfZ}, {-22.0, 33.0, -23.0}};
const Aabb kPatellaBox{-kPatellaSemiAxes, kPatellaSemiAxes};

// ---- Bones (model frame for the femur; tibia frame for tibia and fibula).

double condyle(const glm::dvec3& p, double xLo, double xHi) {
    constexpr glm::dvec2 kPosteriorDistal{kFlexionAxisPoint.y, kFlexionAxisPoint.z};
    constexpr glm::dvec2 kAnteriorProximal{-8.0, 32.0};
    constexpr double kEdgeRounding = 10.0;
    const double d2 = segment2({p.y, p.z}, kPosteriorDistal, kAnteriorProximal) - kCondyleRadius;
    return roundedExtrusion(d2, p.x - 0.5 * (xLo + xHi), 0.5 * (xHi - xLo), kEdgeRounding);
}

double femurDistance(const glm::dvec3& p) {
    double d = capsule(p, kFemurShaftStart, kFemurShaftEnd, kFemurShaftRadius);
    // Metaphysis: a wide smooth union gives the concave, trumpet-like flare of real bone.
    d = smoothMin(d, ellipsoid(p - glm::dvec3(0.0, -3.0, 50.0), {24.0, 18.0, 26.0}), 22.0);
    d = smoothMin(d, ellipsoid(p - glm::dvec3(0.0, -8.0, 36.0), {33.0, 22.0, 22.0}), 10.0);
    const double condyles = std::min(condyle(p, 7.0, 39.0), condyle(p, -37.0, -7.0));
    d = smoothMin(d, condyles, 6.0);
    // Trochlear groove where the patella glides.
    const double groove = capsule(p, {0.0, -36.0, 56.0}, {0.0, -33.0, 14.0}, 8.0);
    return smoothSubtract(d, groove, 4.0);
}

double tibiaDistance(const glm::dvec3& p) {
    const double plateau2 = ellipse({p.x - 1.0, p.y - 4.0}, {38.0, 26.0});
    constexpr double kPlateauBottom = -24.0;
    const double midZ = 0.5 * (kTibialPlateauTopZ + kPlateauBottom);
    double d =
        roundedExtrusion(plateau2, p.z - midZ, 0.5 * (kTibialPlateauTopZ - kPlateauBottom), 6.0);
    d = smoothMin(d, ellipsoid(p - glm::dvec3(0.0, 4.0, -3.0), {5.5, 10.0, 6.0}), 3.0);
    d = smoothMin(d, ellipsoid(p - glm::dvec3(1.0, 2.0, -30.0), {27.0, 20.0, 22.0}), 12.0);
    d = smoothMin(d, capsule(p, kTibiaShaftStart, kTibiaShaftEnd, kTibiaShaftRadius), 22.0);
    return smoothMin(d, ellipsoid(p - glm::dvec3(2.0, -20.0, -36.0), {11.0, 8.0, 14.0}), 8.0);
}

double fibulaDistance(const glm::dvec3& p) {
    const double head = ellipsoid(p - glm::dvec3(-36.0, 22.0, -36.0), {10.0, 10.0, 12.0});
    return smoothMin(head, capsule(p, kFibulaShaftStart, kFibulaShaftEnd, kFibulaShaftRadius), 8.0);
}

// ---- Soft tissue: elliptic cross-section of the limb along its segment axis.
struct LimbProfile {
    glm::dvec2 center;
    glm::dvec2 semiAxes;
    double fatMm;
};

// zRel: height above the flexion axis in the segment's own frame (thigh > 0, shank < 0).
// Constant within 30 mm of the axis so that the two segments meet without a step.
LimbProfile limbProfile(double zRel) {
    if (zRel >= 0.0) {
        const double t = smoothstep(30.0, 150.0, zRel);
        // The thigh follows the femur's valgus tilt.
        const double slope =
            (kFemurShaftEnd.x - kFemurShaftStart.x) / (kFemurShaftEnd.z - kFemurShaftStart.z);
        const double shaftZ = kFemurShaftStart.z - kFlexionAxisPoint.z;
        return {{slope * std::max(0.0, zRel - shaftZ), 4.0 + 2.0 * t},
                {56.0 + 16.0 * t, 63.0 + 9.0 * t},
                6.0 + 4.0 * t};
    }
    const double t = smoothstep(30.0, 150.0, -zRel);
    return {{2.0 * t, 4.0 + 20.0 * t}, {56.0 - 8.0 * t, 63.0 - 13.0 * t}, 6.0 + 1.0 * t};
}

// Fraction of a voxel inside a surface at signed distance d (linear ramp across the voxel).
struct Coverage {
    double invWidth;
    double operator()(double d) const { return std::clamp(0.5 - d * invWidth, 0.0, 1.0); }
};

}  // namespace

double corticalThicknessMm(double distanceFromJointMm) {
    return 2.5 + 2.5 * smoothstep(45.0, 110.0, std::abs(distanceFromJointMm));
}

void validateKneeParams(const KneePhantomParams& p) {
    auto fail = [](const std::string& why) { throw Error("knee phantom: " + why); };
    constexpr int kMaxDim = 2048;  // beyond this the phantom is absurd, not a CT
    for (int a = 0; a < 3; ++a) {
        if (p.dims[a] < 2 || p.dims[a] > kMaxDim) {
            std::ostringstream msg;
            msg << "size must be 2.." << kMaxDim << " voxels per axis, got " << p.dims.x << "x"
                << p.dims.y << "x" << p.dims.z;
            fail(msg.str());
        }
        constexpr double kMinField = 10.0, kMaxField = 2000.0;  // mm
        if (!std::isfinite(p.fieldMm[a]) || p.fieldMm[a] < kMinField || p.fieldMm[a] > kMaxField) {
            std::ostringstream msg;
            msg << "field must be " << kMinField << ".." << kMaxField << " mm per axis, got "
                << p.fieldMm.x << "x" << p.fieldMm.y << "x" << p.fieldMm.z;
            fail(msg.str());
        }
    }
    if (!std::isfinite(p.flexionDeg) || p.flexionDeg < kKneeMinFlexionDeg ||
        p.flexionDeg > kKneeMaxFlexionDeg) {
        std::ostringstream msg;
        msg << "flexion must be " << kKneeMinFlexionDeg << ".." << kKneeMaxFlexionDeg
            << " degrees, got " << p.flexionDeg;
        fail(msg.str());
    }
    const float hu[] = {p.hu.air, p.hu.fat, p.hu.muscle, p.hu.cancellous, p.hu.cortical};
    for (float v : hu)
        if (!std::isfinite(v)) fail("tissue values must be finite");
    const double voxels = static_cast<double>(p.dims.x) * p.dims.y * p.dims.z;
    if (voxels > static_cast<double>(kMaxVoxelCount))
        fail("size of " + std::to_string(p.dims.x) + "x" + std::to_string(p.dims.y) + "x" +
             std::to_string(p.dims.z) + " voxels exceeds the supported maximum");
}

std::string describeKnee(const KneePhantomParams& p) {
    std::ostringstream s;
    s << "procedural " << (p.leftKnee ? "left" : "right") << " knee phantom: " << p.dims.x << "x"
      << p.dims.y << "x" << p.dims.z << " voxels, field " << p.fieldMm.x << "x" << p.fieldMm.y
      << "x" << p.fieldMm.z << " mm, flexion " << p.flexionDeg << " deg; HU air " << p.hu.air
      << ", fat " << p.hu.fat << ", muscle " << p.hu.muscle << ", cancellous " << p.hu.cancellous
      << ", cortical " << p.hu.cortical;
    return s.str();
}

namespace {

// Rigid placement of the moving parts for one flexion angle.
struct KneePose {
    double cosT, sinT;  // tibia rotation
    double cosP, sinP;  // patella rotation
    glm::dvec3 patellaCenter;
    double cosHalf, sinHalf;  // bisecting plane between thigh and shank

    explicit KneePose(double flexionDeg) {
        const double theta = flexionDeg * kDegToRad;
        cosT = std::cos(theta);
        sinT = std::sin(theta);
        cosHalf = std::cos(0.5 * theta);
        sinHalf = std::sin(0.5 * theta);
        const double alpha = kPatellaFlexionRatio * theta;
        cosP = std::cos(alpha);
        sinP = std::sin(alpha);
        // The patella rides around the condyles and sinks towards them as the knee bends.
        constexpr double kPatellaSinkMm = 18.0;
        const glm::dvec3 rest = kPatellaCenter - kFlexionAxisPoint;
        const double radius = glm::length(rest) - kPatellaSinkMm * std::sin(std::max(alpha, 0.0));
        patellaCenter = kFlexionAxisPoint + rotateX(glm::normalize(rest), cosP, sinP) * radius;
    }
    glm::dvec3 tibiaToModel(const glm::dvec3& t) const {
        return kFlexionAxisPoint + rotateX(t - kFlexionAxisPoint, cosT, sinT);
    }
    glm::dvec3 modelToTibia(const glm::dvec3& m) const {
        return kFlexionAxisPoint + rotateX(m - kFlexionAxisPoint, cosT, -sinT);
    }
    glm::dvec3 patellaToModel(const glm::dvec3& local) const {
        return patellaCenter + rotateX(local, cosP, sinP);
    }
    glm::dvec3 modelToPatella(const glm::dvec3& m) const {
        return rotateX(m - patellaCenter, cosP, -sinP);
    }
};

// Which bone is nearest to a point (given in the model, tibia and patella frames) and how far.
struct NearestBone {
    double distance = kFar;  // signed distance to that bone's surface, mm (kFar: none near)
    double cortexMm = 2.5;
    KneeBoneLabel label = KneeBoneLabel::None;
};

struct BoneBoxes {
    Aabb femur, tibia, fibula, patella;
    // Bounding boxes grown by the anti-aliasing ramp and the smooth-union bulge.
    explicit BoneBoxes(double voxelWidth)
        : femur(grown(kFemurBox, voxelWidth + 5.0)),
          tibia(grown(kTibiaBox, voxelWidth + 5.0)),
          fibula(grown(kFibulaBox, voxelWidth + 5.0)),
          patella(grown(kPatellaBox, voxelWidth + 5.0)) {}

    NearestBone nearest(const glm::dvec3& m, const glm::dvec3& t, const glm::dvec3& pl) const {
        NearestBone b;
        if (femur.contains(m)) {
            b = {femurDistance(m), corticalThicknessMm(m.z), KneeBoneLabel::Femur};
        }
        if (tibia.contains(t)) {
            const double dt = tibiaDistance(t);
            if (dt < b.distance) b = {dt, corticalThicknessMm(t.z), KneeBoneLabel::Tibia};
        }
        if (fibula.contains(t)) {
            const double df = fibulaDistance(t);
            if (df < b.distance)
                b = {df, std::min(corticalThicknessMm(t.z), 3.5), KneeBoneLabel::Fibula};
        }
        if (patella.contains(pl)) {
            const double dp = ellipsoid(pl, kPatellaSemiAxes);
            if (dp < b.distance) b = {dp, 2.0, KneeBoneLabel::Patella};
        }
        return b;
    }
};

}  // namespace

glm::dvec3 kneeModelToWorld(const KneePhantomParams& params, KneeSegment segment,
                            const glm::dvec3& modelPoint) {
    const KneePose pose(params.flexionDeg);
    glm::dvec3 m = modelPoint;
    switch (segment) {
        case KneeSegment::Femur:
            break;
        case KneeSegment::Tibia:
            m = pose.tibiaToModel(modelPoint);
            break;
        case KneeSegment::Patella:
            m = pose.patellaToModel(modelPoint - kPatellaCenter);
            break;
    }
    if (params.leftKnee) m.x = -m.x;
    return m;
}

namespace {

// The phantom's grid: `params.dims` voxels over `params.fieldMm`, centred at the joint.
Volume kneeGrid(const KneePhantomParams& params, float fill) {
    Volume v = Volume::allocate(params.dims, fill);
    v.spacing = params.fieldMm / glm::dvec3(params.dims);
    v.origin = -(glm::dvec3(params.dims) - 1.0) * 0.5 * v.spacing;  // centre at the joint
    return v;
}

double voxelWidthOf(const Volume& v) {
    return (v.spacing.x + v.spacing.y + v.spacing.z) / 3.0;
}

// Calls body(i, j, k, m) for every voxel of `v`, m its centre in the model frame (x mirrored
// for a left knee); slices in parallel, each voxel written by one call only.
template <class Body>
void forEachVoxel(const KneePhantomParams& params, const Volume& v, const Body& body) {
    const double mirror = params.leftKnee ? -1.0 : 1.0;
    parallelFor(params.dims.z, params.threads, [&](int k0, int k1) {
        for (int k = k0; k < k1; ++k)
            for (int j = 0; j < params.dims.y; ++j)
                for (int i = 0; i < params.dims.x; ++i) {
                    glm::dvec3 m = v.origin + v.spacing * glm::dvec3(i, j, k);
                    m.x *= mirror;
                    body(i, j, k, m);
                }
    });
}

}  // namespace

Volume makeKneePhantom(const KneePhantomParams& params) {
    validateKneeParams(params);
    Volume v = kneeGrid(params, params.hu.air);
    v.meta.source = "phantom:knee";
    v.meta.modality = "CT";
    v.meta.units = ValueUnit::HounsfieldUnits;
    v.meta.description = describeKnee(params);

    const KneePose pose(params.flexionDeg);
    const double voxelWidth = voxelWidthOf(v);
    const Coverage cover{1.0 / voxelWidth};
    const BoneBoxes boxes(voxelWidth);
    const KneeTissueHU hu = params.hu;

    forEachVoxel(params, v, [&](int i, int j, int k, const glm::dvec3& m) {
        const glm::dvec3 t = pose.modelToTibia(m);

        // Soft tissue, in the frame of whichever segment's side of the bisecting
        // plane the point lies on.
        const glm::dvec3 rel = m - kFlexionAxisPoint;
        const bool thighSide = -rel.y * pose.sinHalf + rel.z * pose.cosHalf >= 0.0;
        const glm::dvec3 q = thighSide ? m : t;
        const LimbProfile limb = limbProfile(q.z - kFlexionAxisPoint.z);
        const double skin = ellipse(glm::dvec2(q.x, q.y) - limb.center, limb.semiAxes);
        const double inSkin = cover(skin);
        if (inSkin <= 0.0) return;  // air
        const double inMuscle = cover(skin + limb.fatMm);
        double pad = 0.0;
        if (inMuscle > 0.0) {
            const double popliteal = ellipsoid(m - glm::dvec3(0.0, 46.0, 20.0), {24.0, 14.0, 40.0});
            const double infrapatellar =
                ellipsoid(t - glm::dvec3(0.0, -30.0, 4.0), {18.0, 6.0, 9.0});
            pad = cover(std::min(popliteal, infrapatellar));
        }
        double value =
            hu.air + inSkin * (hu.fat - hu.air) + inMuscle * (1.0 - pad) * (hu.muscle - hu.fat);

        // Bones: the nearest one decides (they do not overlap).
        const NearestBone bone = boxes.nearest(m, t, pose.modelToPatella(m));
        const double d = bone.distance, cortex = bone.cortexMm;
        const double inBone = cover(d);
        if (inBone > 0.0) {
            const double inCancellous = cover(d + cortex);
            value += inBone * (hu.cortical - value) + inCancellous * (hu.cancellous - hu.cortical);
        }
        v.at(i, j, k) = static_cast<float>(value);
    });
    return v;
}

Volume makeKneeBoneLabels(const KneePhantomParams& params) {
    validateKneeParams(params);
    Volume v = kneeGrid(params, 0.0f);
    v.meta.source = "phantom:knee labels";
    v.meta.description =
        "bone labels (1 femur, 2 tibia, 3 fibula, 4 patella) of the " + describeKnee(params);
    const KneePose pose(params.flexionDeg);
    const double voxelWidth = voxelWidthOf(v);
    const Coverage cover{1.0 / voxelWidth};
    const BoneBoxes boxes(voxelWidth);
    forEachVoxel(params, v, [&](int i, int j, int k, const glm::dvec3& m) {
        const NearestBone bone = boxes.nearest(m, pose.modelToTibia(m), pose.modelToPatella(m));
        if (cover(bone.distance) > 0.0)
            v.at(i, j, k) = static_cast<float>(static_cast<int>(bone.label));
    });
    return v;
}

}  // namespace fm
