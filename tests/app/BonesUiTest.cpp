// The Bones tab, driven like a user: the bone list (colours of the 3D view's surfaces, hiding a
// bone in both DRRs and the 3D view), the sliders moving one bone with the knee's joint angles
// live, and the flex game. Checked against the engine's articulated knee built here, apart from
// the app, and against what line integrals and the phantom's flexion must give.
#include <imgui.h>

#include <cmath>

#include "AppFixture.h"
#include "bones/BoneMotion.h"
#include "core/Error.h"
#include "bones/KneeMotionGame.h"
#include "phantom/ArticulatedKnee.h"
#include "render/SceneRenderer.h"
#include "scene/DrrCache.h"

namespace fm::test {
namespace {

using BonesUi = HeadlessApp;

// The articulated knee as the engine makes it (values as the app's DRRs).
Scene engineKnee(const app::App& app) {
    BoneSceneOptions options;
    options.values = app::appDrrValueOptions(*app.scene()->volume);
    return makeArticulatedKnee(KneePhantomParams{}, options);
}

Image engineView(const app::App& app, const Scene& scene, const Pose& camera) {
    XrayRenderSettings settings;
    settings.threads = kTestDrrThreads;
    return renderView(scene, app::appGeometry(*app.scene(), camera), settings);
}

double maxAbsDifference(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height) return INFINITY;
    double d = 0.0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i)
        d = std::max(d, double(std::abs(a.pixels[i] - b.pixels[i])));
    return d;
}

double peak(const Image& a) {
    double p = 0.0;
    for (float v : a.pixels) p = std::max(p, double(v));
    return p;
}

// Pixels of the 3D view (alone, no box or apparatus) whose blue clearly dominates: the tibia's
// surface colour (kBoneColors[1]); the femur's ivory and the patella's orange never are.
int bluePixels(const app::App& app) {
    const auto& r = app.sceneRenderer();
    const std::vector<std::uint8_t> px = r.readPixels();
    int n = 0;
    for (std::size_t i = 0; i < px.size(); i += 4)
        if (int(px[i + 2]) > int(px[i]) + 40 && int(px[i + 2]) > int(px[i + 1]) + 10) ++n;
    return n;
}

TEST_F(BonesUi, TheListNamesTheKneesBonesInTheColoursOfTheirSurfaces) {
    script->clickWidget("tab:bones");
    const auto& list = app->state().bones.list;
    ASSERT_EQ(list.size(), 3u);
    EXPECT_EQ(list[0].name, kKneeFemur);
    EXPECT_EQ(list[1].name, kKneeTibia);
    EXPECT_EQ(list[2].name, kKneePatella);
    EXPECT_TRUE(app->state().bones.isKnee);
    const auto surfaces = app->surfaces();
    ASSERT_EQ(surfaces.size(), 3u);
    const render::RgbaImage frame = app->capture();
    for (std::size_t i = 0; i < list.size(); ++i) {
        // The 3D view draws the bone in the colour of its swatch ...
        EXPECT_EQ(surfaces[i].color, glm::vec3(list[i].color[0], list[i].color[1], list[i].color[2]));
        EXPECT_EQ(surfaces[i].mesh, app->scene()->bones->bones[i].mesh.get());
        // ... and the swatch shows that colour (its centre pixel, as drawn).
        const glm::vec2 c = script->widget("swatch:" + list[i].name).center();
        const std::uint8_t* p = &frame.pixels[(std::size_t(c.y) * frame.width + std::size_t(c.x)) * 4];
        for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(p[ch], list[i].color[ch] * 255.0f, 2.0) << list[i].name;
    }
    // No two bones share a colour.
    EXPECT_NE(list[0].color, list[1].color);
    EXPECT_NE(list[1].color, list[2].color);
    EXPECT_NE(list[0].color, list[2].color);
}

