// The knee phantom against the 2011 data's geometry, the documented tissue values and
// anatomical facts (bone sizes, positions), and the model's documented landmarks.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/Error.h"
#include "phantom/KneePhantom.h"

namespace {

// Tissue ranges from the issue text (HU).
constexpr float kCorticalMin = 1200, kCorticalMax = 1800;
constexpr float kCancellousMin = 200, kCancellousMax = 400;
constexpr float kMuscleMin = 0, kMuscleMax = 100;  // "about 40"
constexpr float kFatMin = -150, kFatMax = -50;     // "about -100"
constexpr float kAirMax = -990;                    // "-1000"
constexpr float kBoneLevel = 300;                  // the isosurface the issue asks for

// One shared default knee (generation takes milliseconds, but several tests read it).
const fm::Volume& defaultKnee() {
    static const fm::Volume v = fm::makeKneePhantom();
    return v;
}

float nearest(const fm::Volume& v, const glm::dvec3& world) {
    const glm::dvec3 ijk = glm::round(v.worldToIndex(world));
    const glm::ivec3 c = glm::clamp(glm::ivec3(ijk), glm::ivec3(0), v.dims - 1);
    return v.at(c.x, c.y, c.z);
}

double trilinear(const fm::Volume& v, const glm::dvec3& world) {
    const glm::dvec3 p = v.worldToIndex(world);
    const glm::ivec3 b = glm::clamp(glm::ivec3(glm::floor(p)), glm::ivec3(0), v.dims - 2);
    const glm::dvec3 f = p - glm::dvec3(b);
    double sum = 0.0;
    for (int c = 0; c < 8; ++c) {
        const glm::ivec3 o{c & 1, (c >> 1) & 1, (c >> 2) & 1};
        const double w = (o.x ? f.x : 1 - f.x) * (o.y ? f.y : 1 - f.y) * (o.z ? f.z : 1 - f.z);
        sum += w * v.at(b.x + o.x, b.y + o.y, b.z + o.z);
    }
    return sum;
}

// Point on a bone axis from `a` to `b` at height z (model frame).
glm::dvec3 axisAt(const glm::dvec3& a, const glm::dvec3& b, double z) {
    return a + (b - a) * ((z - a.z) / (b.z - a.z));
}

TEST(KneePhantom, DefaultMatchesThe2011KneeCt) {
    const fm::Volume& v = defaultKnee();
    EXPECT_EQ(v.dims, glm::ivec3(128, 128, 141));
    constexpr double kMm = 1e-9;  // spacing = field / dims in double precision
    EXPECT_NEAR(v.extent().x, 220.0, kMm);
    EXPECT_NEAR(v.extent().y, 220.0, kMm);
    EXPECT_NEAR(v.extent().z, 281.0, kMm);
    EXPECT_NEAR(v.spacing.x, 220.0 / 128.0, kMm);
    EXPECT_NEAR(v.spacing.z, 281.0 / 141.0, kMm);
    EXPECT_EQ(fm::orientationCode(v.direction), "LPS");
    EXPECT_NEAR(glm::length(v.center()), 0.0, kMm);  // the joint centre
    EXPECT_EQ(v.meta.source, "phantom:knee");
    EXPECT_EQ(v.meta.modality, "CT");
    EXPECT_EQ(v.meta.units, fm::ValueUnit::HounsfieldUnits);
    EXPECT_NE(v.meta.description.find("flexion 0"), std::string::npos);
    EXPECT_NO_THROW(v.validate("knee"));
}

TEST(KneePhantom, BonesHoldCancellousInsideCorticalShells) {
    const fm::Volume& v = defaultKnee();
    struct Bone {
        const char* name;
        glm::dvec3 a, b;
        double radius;
        double z;
    };
    const Bone bones[] = {
        {"femur", fm::kFemurShaftStart, fm::kFemurShaftEnd, fm::kFemurShaftRadius, 110.0},
        {"tibia", fm::kTibiaShaftStart, fm::kTibiaShaftEnd, fm::kTibiaShaftRadius, -110.0},
    };
    for (const Bone& bone : bones) {
        const glm::dvec3 axis = axisAt(bone.a, bone.b, bone.z);
        const float centre = nearest(v, axis);
        EXPECT_GE(centre, kCancellousMin) << bone.name;
        EXPECT_LE(centre, kCancellousMax) << bone.name;
        // Middle of the cortical shell, on a line perpendicular to the axis (posterior).
        const glm::dvec3 u = glm::normalize(bone.b - bone.a);
        const glm::dvec3 e = glm::normalize(glm::cross(u, glm::dvec3(1, 0, 0)));
        const double depth = 0.5 * fm::corticalThicknessMm(bone.z);
        for (double sign : {-1.0, 1.0}) {
            const float cortex = nearest(v, axis + sign * (bone.radius - depth) * e);
            EXPECT_GE(cortex, kCorticalMin) << bone.name;
            EXPECT_LE(cortex, kCorticalMax) << bone.name;
        }
    }
    // Fibula (lateral = patient right = -x for the default right knee) and patella centres.
    const float fibula = nearest(v, axisAt(fm::kFibulaShaftStart, fm::kFibulaShaftEnd, -100.0));
    EXPECT_GE(fibula, kCancellousMin);
    EXPECT_LE(fibula, kCancellousMax);
    const float patella = nearest(v, fm::kPatellaCenter);
    EXPECT_GE(patella, kCancellousMin);
    EXPECT_LE(patella, kCancellousMax);
    // The fibula is lateral and posterior to the tibia, the patella anterior to the femur.
    const glm::dvec3 tibia = axisAt(fm::kTibiaShaftStart, fm::kTibiaShaftEnd, -100.0);
    const glm::dvec3 fib = axisAt(fm::kFibulaShaftStart, fm::kFibulaShaftEnd, -100.0);
    EXPECT_LT(fib.x, tibia.x - 20.0);
    EXPECT_GT(fib.y, tibia.y);
    EXPECT_LT(fm::kPatellaCenter.y, -30.0);
}

TEST(KneePhantom, RadialProfileIsBoneMuscleFatAir) {
    // Walking from the femoral shaft axis towards patient left at z = 110 mm: cancellous,
    // cortex, then muscle, a fat layer of several mm under the skin, then air; each tissue's
    // plateau in its documented range.
    const fm::Volume& v = defaultKnee();
    const glm::dvec3 start = axisAt(fm::kFemurShaftStart, fm::kFemurShaftEnd, 110.0);
    enum Tissue { Cancellous, Cortical, Muscle, Fat, Air, Other };
    auto classify = [](float hu) {
        if (hu >= kCancellousMin && hu <= kCancellousMax) return Cancellous;
        if (hu >= kCorticalMin && hu <= kCorticalMax) return Cortical;
        if (hu >= kMuscleMin && hu <= kMuscleMax) return Muscle;
        if (hu >= kFatMin && hu <= kFatMax) return Fat;
        if (hu <= kAirMax) return Air;
        return Other;  // partial-volume edge
    };
    std::vector<Tissue> order;
    double fatMm = 0.0;
    const int i0 = static_cast<int>(std::lround(v.worldToIndex(start).x));
    const int j = static_cast<int>(std::lround(v.worldToIndex(start).y));
    const int k = static_cast<int>(std::lround(v.worldToIndex(start).z));
    for (int i = i0; i < v.dims.x; ++i) {
        const Tissue t = classify(v.at(i, j, k));
        if (t == Fat) fatMm += v.spacing.x;
        if (t != Other && (order.empty() || order.back() != t)) order.push_back(t);
    }
    const std::vector<Tissue> want{Cancellous, Cortical, Muscle, Fat, Air};
    EXPECT_EQ(order, want);
    EXPECT_GE(fatMm, 5.0);  // subcutaneous fat of the thigh: several mm
    EXPECT_LE(fatMm, 30.0);
    EXPECT_LE(v.at(0, 0, 0), kAirMax);
    EXPECT_LE(v.at(v.dims.x - 1, v.dims.y - 1, v.dims.z - 1), kAirMax);
}

TEST(KneePhantom, BoneSizesAreAnatomical) {
    const fm::Volume& v = defaultKnee();
    // Medial-lateral width of the bone (>= 300 HU) in the axial slice nearest to z.
    auto boneWidthX = [&](double z) {
        const int k = static_cast<int>(std::lround(v.worldToIndex({0, 0, z}).z));
        int lo = v.dims.x, hi = -1;
        for (int j = 0; j < v.dims.y; ++j)
            for (int i = 0; i < v.dims.x; ++i)
                if (v.at(i, j, k) >= kBoneLevel) {
                    lo = std::min(lo, i);
                    hi = std::max(hi, i);
                }
        return hi < lo ? 0.0 : (hi - lo + 1) * v.spacing.x;
    };
    // Adult femoral epicondylar width ~70-90 mm; tibial plateau ~70-85 mm (plus the fibula
    // head below it). Shafts: femur ~25-30 mm, tibia ~22-30 mm (plus the fibula).
    const double condyles = boneWidthX(20.0);
    EXPECT_GE(condyles, 65.0);
    EXPECT_LE(condyles, 95.0);
    const double plateau = boneWidthX(-10.0);
    EXPECT_GE(plateau, 65.0);
    EXPECT_LE(plateau, 90.0);
    const double femurShaft = boneWidthX(120.0);
    EXPECT_GE(femurShaft, 22.0);
    EXPECT_LE(femurShaft, 34.0);
    // At mid-shank the width spans tibia and fibula: about 55-70 mm apart in total.
    const double shank = boneWidthX(-120.0);
    EXPECT_GE(shank, 45.0);
    EXPECT_LE(shank, 75.0);
}

TEST(KneePhantom, BoneVolumeAndFractionArePlausible) {
    const fm::Volume& v = defaultKnee();
    std::size_t bone = 0;
    for (float x : v.values)
        if (x >= kBoneLevel) ++bone;
    const double voxelMm3 = v.spacing.x * v.spacing.y * v.spacing.z;
    const double boneCm3 = bone * voxelMm3 / 1000.0;
    // The 28 cm field holds the distal ~14 cm of the femur (epiphysis ~75 x 60 x 50 mm plus a
    // ~27 mm shaft), the proximal ~14 cm of tibia and fibula and the patella: a few hundred
    // cm^3 of bone. Below 250 cm^3 a bone is missing, above 650 cm^3 something is bloated.
    EXPECT_GE(boneCm3, 250.0);
    EXPECT_LE(boneCm3, 650.0);
    // The rest is mostly soft tissue and air: bone is a few percent of a knee CT's field.
    const double fraction = static_cast<double>(bone) / v.voxelCount();
    EXPECT_GE(fraction, 0.015);
    EXPECT_LE(fraction, 0.06);
}

TEST(KneePhantom, BoneSurfaceIsSubVoxelAccurate) {
    // The femoral shaft above 110 mm is an exact cylinder of kFemurShaftRadius. Thanks to the
    // partial-volume edges, the level halfway between muscle and cortex, interpolated between
    // voxels, finds that surface to a fraction of a voxel at every slice; a binary (staircase)
    // volume would miss it by up to half a voxel (0.86 mm) depending on the alignment.
    constexpr double kSubVoxelMm = 0.35;
    const fm::Volume& v = defaultKnee();
    const fm::KneeTissueHU hu;
    const double midLevel = 0.5 * (hu.muscle + hu.cortical);
    const glm::dvec3 u = glm::normalize(fm::kFemurShaftEnd - fm::kFemurShaftStart);
    for (double z = 112.0; z <= 130.0; z += 3.1) {
        const glm::dvec3 axis = axisAt(fm::kFemurShaftStart, fm::kFemurShaftEnd, z);
        for (const glm::dvec3 dir : {glm::dvec3(1, 0, 0), glm::dvec3(-1, 0, 0), glm::dvec3(0, 1, 0),
                                     glm::dvec3(0, -1, 0)}) {
            // March outwards in 0.05 mm steps until the value drops below the mid level.
            double r = fm::kFemurShaftRadius - 3.0;
            while (r < fm::kFemurShaftRadius + 3.0 && trilinear(v, axis + r * dir) > midLevel)
                r += 0.05;
            // Distance from the (slightly tilted) axis of the crossing point.
            const glm::dvec3 p = axis + r * dir - axis;
            const double radial = glm::length(p - glm::dot(p, u) * u);
            EXPECT_NEAR(radial, fm::kFemurShaftRadius, kSubVoxelMm) << "z " << z;
        }
    }
}

TEST(KneePhantom, DeterministicAndThreadIndependent) {
    fm::KneePhantomParams p;
    p.dims = {64, 64, 70};
    p.flexionDeg = 35.0;
    p.threads = 1;
    const fm::Volume a = fm::makeKneePhantom(p);
    p.threads = 2;
    const fm::Volume b = fm::makeKneePhantom(p);
    const fm::Volume c = fm::makeKneePhantom(p);
    EXPECT_EQ(a.values, b.values);
    EXPECT_EQ(b.values, c.values);
}

TEST(KneePhantom, FlexionMovesTibiaAndPatellaNotFemur) {
    fm::KneePhantomParams straight;
    fm::KneePhantomParams bent;
    bent.flexionDeg = 60.0;
    const fm::Volume& v0 = defaultKnee();
    const fm::Volume v60 = fm::makeKneePhantom(bent);

    // The tibial shaft leaves its straight-leg place ...
    const glm::dvec3 tibiaModel = axisAt(fm::kTibiaShaftStart, fm::kTibiaShaftEnd, -90.0);
    EXPECT_GE(nearest(v0, tibiaModel), kBoneLevel);
    EXPECT_LT(nearest(v60, tibiaModel), kBoneLevel);
    // ... for the rotated one: 60 deg about x through the flexion axis swings it posteriorly.
    const glm::dvec3 tibiaBent = fm::kneeModelToWorld(bent, fm::KneeSegment::Tibia, tibiaModel);
    const glm::dvec3 rel = tibiaModel - fm::kFlexionAxisPoint;
    const double c = std::cos(60.0 * std::numbers::pi / 180.0);
    const double s = std::sin(60.0 * std::numbers::pi / 180.0);
    constexpr double kMm = 1e-9;
    EXPECT_NEAR(tibiaBent.y, fm::kFlexionAxisPoint.y + rel.y * c - rel.z * s, kMm);
    EXPECT_NEAR(tibiaBent.z, fm::kFlexionAxisPoint.z + rel.y * s + rel.z * c, kMm);
    EXPECT_GT(tibiaBent.y, tibiaModel.y + 50.0);  // posterior: the foot goes back
    const float shaft = nearest(v60, tibiaBent);
    EXPECT_GE(shaft, kCancellousMin);
    EXPECT_LE(shaft, kCancellousMax);
    // The patella moves too and stays bone.
    const glm::dvec3 patellaBent =
        fm::kneeModelToWorld(bent, fm::KneeSegment::Patella, fm::kPatellaCenter);
    EXPECT_GT(glm::length(patellaBent - fm::kPatellaCenter), 10.0);
    EXPECT_GE(nearest(v60, patellaBent), kCancellousMin);
    EXPECT_EQ(fm::kneeModelToWorld(straight, fm::KneeSegment::Femur, {1, 2, 3}),
              glm::dvec3(1, 2, 3));

    // The thigh above the patella's reach is untouched, voxel for voxel.
    const int kFirstUnchanged = static_cast<int>(std::ceil(v0.worldToIndex({0, 0, 110.0}).z));
    for (int k = kFirstUnchanged; k < v0.dims.z; ++k)
        for (int j = 0; j < v0.dims.y; ++j)
            for (int i = 0; i < v0.dims.x; ++i)
                ASSERT_EQ(v0.at(i, j, k), v60.at(i, j, k)) << i << " " << j << " " << k;
}

TEST(KneePhantom, FlexedKneeKeepsTheJointSpace) {
    // Bending must not fuse tibia and femur: along the line from the flexion axis through the
    // rotated plateau centre, bone (femoral condyle) gives way to soft tissue before bone again.
    for (double flexion : {30.0, 90.0, 120.0}) {
        fm::KneePhantomParams p;
        p.flexionDeg = flexion;
        const fm::Volume v = fm::makeKneePhantom(p);
        // Through the middle of the medial condyle (x = 22 mm).
        const glm::dvec3 from = fm::kFlexionAxisPoint + glm::dvec3(22, 0, 0);
        const glm::dvec3 plateau = fm::kneeModelToWorld(
            p, fm::KneeSegment::Tibia, {22.0, fm::kFlexionAxisPoint.y, fm::kTibialPlateauTopZ});
        const glm::dvec3 dir = glm::normalize(plateau - from);
        bool sawGap = false, boneBefore = false;
        for (double t = 0.0; t < 40.0; t += 0.25) {
            const bool bone = trilinear(v, from + t * dir) >= kBoneLevel;
            if (bone && !sawGap) boneBefore = true;
            if (!bone && boneBefore) sawGap = true;
        }
        EXPECT_TRUE(boneBefore) << flexion;
        EXPECT_TRUE(sawGap) << flexion;
        EXPECT_GE(trilinear(v, plateau + 3.0 * dir), kBoneLevel)
            << flexion;  // 3 mm below the plateau surface: tibia
    }
}

TEST(KneePhantom, LeftKneeIsTheMirrorImage) {
    fm::KneePhantomParams right, left;
    right.dims = left.dims = {48, 40, 50};
    right.flexionDeg = left.flexionDeg = 20.0;
    left.leftKnee = true;
    const fm::Volume r = fm::makeKneePhantom(right);
    const fm::Volume l = fm::makeKneePhantom(left);
    // Voxel centres mirror exactly up to rounding of the positions (~1e-14 mm), which moves
    // values by far less than this.
    constexpr float kHu = 0.01f;
    for (int k = 0; k < r.dims.z; ++k)
        for (int j = 0; j < r.dims.y; ++j)
            for (int i = 0; i < r.dims.x; ++i)
                ASSERT_NEAR(r.at(i, j, k), l.at(r.dims.x - 1 - i, j, k), kHu);
}

TEST(KneePhantom, SizeAndFieldAreAdjustable) {
    fm::KneePhantomParams p;
    p.dims = {40, 50, 60};
    p.fieldMm = {200.0, 210.0, 240.0};
    const fm::Volume v = fm::makeKneePhantom(p);
    EXPECT_EQ(v.dims, glm::ivec3(40, 50, 60));
    EXPECT_NEAR(v.spacing.x, 5.0, 1e-12);
    EXPECT_NEAR(v.spacing.y, 4.2, 1e-12);
    EXPECT_NEAR(v.spacing.z, 4.0, 1e-12);
    EXPECT_NEAR(glm::length(v.center()), 0.0, 1e-9);
}

TEST(KneePhantom, RejectsAbsurdParameters) {
    auto with = [](auto change) {
        fm::KneePhantomParams p;
        change(p);
        return p;
    };
    EXPECT_THROW(fm::makeKneePhantom(with([](auto& p) { p.flexionDeg = 200; })), fm::Error);
    EXPECT_THROW(fm::makeKneePhantom(with([](auto& p) { p.flexionDeg = -30; })), fm::Error);
    EXPECT_THROW(fm::makeKneePhantom(with([](auto& p) { p.flexionDeg = std::nan(""); })),
                 fm::Error);
    EXPECT_THROW(fm::makeKneePhantom(with([](auto& p) { p.dims = {0, 10, 10}; })), fm::Error);
    EXPECT_THROW(fm::makeKneePhantom(with([](auto& p) { p.dims = {100000, 10, 10}; })), fm::Error);
    EXPECT_THROW(fm::makeKneePhantom(with([](auto& p) {
                     p.dims = {2048, 2048, 2048};
                 })),
                 fm::Error);
    EXPECT_THROW(fm::makeKneePhantom(with([](auto& p) { p.fieldMm.y = -5; })), fm::Error);
    EXPECT_THROW(fm::makeKneePhantom(with([](auto& p) { p.fieldMm.z = 1e9; })), fm::Error);
    EXPECT_THROW(fm::makeKneePhantom(with([](auto& p) { p.hu.fat = INFINITY; })), fm::Error);
}

}  // namespace
