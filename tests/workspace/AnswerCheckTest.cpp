// A registration's verdict (xray/AnswerCheck.h) on the JTML frame 0160 and its femoral
// implant: each piece of evidence classes it at both sides of its thresholds, the worst wins,
// ok needs one piece that confirms, and a pose at which the model covers no valid pixel is lost
// whatever the rest says.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "WorkspaceTestData.h"
#include "xray/AnswerCheck.h"

namespace fm::test {
namespace {

using V = AnswerVerdict;

struct Jtml {
    std::shared_ptr<app::WorkspaceModel> model = app::WorkspaceModel::open(jtmlRadiographSource(), 2);
    const SceneObject& femur() const { return model->scene().objects.at(0); }
    RigidTransform start() const { return *model->initialPoses().at(0).at(0); }
    AnswerCheck check(const RigidTransform& pose, const AnswerEvidence& e) const {
        return checkAnswer(femur(), pose, model->prepared(0), model->scene().cameras, e, 2);
    }
};

AnswerEvidence withIoU(double iou) {
    AnswerEvidence e;
    e.iou = iou;
    return e;
}

AnswerEvidence withRuns(int runs, int agreeing) {
    AnswerEvidence e;
    e.runs = runs;
    e.agreeing = agreeing;
    return e;
}

TEST(AnswerCheck, TheMaskClassesOkDoubtfulLost) {
    FM_REQUIRE_SHARED_DATA("jtml-kneel-tka-fluoro");
    const Jtml j;
    EXPECT_EQ(j.check(j.start(), withIoU(kConfirmedIoU)).verdict, V::Ok);
    EXPECT_EQ(j.check(j.start(), withIoU(0.95)).text, "ok: silhouette IoU 0.950 against the mask (at least 0.90)");
    EXPECT_EQ(j.check(j.start(), withIoU(std::nextafter(kConfirmedIoU, 0.0))).verdict, V::Doubtful);
    EXPECT_EQ(j.check(j.start(), withIoU(kLostIoU)).verdict, V::Doubtful);
    EXPECT_EQ(j.check(j.start(), withIoU(std::nextafter(kLostIoU, 0.0))).verdict, V::Lost);
    EXPECT_EQ(j.check(j.start(), withIoU(0.3)).text, "lost: silhouette IoU 0.300 against the mask (below 0.50)");
}

TEST(AnswerCheck, SearchesFromIndependentStartsConfirmWhenTwoAgree) {
    FM_REQUIRE_SHARED_DATA("jtml-kneel-tka-fluoro");
    const Jtml j;
    EXPECT_EQ(j.check(j.start(), withRuns(2, 2)).text, "ok: 2 of 2 searches from different starts end here");
    const AnswerCheck alone = j.check(j.start(), withRuns(4, 1));
    EXPECT_EQ(alone.verdict, V::Doubtful);
    EXPECT_NE(alone.text.find("no other search from a different start ends here (1 of 4"), std::string::npos)
        << alone.text;
    // The mask outranks agreement: two runs in the same wrong basin are not ok.
    AnswerEvidence both = withRuns(2, 2);
    both.iou = 0.7;
    EXPECT_EQ(j.check(j.start(), both).verdict, V::Doubtful);
    both.stopped = true;
    both.iou = 0.95;
    EXPECT_EQ(j.check(j.start(), both).verdict, V::Doubtful);
}

TEST(AnswerCheck, NothingThatConfirmsIsDoubtfulNeverOk) {
    FM_REQUIRE_SHARED_DATA("jtml-kneel-tka-fluoro");
    const Jtml j;
    const AnswerCheck none = j.check(j.start(), AnswerEvidence{});
    EXPECT_EQ(none.verdict, V::Doubtful);
    EXPECT_EQ(none.text.rfind("doubtful: nothing confirms it", 0), 0u) << none.text;
    // An uncertainty alone does not confirm; one with an unfixed direction makes it doubtful.
    AnswerEvidence e = withRuns(2, 2);
    PoseUncertainty u;
    u.evaluations = 73;
    u.bounded = false;
    u.sd = {0.1, 0.1, std::numeric_limits<double>::infinity(), 0.3, 0.3, 0.1};
    e.uncertainty = u;
    const AnswerCheck flat = j.check(j.start(), e);
    EXPECT_EQ(flat.verdict, V::Doubtful);
    EXPECT_NE(flat.text.find("the cost does not rise along depth"), std::string::npos) << flat.text;
}

TEST(AnswerCheck, SimilarityAgainstTheLastGoodFrames) {
    FM_REQUIRE_SHARED_DATA("jtml-kneel-tka-fluoro");
    const Jtml j;
    AnswerEvidence e;
    e.similarityRatio = kConfirmedSimilarityRatio;
    EXPECT_EQ(j.check(j.start(), e).verdict, V::Ok);
    e.similarityRatio = std::nextafter(kConfirmedSimilarityRatio, 0.0);
    EXPECT_EQ(j.check(j.start(), e).verdict, V::Doubtful);
    e.similarityRatio = std::nextafter(kLostSimilarityRatio, 0.0);
    EXPECT_EQ(j.check(j.start(), e).verdict, V::Lost);
}

TEST(AnswerCheck, BlindIsLostWhateverTheRestSays) {
    FM_REQUIRE_SHARED_DATA("jtml-kneel-tka-fluoro");
    const Jtml j;
    // 100 m along the view: blind in the only camera, lost even with a perfect IoU and agreement.
    RigidTransform far = j.start();
    far.translation += 1e5 * glm::normalize(far.translation - j.model->scene().cameras[0].source);
    AnswerEvidence e = withRuns(2, 2);
    e.iou = 1.0;
    const AnswerCheck blind = j.check(far, e);
    EXPECT_EQ(blind.verdict, V::Lost);
    EXPECT_NE(blind.text.find("lost: at the answer the model covers 0 valid pixels"), std::string::npos)
        << blind.text;
}

}  // namespace
}  // namespace fm::test
