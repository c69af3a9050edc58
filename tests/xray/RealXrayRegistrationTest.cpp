// Registration against the real JTML knee fluoroscopy (docs/real-xray.md, "Proof on the real
// frames"): for the three frames and both implants, from the .jts pose perturbed by up to
// 5 mm in-plane, 20 mm in depth and 5 deg about each camera axis, the registration (`register`'s:
// two searches from independent starts, more while they disagree) ends within 1 mm in-plane and
// 2 deg of the .jts pose in at least 99 % of the starts, every miss has a verdict other than ok
// (decided without the mask), and its silhouette matches the label mask.
//
// Ten seeded starts per frame and implant (60 registrations) in the Release suite; one under
// the sanitizers (6: they run ~5x slower). FM_REAL_XRAY_STARTS=N overrides.
// The label masks reproduce the .jts silhouettes exactly, so the IoU of the .jts pose is 1.0
// and cannot be reached by any other pose: the bound is kMinIoU, below what was measured.
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>

#include <gtest/gtest.h>

#include "camera/CameraFile.h"
#include "common/TestData.h"
#include "core/Random.h"
#include "meshdrr/MeshDrr.h"
#include "model/MeshModel.h"
#include "radiograph/Radiograph.h"
#include "radiograph/RadiographPreparation.h"
#include "scene/MeshXrayModel.h"
#include "scene/ObjectPoseParameterization.h"
#include "search/PoseUncertainty.h"
#include "search/Registration.h"
#include "xray/AnswerCheck.h"
#include "xray/CameraPoseDifference.h"
#include "xray/ConfirmedRegistration.h"
#include "xray/ObjectRegistration.h"
#include "xray/PoseSpec.h"