TEST_F(BonesUi, HidingABoneRemovesItFromBothDrrsAndThe3dView) {
    script->clickWidget("tab:bones");
    app->state().view.showBox = false;
    app->state().view.showApparatus = false;  // the 3D view shows the bones alone
    script->idle(1);
    const Image whole = app->userDrr();
    const int tibiaPixels = bluePixels(*app);
    EXPECT_GT(tibiaPixels, 200) << "the tibia is drawn in its colour";

    script->clickWidget("checkbox:bone-femur");
    script->idle(1);
    EXPECT_FALSE(app->state().bones.list[0].visible);
    // Your DRR and the reference: the engine's knee without the femur, each in its camera.
    Scene knee = engineKnee(*app);
    knee.object(kKneeFemur).visible = false;
    const Image noFemur = engineView(*app, knee, app->state().userPose);
    ASSERT_EQ(app->userDrr().width, noFemur.width);
    EXPECT_EQ(app->userDrr().pixels, noFemur.pixels);
    EXPECT_EQ(app->referenceDrr().pixels, engineView(*app, knee, app->state().referencePose).pixels);
    // Line integrals add: the femur alone plus the rest is the whole CT's DRR (float rounding).
    Scene femurOnly = engineKnee(*app);
    for (auto& o : femurOnly.objects) o.visible = o.name == kKneeFemur;
    const Image femur = engineView(*app, femurOnly, app->state().userPose);
    Image sum = noFemur;
    for (std::size_t i = 0; i < sum.pixels.size(); ++i) sum.pixels[i] += femur.pixels[i];
    EXPECT_LT(maxAbsDifference(sum, whole), 1e-5 * peak(whole));

    // The tibia hidden too: gone from the 3D view.
    script->clickWidget("checkbox:bone-tibia");
    script->idle(1);
    EXPECT_EQ(bluePixels(*app), 0);
    // "only" and "all".
    script->clickWidget("button:only-patella");
    script->idle(1);
    EXPECT_FALSE(app->state().bones.restVisible);
    Scene patella = engineKnee(*app);
    for (auto& o : patella.objects) o.visible = o.name == kKneePatella;
    EXPECT_EQ(app->userDrr().pixels, engineView(*app, patella, app->state().userPose).pixels);
    script->clickWidget("button:show-all");
    script->idle(1);
    EXPECT_EQ(app->userDrr().pixels, whole.pixels) << "all shown: the CT's own DRR again";
    EXPECT_EQ(bluePixels(*app), tibiaPixels);
}

