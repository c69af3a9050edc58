// A Solve's verdict (xray/AnswerCheck.h) on the JTML frame 0160 and its femoral
// implant: the mask's IoU classes it (the thresholds are the rule's, tested at both sides), no mask
// leaves it unchecked, and a pose at which the model covers no valid pixel is lost whatever the
// IoU says.
#include <gtest/gtest.h>

#include <cmath>

#include "WorkspaceTestData.h"
#include "xray/AnswerCheck.h"

namespace fm::test {
namespace {

using Check = AnswerVerdict;

TEST(AnswerCheck, TheMaskDecidesCheckedDoubtfulLostAndNoMaskIsUnchecked) {
    FM_REQUIRE_SHARED_DATA("jtml-kneel-tka-fluoro");
    const auto model = app::WorkspaceModel::open(jtmlRadiographSource(), 2);
    const SceneObject& femur = model->scene().objects.at(0);
    const RigidTransform start = *model->initialPoses().at(0).at(0);
    const auto check = [&](const RigidTransform& pose, std::optional<double> iou) {
        return checkAnswer(femur, pose, model->prepared(0), model->scene().cameras, iou, 2);
    };
    EXPECT_EQ(check(start, kConfirmedIoU).check, Check::Confirmed);
    EXPECT_EQ(check(start, 0.95).text, "checked: silhouette IoU 0.950 against the mask (at least 0.90)");
    EXPECT_EQ(check(start, std::nextafter(kConfirmedIoU, 0.0)).check, Check::Doubtful);
    EXPECT_EQ(check(start, kLostIoU).check, Check::Doubtful);
    EXPECT_EQ(check(start, std::nextafter(kLostIoU, 0.0)).check, Check::Lost);
    EXPECT_EQ(check(start, 0.3).text, "lost: silhouette IoU 0.300 against the mask (below 0.50)");
    const AnswerCheck none = check(start, std::nullopt);
    EXPECT_EQ(none.check, Check::Unchecked);
    EXPECT_EQ(none.text.rfind("unchecked", 0), 0u);
    // 100 m along the view: blind in the only camera, lost even with a perfect IoU.
    RigidTransform far = start;
    far.translation += 1e5 * glm::normalize(start.translation - model->scene().cameras[0].source);
    const AnswerCheck blind = check(far, 1.0);
    EXPECT_EQ(blind.check, Check::Lost);
    EXPECT_NE(blind.text.find("lost: at the answer the model covers 0 valid pixels"), std::string::npos)
        << blind.text;
}

}  // namespace
}  // namespace fm::test
