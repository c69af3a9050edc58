#include "pose/AutoscoperTra.h"

#include <cmath>
#include <cstdio>

#include "core/Error.h"
#include "geometry/EulerAngles.h"
#include "io/AtomicFile.h"
#include "io/HeaderText.h"
#include "io/TextFile.h"
#include "pose/JointTrackPoses.h"

namespace fm {

namespace {

bool isNanWord(const std::string& w) {
    std::string s = w;
    if (!s.empty() && (s[0] == '-' || s[0] == '+')) s.erase(0, 1);
    return io::equalsIgnoreCase(s, "nan");
}

int perObject(TraForm form) { return form == TraForm::Matrix ? 16 : 6; }

}  // namespace

RigidTransform transformFromXyzypr(const double v[6]) {
    return RigidTransform{rotationZyx(v[3], v[4], v[5]), glm::dvec3(v[0], v[1], v[2])};
}

void xyzyprFromTransform(const RigidTransform& t, double v[6]) {
    const glm::dvec3 a = anglesZyx(t.rotation);
    for (int i = 0; i < 3; ++i) v[i] = t.translation[i];
    v[3] = a[0], v[4] = a[1], v[5] = a[2];
}

TraForm parseTraForm(const std::string& text, const std::string& option) {
    if (text == "matrix") return TraForm::Matrix;
    if (text == "xyzypr") return TraForm::Xyzypr;
    throw Error(option + " \"" + text + "\": expected matrix (16 numbers an object) or xyzypr (6)");
}

TraFile parseTra(const std::string& text, const std::string& what, TraForm form, int objects,
                 const std::string& howToSay) {
    std::vector<std::pair<std::size_t, std::vector<std::string>>> rows;
    std::size_t pos = 0, number = 0, lastNonBlank = 0;
    std::string line;
    while (io::nextLine(text, pos, line)) {
        ++number;
        rows.emplace_back(number, io::splitFields(line));
        if (!rows.back().second.empty()) lastNonBlank = rows.size();
    }
    rows.resize(lastNonBlank);  // trailing blank lines are not frames
    if (rows.empty()) throw Error(what + ": empty tracking file (one line per frame expected)");
    const std::size_t count = rows[0].second.size();
    TraFile tra;
    if (form == TraForm::Auto) {
        bool m = count % 16 == 0, x = count % 6 == 0;
        if (m && x && objects > 0) {  // the expected object count decides, if it fits one
            const bool asMatrices = count == 16 * static_cast<std::size_t>(objects);
            const bool asRows = count == 6 * static_cast<std::size_t>(objects);
            if (asMatrices != asRows) m = asMatrices, x = asRows;
        }
        if (m && x)
            throw Error(what + ": line 1 holds " + std::to_string(count) + " numbers: " +
                        std::to_string(count / 16) + " matrices (16 numbers each) or " +
                        std::to_string(count / 6) +
                        " x, y, z, yaw, pitch, roll rows (6 each) both fit" +
                        (objects > 0 ? ", and neither is the " + std::to_string(objects) +
                                           " objects expected"
                                     : std::string()) +
                        "; " + (howToSay.empty() ? std::string("write the file with one object, or read it "
                                                               "where the object count is known (a "
                                                               "trial's bones)")
                                                 : howToSay));
        if (!m && !x)
            throw Error(what + ": line 1 holds " + std::to_string(count) +
                        " numbers: not 16 (a 4x4 matrix) or 6 (x, y, z, yaw, pitch, roll) per object");
        form = m ? TraForm::Matrix : TraForm::Xyzypr;
    }
    tra.form = form;
    const int n = perObject(form);
    if (count == 0 || count % n != 0)
        throw Error(what + ": line 1 holds " + std::to_string(count) + " numbers, not a multiple of " +
                    std::to_string(n));
    tra.objects = static_cast<int>(count / n);
    for (const auto& [lineNumber, fields] : rows) {
        const std::string where = what + ": line " + std::to_string(lineNumber);
        if (fields.size() != count)
            throw Error(where + ": expected " + std::to_string(count) + " numbers (as on line 1), got " +
                        std::to_string(fields.size()));
        std::vector<std::optional<RigidTransform>> frame;
        for (int k = 0; k < tra.objects; ++k) {
            const std::string object = where + ", object " + std::to_string(k + 1);
            int nans = 0;
            double v[16];
            for (int i = 0; i < n; ++i) {
                const std::string& f = fields[static_cast<std::size_t>(k * n + i)];
                if (isNanWord(f)) {
                    ++nans;
                    v[i] = 0.0;
                } else {
                    v[i] = io::parseFinite(f, object + ", value " + std::to_string(i + 1));
                }
            }
            if (nans == n) {
                frame.emplace_back(std::nullopt);
                continue;
            }
            if (nans > 0)
                throw Error(object + ": " + std::to_string(nans) + " of " + std::to_string(n) +
                            " values are NaN (an untracked frame has all NaN)");
            if (form == TraForm::Matrix) {
                std::array<double, 16> m;
                for (int i = 0; i < 16; ++i) m[i] = v[i];
                frame.emplace_back(RigidTransform::fromRowMajor4x4(m, object));
            } else {
                frame.emplace_back(transformFromXyzypr(v));
            }
        }
        tra.frames.push_back(std::move(frame));
    }
    return tra;
}

TraFile readTra(const std::filesystem::path& path, TraForm form, int objects,
                const std::string& howToSay) {
    return parseTra(io::readTextFile(path, kMaxPoseFileBytes, "Autoscoper tracking file"),
                    path.string(), form, objects, howToSay);
}

std::string traText(const TraFile& tra) {
    if (tra.form == TraForm::Auto) throw Error("tracking file to write: say Matrix or Xyzypr");
    const int n = perObject(tra.form);
    std::string s;
    char buffer[64];
    for (std::size_t f = 0; f < tra.frames.size(); ++f) {
        const auto& frame = tra.frames[f];
        if (frame.size() != static_cast<std::size_t>(tra.objects))
            throw Error("tracking file to write: frame " + std::to_string(f + 1) + " has " +
                        std::to_string(frame.size()) + " objects, expected " + std::to_string(tra.objects));
        for (std::size_t k = 0; k < frame.size(); ++k) {
            double v[16];
            if (frame[k]) {
                frame[k]->validate("tracking file to write: frame " + std::to_string(f + 1));
                if (tra.form == TraForm::Matrix) {
                    const auto m = frame[k]->toRowMajor4x4();
                    for (int i = 0; i < 16; ++i) v[i] = m[i];
                } else {
                    xyzyprFromTransform(*frame[k], v);
                }
            }
            for (int i = 0; i < n; ++i) {
                if (k > 0 || i > 0) s += ",";
                if (!frame[k]) {
                    s += "NaN";
                    continue;
                }
                std::snprintf(buffer, sizeof buffer, "%.16f", v[i] == 0.0 ? 0.0 : v[i]);
                s += buffer;
            }
        }
        s += "\n";
    }
    return s;
}

void writeTra(const std::filesystem::path& path, const TraFile& tra) {
    const std::string text = traText(tra);
    io::writeFileAtomically(path, std::vector<std::uint8_t>(text.begin(), text.end()));
}

RigidTransform asWrittenInTra(const RigidTransform& pose) {
    TraFile one;
    one.frames = {{pose}};
    return *parseTra(traText(one), "pose").frames[0][0];
}

}  // namespace fm