TEST_F(BonesUi, TheSlidersMoveTheChosenBoneAndTheJointAnglesFollowLive) {
    script->clickWidget("tab:bones");
    script->clickWidget("radio:moves-tibia");
    ASSERT_EQ(app->state().bones.sliderTarget, 1);
    script->idle(1);
    // The parameter pane now moves the tibia: shifts and turns about the LPS axes.
    const app::WidgetRect slider = script->widget("slider:turn-x");
    EXPECT_NO_THROW(script->widget("text:knee-angles"));
    const Pose camera = app->state().userPose;

    // Drag the turn about x: the knee's flexion follows the slider in every frame of the drag.
    const glm::vec2 from = slider.center();
    const glm::vec2 to(slider.min.x + 0.6f * (slider.max.x - slider.min.x), from.y);
    script->moveTo(from);
    app::FrameInput press;
    press.mousePos = from;
    press.mouseDown[0] = true;
    backend->setFrameInput(press);
    app->frame();
    int frames = 0;
    for (int step = 1; step <= 6; ++step) {
        press.mousePos = from + (to - from) * (step / 6.0f);
        backend->setFrameInput(press);
        app->frame();
        const auto& b = app->state().bones;
        ASSERT_TRUE(b.anglesValid);
        // About the flexion axis, a turn about x is the phantom's flexion: Grood-Suntay gives
        // that angle as flexion, no varus, no rotation (femur unmoved).
        EXPECT_NEAR(b.angles[3], b.list[1].motion[3], 1e-9);
        EXPECT_NEAR(b.angles[4], 0.0, 1e-9);
        EXPECT_NEAR(b.angles[5], 0.0, 1e-9);
        frames += b.list[1].motion[3] != 0.0;
    }
    press.mouseDown[0] = false;
    backend->setFrameInput(press);
    app->frame();
    EXPECT_GE(frames, 5) << "the angle changed while dragging";
    EXPECT_EQ(app->state().userPose.toArray(), camera.toArray()) << "the camera did not move";

    // Typed: 25 deg. The user DRR is the knee flexed to 25 deg as the phantom generator flexes
    // it (kneeBonePoses), traced by the engine.
    script->clickWidget("input:turn-x");
    script->type("25");
    script->pressKey(ImGuiKey_Enter);
    script->idle(1);
    EXPECT_DOUBLE_EQ(app->state().bones.list[1].motion[3], 25.0);
    EXPECT_NEAR(app->state().bones.angles[3], 25.0, 1e-9);
    Scene knee = engineKnee(*app);
    knee.object(kKneeTibia).worldFromObject = kneeBonePoses(KneePhantomParams{}, 25.0).tibia;
    const Image flexed = engineView(*app, knee, camera);
    ASSERT_EQ(app->userDrr().width, flexed.width);
    EXPECT_LT(maxAbsDifference(app->userDrr(), flexed), 1e-6 * peak(flexed));
    // The 3D view draws the tibia at that pose.
    EXPECT_EQ(app->surfaces()[1].worldFromObject[3][1],
              kneeBonePoses(KneePhantomParams{}, 25.0).tibia.translation.y);

    // Back to the camera: the sliders are the 2011 parameters again.
    script->clickWidget("radio:moves-camera");
    script->idle(1);
    EXPECT_NO_THROW(script->widget("slider:azimuth"));
    EXPECT_THROW(script->widget("slider:turn-x"), Error);
}

// In a 960 x 600 window the game's hints fit their pane without scrolling: the bone list folds
// while a game runs (unfolded on request) and the hints take two numbers a row.
TEST_F(BonesUi, TheFlexGamesHintsFitASmallWindow) {
    script->clickWidget("tab:bones");
    script->clickWidget("button:new-flex");
    ASSERT_TRUE(app->state().bones.flex.active);
    EXPECT_FALSE(app->state().bones.listUnfolded);
    script->idle(1);
    script->clickWidget("button:check-flex");
    script->idle(1);
    ASSERT_TRUE(app->state().bones.flex.outcome.has_value());
    const float bottom = float(backend->framebufferSize().y);
    EXPECT_LE(script->widget("table:flex-hints").max.y, bottom) << "the hints run below the window";
    // After Reveal too: the signed errors in one line each.
    script->clickWidget("checkbox:reveal-flex");
    script->idle(1);
    ASSERT_TRUE(app->state().bones.flex.outcome->numbersShown);
    EXPECT_LE(script->widget("table:flex-hints").max.y, bottom) << "the revealed hints run below the window";
    EXPECT_THROW(script->widget("radio:moves-tibia"), Error) << "the bone list is folded";
    script->clickWidget("header:bone-list");
    script->idle(1);
    EXPECT_TRUE(app->state().bones.listUnfolded);
    EXPECT_NO_THROW(script->widget("radio:moves-tibia"));
}

