// Random corruption of valid pose tables (.jts, .tra): a valid result or fm::Error, never a
// crash, a hang, a sanitizer report or another exception.
#include <gtest/gtest.h>

#include "common/TextFuzz.h"
#include "core/Error.h"
#include "pose/AutoscoperTra.h"
#include "pose/JointTrackPoses.h"

namespace {

TEST(PoseFuzz, Readers) {
    fm::test::fuzzText("JT_EULER_312",
         "JT_EULER_312\n x_tran, y_tran, z_tran, z_rot, x_rot, y_rot\n"
         "18.52191, 19.69514, -1027.713, -26.69708, -7.419319, -0.2587041\nNOT_OPTIMIZED\n",
         [](const std::string& t) { (void)fm::parseJointTrackPoses(t, "fuzz"); });
    fm::test::fuzzText("tra matrix",
         "1,0,0,5,0,1,0,6,0,0,1,7,0,0,0,1\nNaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN,NaN\n"
         "0,-1,0,5,1,0,0,6,0,0,1,7,0,0,0,1\n",
         [](const std::string& t) {
             const fm::TraFile f = fm::parseTra(t, "fuzz");
             for (const auto& frame : f.frames)
                 for (const auto& p : frame)
                     if (p) p->validate("fuzzed pose");
         });
    fm::test::fuzzText("tra xyzypr", "1 2 3 4 5 6\n7 8 9 10 11 12\nnan nan nan nan nan nan\n",
         [](const std::string& t) { (void)fm::parseTra(t, "fuzz", fm::TraForm::Xyzypr); });
}

}  // namespace
