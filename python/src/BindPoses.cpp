// Pose files of the field and their parameterizations: Autoscoper .tra (16-number matrices or
// xyzypr rows), JointTrack .jts (JT_EULER_312), as 4x4 numpy arrays with NaN for a frame that
// holds no pose.
#include <cmath>
#include <limits>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "Arrays.h"
#include "Bindings.h"
#include "core/Error.h"
#include "pose/AutoscoperTra.h"
#include "pose/JointTrackPoses.h"
#include "pose/PoseComparison.h"

namespace fm::py {

namespace {

using Doubles = pb::array_t<double, pb::array::c_style | pb::array::forcecast>;

std::array<double, 6> sixNumbers(const pb::handle& value, const std::string& what) {
    const std::vector<double> v = numbersOf(value, what, {6}, "6 numbers");
    std::array<double, 6> out{};
    std::copy(v.begin(), v.end(), out.begin());
    return out;
}

pb::array_t<double> sixArray(const double v[6]) {
    pb::array_t<double> a(6);
    std::copy(v, v + 6, a.mutable_data());
    return a;
}

// (frames, objects, 4, 4) with NaN for untracked.
pb::array_t<double> traArray(const TraFile& tra) {
    const pb::ssize_t frames = static_cast<pb::ssize_t>(tra.frames.size()), objects = tra.objects;
    pb::array_t<double> a(std::vector<pb::ssize_t>{frames, objects, 4, 4});
    double* d = a.mutable_data();
    for (pb::ssize_t f = 0; f < frames; ++f)
        for (pb::ssize_t o = 0; o < objects; ++o) {
            double* m = d + (f * objects + o) * 16;
            const auto& pose = tra.frames[static_cast<std::size_t>(f)][static_cast<std::size_t>(o)];
            if (!pose) {
                std::fill(m, m + 16, kNaN);
                continue;
            }
            const std::array<double, 16> r = pose->toRowMajor4x4();
            std::copy(r.begin(), r.end(), m);
        }
    return a;
}

// (frames, 4, 4) or (frames, objects, 4, 4); a matrix of NaN = no pose in that frame.
TraFile traFromArray(const pb::handle& value, const std::string& form, const std::string& what) {
    TraFile tra;
    tra.form = parseTraForm(form, "form");
    const Doubles a = arrayOf<double>(value, what, "poses as an (frames, 4, 4) or (frames, objects, 4, 4) array");
    const int leading = a.ndim() == 4 ? 2 : 1;
    const auto poses = poseStack(a, what, leading, true);
    tra.objects = leading == 2 ? static_cast<int>(a.shape(1)) : 1;
    for (std::size_t n = 0; n < poses.size(); ++n) {
        if (n % static_cast<std::size_t>(tra.objects) == 0) tra.frames.emplace_back();
        tra.frames.back().push_back(poses[n]);
    }
    return tra;
}

// One statistic as {"bias", "sd", "rms", "worst"}; six as {"x": ..., ..., "rz": ...}.
pb::dict statsDict(const ErrorStats& s) {
    pb::dict d;
    d["bias"] = s.bias;
    d["sd"] = s.sd;
    d["rms"] = s.rms;
    d["worst"] = s.worst;
    return d;
}
pb::dict sixStats(const std::array<ErrorStats, 6>& stats) {
    pb::dict d;
    for (std::size_t i = 0; i < 6; ++i) d[kPoseErrorNames[i]] = statsDict(stats[i]);
    return d;
}

// (frames, 4, 4) or (frames, 1, 4, 4) poses, NaN where a frame holds none.
std::vector<std::optional<RigidTransform>> framePoses(const pb::handle& value, const std::string& what) {
    const pb::array a = pb::array::ensure(value);
    if (!a || (a.ndim() != 3 && !(a.ndim() == 4 && a.shape(1) == 1)))
        throw Error(what + ": expected (frames, 4, 4) poses (or read_tra's (frames, 1, 4, 4))");
    return poseStack(value, what, a.ndim() == 4 ? 2 : 1, true);
}

}  // namespace

void bindPoses(pb::module_& m) {
    m.def(
        "compare_poses",
        [](const pb::handle& truth, const pb::handle& result, const pb::handle& centre, const pb::object& cameraFromWorld) {
            const std::optional<RigidTransform> camera =
                cameraFromWorld.is_none() ? std::nullopt : std::optional(toTransform(cameraFromWorld, "camera_from_world"));
            const PoseComparison c =
                comparePoses(framePoses(truth, "truth"), framePoses(result, "result"), toVec3(centre, "centre"), camera);
            const pb::ssize_t n = static_cast<pb::ssize_t>(c.frames.size());
            pb::array_t<int> frames(n);
            pb::array_t<double> centreMm(n), rotationDeg(n), bone(std::vector<pb::ssize_t>{n, 6}),
                cameraColumns(std::vector<pb::ssize_t>{n, 6});
            for (pb::ssize_t i = 0; i < n; ++i) {
                const FramePoseError& f = c.frames[static_cast<std::size_t>(i)];
                frames.mutable_at(i) = f.frame;
                centreMm.mutable_at(i) = f.centreMm;
                rotationDeg.mutable_at(i) = f.rotationDeg;
                for (pb::ssize_t k = 0; k < 6; ++k) {
                    bone.mutable_at(i, k) = f.bone[static_cast<std::size_t>(k)];
                    cameraColumns.mutable_at(i, k) = f.camera[static_cast<std::size_t>(k)];
                }
            }
            pb::dict d;
            d["frames"] = frames;
            d["centre_mm"] = centreMm;
            d["rotation_deg"] = rotationDeg;
            d["bone"] = bone;
            d["missing_in_result"] = c.missingInResult;
            d["missing_in_truth"] = c.missingInTruth;
            d["centre"] = statsDict(c.centre);
            d["rotation"] = statsDict(c.rotation);
            d["bone_stats"] = sixStats(c.bone);
            if (c.hasCamera) {
                d["camera"] = cameraColumns;
                d["camera_stats"] = sixStats(c.camera);
            }
            d["within_1mm_2deg"] = c.within1mm2deg;
            d["within_05mm_05deg"] = c.within05mm05deg;
            return d;
        },
        pb::arg("truth"), pb::arg("result"), pb::arg("centre"), pb::arg("camera_from_world") = pb::none(), R"doc(
A tracking result scored against a truth, as `fluoromatch compare` scores it (docs/tracking.md):
truth and result are (frames, 4, 4) worldFromObject poses (read_tra's (frames, 1, 4, 4) too), NaN
where a frame holds none; centre is the bone's centre in the object frame (mm). Returns a dict:
"frames" (those both hold), per frame "centre_mm" (|error of the centre|), "rotation_deg" (angle of
the relative rotation), "bone" ((frames, 6): x, y, z mm and rx, ry, rz deg in the truth's axes) and,
with camera_from_world, "camera" (the same in the camera's axes); "missing_in_result" and
"missing_in_truth" (frames one side lacks, never dropped silently); "centre", "rotation",
"bone_stats", "camera_stats" ({"bias", "sd", "rms", "worst"}); "within_1mm_2deg" and
"within_05mm_05deg" (shares of the compared frames). fluoromatch.Error when no frame holds both.)doc");


    m.def("read_tra",
          [](const std::filesystem::path& path, const std::string& form, int objects) {
              const TraForm f = form == "auto" ? TraForm::Auto : parseTraForm(form, "form");
              return traArray(readTra(path, f, objects, "give form=\"matrix\" or form=\"xyzypr\""));
          },
          pb::arg("path"), pb::arg("form") = "auto", pb::arg("objects") = 0, R"doc(
An Autoscoper .tra as a (frames, objects, 4, 4) array of worldFromVolume poses (mm), NaN where a
frame holds no pose. form "auto" (decided by the count of numbers), "matrix" or "xyzypr";
objects: how many objects a line holds when the count does not say (48 numbers).)doc");

    m.def("write_tra",
          [](const std::filesystem::path& path, const pb::handle& poses, const std::string& form) {
              writeTra(path, traFromArray(poses, form, "poses"));
          },
          pb::arg("path"), pb::arg("poses"), pb::arg("form") = "matrix", R"doc(
Writes an Autoscoper .tra (atomically) from (frames, 4, 4) or (frames, objects, 4, 4) poses; a
pose of 16 NaN writes an untracked frame. form "matrix" (16 numbers) or "xyzypr".)doc");

    m.def("xyzypr_to_matrix",
          [](const pb::handle& v) {
              const std::array<double, 6> a = sixNumbers(v, "xyzypr");
              return fromTransform(transformFromXyzypr(a.data()));
          },
          pb::arg("xyzypr"), "Autoscoper's x, y, z (mm), yaw, pitch, roll (deg) -> 4x4: R = Rz(yaw) Ry(pitch) Rx(roll).");
    m.def("matrix_to_xyzypr",
          [](const pb::handle& pose) {
              double v[6];
              xyzyprFromTransform(toTransform(pose, "pose"), v);
              return sixArray(v);
          },
          pb::arg("pose"), "4x4 -> Autoscoper's x, y, z, yaw, pitch, roll.");

    m.def("jts_to_matrix",
          [](const pb::handle& row) {
              const std::array<double, 6> a = sixNumbers(row, "jts row");
              JointTrackPose p;
              p.x = a[0], p.y = a[1], p.z = a[2], p.zRot = a[3], p.xRot = a[4], p.yRot = a[5];
              return fromTransform(p.cameraFromModel());
          },
          pb::arg("row"), "A .jts row x, y, z (mm), z_rot, x_rot, y_rot (deg) -> cameraFromModel 4x4.");
    m.def("matrix_to_jts",
          [](const pb::handle& pose) {
              const JointTrackPose p = JointTrackPose::fromCameraFromModel(toTransform(pose, "pose"));
              const double v[6] = {p.x, p.y, p.z, p.zRot, p.xRot, p.yRot};
              return sixArray(v);
          },
          pb::arg("pose"), "cameraFromModel 4x4 -> the .jts row (JT_EULER_312, x_rot in [-90, 90]).");

    m.def("read_jts",
          [](const std::filesystem::path& path) {
              const JointTrackPoses poses = readJointTrackPoses(path);
              const pb::ssize_t n = static_cast<pb::ssize_t>(poses.frames.size());
              pb::array_t<double> a(std::vector<pb::ssize_t>{n, 4, 4});
              double* d = a.mutable_data();
              for (pb::ssize_t f = 0; f < n; ++f) {
                  const JointTrackPose& p = poses.frames[static_cast<std::size_t>(f)];
                  if (!p.optimized) {
                      std::fill(d + 16 * f, d + 16 * f + 16, kNaN);
                      continue;
                  }
                  const std::array<double, 16> r = p.cameraFromModel().toRowMajor4x4();
                  std::copy(r.begin(), r.end(), d + 16 * f);
              }
              return a;
          },
          pb::arg("path"), R"doc(
A JointTrack .jts (JT_EULER_312) as an (images, 4, 4) array of cameraFromModel poses (the
JointTrack camera frame: source at the origin, looking along -z); NaN for NOT_OPTIMIZED rows.)doc");

    m.def("write_jts",
          [](const std::filesystem::path& path, const pb::handle& poses) {
              JointTrackPoses out;
              for (const std::optional<RigidTransform>& pose : poseStack(poses, "poses", 1, true)) {
                  JointTrackPose row;  // NOT_OPTIMIZED unless there is a pose
                  if (pose) row = JointTrackPose::fromCameraFromModel(*pose);
                  else row.optimized = false;
                  out.frames.push_back(row);
              }
              writeJointTrackPoses(path, out);
          },
          pb::arg("path"), pb::arg("poses"), R"doc(
Writes a .jts (JT_EULER_312, as JointTrack and JTML read it) from (images, 4, 4) cameraFromModel
poses; a pose of NaN writes a NOT_OPTIMIZED row.)doc");
}

}  // namespace fm::py