TEST_F(BonesUi, TheFlexGameHidesAFlexionThatTheTibiaMustFind) {
    start(testAppOptions(), {1280, 800});  // room for the game's hints under the bone list
    script->clickWidget("tab:bones");
    script->clickWidget("button:new-flex");  // easy: a flexion only
    const app::FlexGame& flex = app->state().bones.flex;
    ASSERT_TRUE(flex.active);
    EXPECT_EQ(app->state().bones.sliderTarget, 1) << "the sliders move the tibia";
    const double hidden = flex.hiddenMotion[3];
    EXPECT_GE(hidden, 10.0);
    EXPECT_LE(hidden, 60.0);
    for (int k : {0, 1, 2, 4, 5}) EXPECT_EQ(flex.hiddenMotion[k], 0.0);
    script->idle(1);
    // The reference: the knee flexed by the hidden angle as the generator flexes it, seen from
    // the user's camera.
    Scene knee = engineKnee(*app);
    knee.object(kKneeTibia).worldFromObject = kneeBonePoses(KneePhantomParams{}, hidden).tibia;
    const Image reference = engineView(*app, knee, app->state().userPose);
    EXPECT_LT(maxAbsDifference(app->referenceDrr(), reference), 1e-6 * peak(reference));
    EXPECT_NEAR(flex.referenceAngles[3], hidden, 1e-9);

    // Check at the straight knee: flexion too low, no number before a match or Reveal.
    script->clickWidget("button:check-flex");
    ASSERT_TRUE(flex.outcome.has_value());
    EXPECT_FALSE(flex.outcome->matched);
    EXPECT_EQ(flex.outcome->hintCells[3], "too low");
    EXPECT_EQ(flex.outcome->furthestParameter, 3);
    EXPECT_NE(flex.outcome->verdict.find("flexion too low"), std::string::npos)
        << flex.outcome->verdict;
    EXPECT_EQ(flex.outcome->verdict.find_first_of("0123456789"), std::string::npos);

    // Reveal: the signed error, from the engine's joint angles.
    script->clickWidget("checkbox:reveal-flex");
    char expected[48];
    std::snprintf(expected, sizeof(expected), "too low (%+.1f deg)", -hidden);
    EXPECT_EQ(flex.outcome->hintCells[3], expected);
    script->clickWidget("checkbox:reveal-flex");

    // Within a degree of the hidden flexion: a match.
    script->clickWidget("input:turn-x");
    char typed[16];
    std::snprintf(typed, sizeof(typed), "%.1f", hidden + 0.8);
    script->type(typed);
    script->pressKey(ImGuiKey_Enter);
    script->clickWidget("button:check-flex");
    EXPECT_TRUE(flex.outcome->matched) << flex.outcome->verdict;
    EXPECT_EQ(flex.attempts, 2);
    EXPECT_EQ(flex.outcome->hintCells[3], "ok (+0.8 deg)");
    EXPECT_EQ(app->userDrr().width, app->referenceDrr().width);

    script->clickWidget("button:end-flex");
    EXPECT_FALSE(app->state().bones.flex.active);
}

}  // namespace
}  // namespace fm::test

namespace fm::test {
namespace {

TEST_F(BonesUi, AClickOnYourDrrGrowsABoneFromTheVoxelItHits) {
    app->state().requests.loadVolume = std::string("phantom:sphere,radius=20");
    app->waitForLoad();
    script->idle(1);
    ASSERT_EQ(app->scene()->bones, nullptr);
    script->clickWidget("tab:bones");
    script->clickWidget("checkbox:grow");
    ASSERT_TRUE(app->state().bones.growArmed);
    const Image whole = app->userDrr();
    // The centre of your DRR: its ray runs through the sphere's centre.
    script->click(script->widget("image:user").center());
    script->idle(1);
    ASSERT_NE(app->scene()->bones, nullptr) << app->state().bones.growMessage;
    ASSERT_EQ(app->state().bones.list.size(), 1u);
    EXPECT_EQ(app->state().bones.list[0].name, "region 1");
    EXPECT_FALSE(app->state().bones.growArmed) << "one click, one bone";
    // The region is every voxel at or above the surface level (the sphere is one piece).
    const Volume& ct = *app->scene()->volume;
    const double level = app->state().bone.shownLevel;
    std::size_t expected = 0, labelled = 0;
    for (float v : ct.values) expected += v >= level;
    for (float v : app->scene()->bones->labels->values) labelled += v == 1.0f;
    EXPECT_EQ(labelled, expected);
    EXPECT_GT(labelled, 1000u);
    // All shown: the same DRR; the region hidden, the rest alone; both add up to the whole.
    EXPECT_EQ(app->userDrr().pixels, whole.pixels);
    script->clickWidget("checkbox:bone-region 1");
    script->idle(1);
    const Image rest = app->userDrr();
    app->state().bones.list[0].visible = true;
    app->state().bones.restVisible = false;
    script->idle(1);
    const Image region = app->userDrr();
    Image sum = rest;
    for (std::size_t i = 0; i < sum.pixels.size(); ++i) sum.pixels[i] += region.pixels[i];
    EXPECT_LT(maxAbsDifference(sum, whole), 1e-5 * peak(whole));
    EXPECT_GT(peak(region), 0.5 * peak(whole)) << "the region is the dense part";
    // The same pixel again: its ray meets only the bone already grown, which it never takes.
    app->state().bones.restVisible = true;
    script->clickWidget("checkbox:grow");
    script->click(script->widget("image:user").center());
    script->idle(1);
    EXPECT_EQ(app->state().bones.list.size(), 1u);
    EXPECT_NE(app->state().bones.growMessage.find("no new bone"), std::string::npos)
        << app->state().bones.growMessage;
}

}  // namespace
}  // namespace fm::test