namespace fm {
namespace {

constexpr double kMaxInPlaneMm = 1.0;
constexpr double kMaxRotationDeg = 2.0;
constexpr double kMinIoU = 0.95;
constexpr double kMinMetShare = 0.99;

const char* kFrames[3] = {"0160", "0170", "0180"};

struct Implant {
    const char* name;  // "fem", "tib"
    const char* stl;
};
const Implant kImplants[2] = {{"fem", "KR_right_7_fem.stl"}, {"tib", "KR_right_6_tib.stl"}};

std::filesystem::path dataDir() { return test::sharedDataDir() / "jtml-kneel-tka-fluoro"; }

Mask readLabel(int frame, const Implant& implant) {
    const auto path = dataDir() / "Labels" / implant.name /
                      (std::string("AT_K1_V1_") + kFrames[frame] + "_label_" + implant.name + ".tif");
    const RadiographFile f = readRadiograph(path);
    Mask m(f.image.width, f.image.height, false);
    for (std::size_t i = 0; i < m.inside.size(); ++i) m.inside[i] = f.image.pixels[i] > 127.5f;
    return m;
}

struct Frame {
    ProjectionGeometry camera;
    PreparedRadiograph radiograph;
};

Frame loadFrame(int frame) {
    const RadiographFile f =
        readRadiograph(dataDir() / (std::string("AT_K1_V1_") + kFrames[frame] + ".tif"));
    const CameraReadResult cam = readCameraFile(dataDir() / "calibration.txt",
                                                glm::ivec2(f.image.width, f.image.height));
    RadiographPreparation prep;
    prep.invert = true;  // metal is dark in the raw frames
    return {toProjectionGeometry(cam.camera), prepareRadiograph(f.image, prep)};
}

std::shared_ptr<const XrayModel> loadImplant(const Implant& implant) {
    static std::map<std::string, std::shared_ptr<const XrayModel>> cache;
    auto& m = cache[implant.name];
    if (!m)
        m = std::make_shared<MeshXrayModel>(prepareMeshDrr(loadMeshModel(dataDir() / implant.stl)),
                                            kMuCobaltChromePerMm, implant.name);
    return m;
}

// The truth perturbed in the camera's frame: in-plane within a 5 mm disc, depth within
// +-20 mm, each rotation within +-5 deg; all times FM_REAL_XRAY_SPREAD (default 1: the issue's
// range; docs/real-xray.md measures the verdict on wider starts, where searches miss).
double spread() {
    const char* env = std::getenv("FM_REAL_XRAY_SPREAD");
    return env ? std::clamp(std::atof(env), 0.1, 10.0) : 1.0;
}

RigidTransform perturbed(const ObjectPoseParameterization& p, Rng& rng) {
    SceneParams q = p.referenceParams();
    const double k = spread();
    const double r = k * 5.0 * std::sqrt(rng.uniform()), a = 2.0 * M_PI * rng.uniform();
    q[0] += r * std::cos(a);
    q[1] += r * std::sin(a);
    q[2] += k * rng.uniform(-20.0, 20.0);
    for (int i = 3; i < 6; ++i) q[i] += k * rng.uniform(-5.0, 5.0);
    return p.worldFromObject(q);
}

int startsPerCase() {
    const char* env = std::getenv("FM_REAL_XRAY_STARTS");
    const int n = env ? std::atoi(env) : 10;  // Release only (tests/xray/extra.cmake)
    return std::clamp(n, 1, 100);
}

TEST(RealXray, LabelMasksAreTheJtsSilhouettes) {
    FM_REQUIRE_SHARED_DATA("jtml-kneel-tka-fluoro/fem.jts");
    for (int f = 0; f < 3; ++f) {
        const Frame frame = loadFrame(f);
        for (const Implant& implant : kImplants) {
            const RigidTransform truth = readPoseSpec((dataDir() / (std::string(implant.name) + ".jts")).string(), f);
            const double iou = silhouetteIoU(
                objectSilhouette({implant.name, loadImplant(implant), truth, true}, frame.camera),
                readLabel(f, implant));
            EXPECT_GT(iou, 0.999) << kFrames[f] << " " << implant.name;
            for (const char* alt : {"_fft.jts", "_fft_perfect.jts"}) {
                const RigidTransform other = readPoseSpec(
                    (dataDir() / "FFT" / (std::string(implant.name) + alt)).string(), f);
                const CameraPoseDifference d = cameraPoseDifference(
                    frame.camera, truth, other, defaultPivot(*loadImplant(implant)));
                const double altIou = silhouetteIoU(
                    objectSilhouette({implant.name, loadImplant(implant), other, true}, frame.camera),
                    readLabel(f, implant));
                std::printf("%s %s %-17s in-plane %6.3f mm  depth %+8.3f mm  rotation %6.3f deg  "
                            "IoU %.4f\n",
                            kFrames[f], implant.name, alt + 1, d.inPlaneMm, d.depthMm,
                            d.rotationDeg, altIou);
            }
        }
    }
}

// A registration prepared once (its pyramids, edges and distance maps) and searched from other
// starts, and measured at another answer, gives what one constructed for each gives, bit for
// bit: what registerObjects and the finder rely on to prepare a view once per object. The
// fresh ones are written out here as a registration of one object is: its pose in the camera's
// frame from the start (pivot at its bounds' centre, depth along the pivot's ray), the
// uncertainty's with the finest level alone. A short budget (every stage still runs), frame
// 0160, the tray: prepared at the .jts pose, searched from two perturbed starts.
TEST(RealXray, OnePreparedRegistrationServesEverySearchAndTheUncertainty) {
    FM_REQUIRE_SHARED_DATA("jtml-kneel-tka-fluoro/tib.jts");
    RegistrationSettings settings = realXraySettings();
    settings.globalEvaluations = 60;
    settings.polishEvaluations = 12;
    settings.hypothesisEvaluations = 8;
    settings.depthRounds = 1;
    settings.threads = 2;
    const Frame frame = loadFrame(0);
    const RegistrationView view{0, frame.radiograph.image, frame.radiograph.valid};
    const auto model = loadImplant(kImplants[1]);
    const RigidTransform truth = readPoseSpec((dataDir() / "tib.jts").string(), 0);
    Scene scene;
    scene.cameras = {frame.camera};
    scene.objects.push_back({"tib", model, truth, true});
    const Registration prepared = prepareObjectRegistration(scene, 0, view, settings);
    const ObjectPoseParameterization atTruth("tib", frame.camera, truth, defaultPivot(*model));
    Rng rng(77);
    for (int k = 0; k < 2; ++k) {
        const RigidTransform start = perturbed(atTruth, rng);
        RegistrationSettings own = settings;
        own.seed = 5 + k;
        own.threads = k + 1;
        const auto freshAt = [&](const RigidTransform& pose, const RegistrationSettings& with) {
            Scene at = scene;
            at.objects[0].worldFromObject = pose;
            auto p = std::make_shared<ObjectPoseParameterization>("tib", frame.camera, pose, defaultPivot(*model),
                                                                  DepthSearch::AlongRay);
            return std::make_pair(Registration(at, p, {view}, with), p);
        };
        const auto [search, searchParams] = freshAt(start, own);
        const RegistrationResult r = search.run(searchParams->referenceParams());
        const RigidTransform fresh = searchParams->worldFromObject(r.params);
        const ObjectRegistrationResult shared = registerObject(prepared, scene, 0, view, start, own.seed, own.threads);
        EXPECT_EQ(shared.worldFromObject.rotation, fresh.rotation) << k;
        EXPECT_EQ(shared.worldFromObject.translation, fresh.translation) << k;
        EXPECT_EQ(shared.similarity, r.similarity) << k;
        EXPECT_EQ(shared.evaluations, r.evaluations) << k;
        EXPECT_GT(cameraPoseDifference(frame.camera, start, shared.worldFromObject, defaultPivot(*model)).inPlaneMm, 0.01)
            << "the search did not move: nothing compared";
        RegistrationSettings finest = own;
        finest.levelFactors = {1};
        const auto [measure, measureParams] = freshAt(fresh, finest);
        const PoseUncertainty a = poseUncertainty(measure, measureParams->referenceParams());
        const PoseUncertainty b = objectPoseUncertainty(prepared, scene, 0, view, fresh, own.threads);
        EXPECT_EQ(a.hessian, b.hessian) << k;
        EXPECT_EQ(a.sd, b.sd) << k;
        EXPECT_EQ(a.evaluations, b.evaluations) << k;
    }
}

TEST(RealXray, RegistrationFromPerturbedStartsReachesTheJtsPose) {
    FM_REQUIRE_SHARED_DATA("jtml-kneel-tka-fluoro/fem.jts");
    const int starts = startsPerCase();
    // FM_REAL_XRAY_SIMILARITY=gncc (or gd, ncc) compares another measure (docs/real-xray.md);
    // the bounds below are for the default, edge.
    const char* measure = std::getenv("FM_REAL_XRAY_SIMILARITY");
    RegistrationSettings settings =
        realXraySettings(measure ? parseSimilarityMeasure(measure) : SimilarityMeasure::EdgeDistance);
    settings.threads = 2;
    int total = 0, met_ = 0, misses = 0, falseAlarms = 0;
    for (int f = 0; f < 3; ++f) {
        const Frame frame = loadFrame(f);
        const RegistrationView view{0, frame.radiograph.image, frame.radiograph.valid};
        for (const Implant& implant : kImplants) {
            const auto model = loadImplant(implant);
            const RigidTransform truth =
                readPoseSpec((dataDir() / (std::string(implant.name) + ".jts")).string(), f);
            const Mask label = readLabel(f, implant);
            const ObjectPoseParameterization atTruth(implant.name, frame.camera, truth,
                                                     defaultPivot(*model));
            Scene scene;
            scene.cameras = {frame.camera};
            scene.objects.push_back({implant.name, model, truth, true});
            Rng rng(1000 + 10 * f + (implant.name[0] == 't'));
            for (int s = 0; s < starts; ++s) {
                const RigidTransform start = perturbed(atTruth, rng);
                scene.objects[0].worldFromObject = start;
                const ConfirmedObject c = registerObjects(scene, view, settings).objects.at(0);
                const ObjectRegistrationResult& r = c.answer;
                const AnswerCheck check = checkAnswer(scene.objects[0], r.worldFromObject, {view}, scene.cameras,
                                                      c.evidence, settings.threads);
                const CameraPoseDifference before =
                    cameraPoseDifference(frame.camera, truth, start, defaultPivot(*model));
                const CameraPoseDifference d =
                    cameraPoseDifference(frame.camera, truth, r.worldFromObject, defaultPivot(*model));
                const double iou = silhouetteIoU(
                    objectSilhouette({implant.name, model, r.worldFromObject, true}, frame.camera),
                    label);
                const bool met = d.inPlaneMm < kMaxInPlaneMm && d.rotationDeg < kMaxRotationDeg;
                ++total;
                met_ += met ? 1 : 0;
                if (!met) {
                    ++misses;
                    EXPECT_NE(check.verdict, AnswerVerdict::Ok)
                        << kFrames[f] << " " << implant.name << " start " << s << " missed, yet " << check.text;
                } else if (check.verdict != AnswerVerdict::Ok) {
                    ++falseAlarms;
                }
                const PoseUncertainty& u = *c.evidence.uncertainty;
                std::printf("%s %s start %d: from in-plane %.2f depth %+6.2f rot %.2f -> in-plane "
                            "%.3f mm, depth %+7.3f mm, rotation %.3f deg (view %+.3f, out %.3f), "
                            "IoU %.4f, similarity %.4f, %d runs %d agree, %s, sd depth %.2f mm, sd rot %.2f %.2f %.2f deg, "
                            "%d evals, %.2f s\n",
                            kFrames[f], implant.name, s, before.inPlaneMm, before.depthMm,
                            before.rotationDeg, d.inPlaneMm, d.depthMm, d.rotationDeg,
                            d.inPlaneRotationDeg, d.outOfPlaneRotationDeg, iou, r.similarity, c.evidence.runs,
                            c.evidence.agreeing, toString(check.verdict), u.sd[2], u.sd[3], u.sd[4], u.sd[5],
                            r.evaluations, r.seconds);
                std::fflush(stdout);
                if (spread() <= 1.0) {
                    EXPECT_GE(iou, kMinIoU) << kFrames[f] << " " << implant.name << " start " << s;
                }
            }
        }
    }
    std::printf("met %d of %d; misses %d (each not ok), met but not ok %d\n", met_, total, misses, falseAlarms);
    if (spread() <= 1.0) {
        EXPECT_GE(met_, kMinMetShare * total) << met_ << " of " << total << " met";
    }
}

}  // namespace
}  // namespace fm
