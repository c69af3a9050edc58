// Random corruption of valid calibration texts: every reader returns a valid result
// or throws fm::Error. Never a crash, a hang, a sanitizer report or another exception.
#include <gtest/gtest.h>

#include "camera/CameraFile.h"
#include "common/TextFuzz.h"
#include "core/Error.h"

namespace {

TEST(CalibrationFuzz, Readers) {
    auto camera = [](const std::string& t) {
        const fm::CameraReadResult r = fm::parseCameraText(t, "fuzz", glm::ivec2(1024, 1024));
        r.camera.validate("fuzzed camera");
        (void)fm::toProjectionGeometry(r.camera);
    };
    fm::test::fuzzText("MayaCam 2.0",
         "image size\n1760,1760\n\ncamera matrix\n6167.35,0,803.74\n0,6165.63,865.69\n0,0,1\n\n"
         "rotation\n1,0,0\n0,1,0\n0,0,1\n\ntranslation\n-16.6\n-77.8\n901.3\n",
         camera);
    fm::test::fuzzText("MayaCam 1.0", "10,20,-900\n1,2,3\n0,0,-500\n512,512,5000\n0.1,0,0\n", camera);
    fm::test::fuzzText("JT_INTCALIB", "JT_INTCALIB\n1198\n0\n0\n0.373\n", camera);
}

}  // namespace