namespace fm::test {
namespace {

TEST_F(BonesUi, InTheFlexGameSolveRegistersTheTibiaAloneAndFindsTheFlexion) {
    start(testAppOptions(), {1280, 800});
    app->state().userPose = parsePose("0,0,0,90,0,0");  // lateral: the flexion is in the film
    script->clickWidget("tab:bones");
    script->clickWidget("button:new-flex");
    const double hidden = app->state().bones.flex.hiddenMotion[3];
    // From 6 deg short of it (the search's radius is 10 deg: a start the user got near).
    const double start = std::round(hidden - 6.0);
    app->state().bones.list[1].motion[3] = start;
    script->idle(1);
    script->clickWidget("tab:solve");
    script->clickWidget("button:solve");
    ASSERT_TRUE(app->state().solve.running) << app->state().solve.error;
    EXPECT_EQ(app->state().solve.bone, 1);
    for (int frames = 0; app->state().solve.running && frames < 20000; ++frames) {
        app->frame();
        EXPECT_EQ(app->state().bones.list[1].motion[3], start) << "the solve moves no slider";
    }
    const app::SolveStatus& solve = app->state().solve;
    ASSERT_TRUE(solve.finished) << solve.error;
    // The tibia's motion found: the hidden flexion about the flexion axis, nothing else much.
    EXPECT_NEAR(solve.boneMotion[3], hidden, 1.0);
    EXPECT_TRUE(solve.matched) << "turn x " << solve.boneMotion[3] << " vs " << hidden;
    // Judged on the knee's angles: error6 is flexion etc. of the found minus the hidden.
    EXPECT_NEAR(solve.error6[3], solve.boneMotion[3] - hidden, 0.5);
    script->idle(1);
    script->clickWidget("button:apply-solution");
    EXPECT_EQ(app->state().bones.list[1].motion, solve.boneMotion);
    script->clickWidget("tab:bones");
    script->clickWidget("button:check-flex");
    ASSERT_TRUE(app->state().bones.flex.outcome.has_value());
    EXPECT_TRUE(app->state().bones.flex.outcome->matched)
        << app->state().bones.flex.outcome->verdict;
}

}  // namespace
}  // namespace fm::test

namespace fm::test {
namespace {

// Mean distance of a bone's target points between two of its motions (the truth, apart from
// the app: boneMotionTransform of engine/bones about the bone's pivot).
double motionMtre(const app::SceneBone& bone, const BoneMotion& a, const BoneMotion& b) {
    const RigidTransform pa = boneMotionTransform(a, bone.pivot);
    const RigidTransform pb = boneMotionTransform(b, bone.pivot);
    double sum = 0.0;
    for (const glm::dvec3& p : bone.targets)
        sum += glm::length(pa.applyToPoint(p) - pb.applyToPoint(p));
    return sum / double(bone.targets.size());
}

TEST_F(BonesUi, SolveRegistersTheChosenBoneAloneWhileTheOthersStay) {
    start(testAppOptions(), {1280, 800});
    app->state().userPose = parsePose("0,0,0,90,0,0");
    script->clickWidget("tab:bones");
    script->clickWidget("button:new-flex");  // the reference flexes the knee; femur unmoved
    const BoneMotion flexion = app->state().bones.flex.hiddenMotion;
    // The user has the femur 4 mm and 4 deg off where the CT (and the reference) has it, and
    // the tibia at the hidden flexion.
    app->state().bones.list[1].motion = flexion;
    const BoneMotion start{3.0, -2.0, 2.0, 4.0, 0.0, -3.0};
    app->state().bones.list[0].motion = start;
    // Patella and soft tissue hidden (in both images and in the solve): femur and tibia.
    app->state().bones.list[2].visible = false;
    app->state().bones.restVisible = false;
    script->clickWidget("tab:solve");
    // The Solve tab chooses the bone (the sliders' target too); biplane: two views.
    app->state().bones.sliderTarget = 0;
    script->clickWidget("checkbox:solve-biplane");
    ASSERT_TRUE(app->state().bones.biplaneSolve);
    script->clickWidget("button:solve");
    ASSERT_TRUE(app->state().solve.running) << app->state().solve.error;
    EXPECT_EQ(app->state().solve.bone, 0);
    for (int frames = 0; app->state().solve.running && frames < 20000; ++frames) {
        app->frame();
        ASSERT_EQ(app->state().bones.list[0].motion, start) << "the solve moves no slider";
        ASSERT_EQ(app->state().bones.list[1].motion, flexion) << "the tibia stays";
    }
    const app::SolveStatus& solve = app->state().solve;
    ASSERT_TRUE(solve.finished) << solve.error;
    // The femur's truth is where the CT has it: its motion found is about zero.
    const app::SceneBone& femur = app->scene()->bones->bones[0];
    const double mtre = motionMtre(femur, solve.boneMotion, BoneMotion{});
    EXPECT_LT(mtre, 1.0) << "start " << motionMtre(femur, start, BoneMotion{}) << " mm";
    EXPECT_GT(motionMtre(femur, start, BoneMotion{}), 4.0);
    std::printf("femur solved alone (biplane): mTRE %.2f -> %.3f mm, %d evaluations\n",
                motionMtre(femur, start, BoneMotion{}), mtre, solve.evaluations);
    // Judged on its motion numbers (not the knee's angles), as the app says it.
    EXPECT_TRUE(solve.matched);
    EXPECT_NEAR(solve.poseErrorMm, mtre, 1e-9);
    for (int k = 0; k < 6; ++k) EXPECT_NEAR(solve.error6[k], solve.boneMotion[k], 1e-9) << k;
    script->idle(1);
    script->clickWidget("button:apply-solution");
    EXPECT_EQ(app->state().bones.list[0].motion, solve.boneMotion);
    EXPECT_EQ(app->state().bones.list[1].motion, flexion);
}

TEST_F(BonesUi, SolveForABoneNeedsABoneGamesReference) {
    script->clickWidget("tab:bones");
    script->clickWidget("radio:moves-femur");
    script->clickWidget("tab:solve");
    script->clickWidget("button:solve");
    EXPECT_FALSE(app->state().solve.running);
    EXPECT_NE(app->state().solve.error.find("flex game"), std::string::npos)
        << app->state().solve.error;
    EXPECT_EQ(app->state().bones.list[0].motion, BoneMotion{});
    // The camera again: the camera game's solve.
    app->state().bones.sliderTarget = -1;
    script->clickWidget("button:solve");
    EXPECT_TRUE(app->state().solve.running);
    EXPECT_EQ(app->state().solve.bone, -1);
}

}  // namespace
}  // namespace fm::test
