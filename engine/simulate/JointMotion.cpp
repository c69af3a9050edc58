#include "simulate/JointMotion.h"

#include <cmath>
#include <filesystem>

#include "core/Error.h"
#include "io/HeaderText.h"
#include "pose/AutoscoperTra.h"

namespace fm {

namespace {

std::vector<double> numbersOf(const std::string& text, std::size_t count, const std::string& what) {
    std::string spaced = text;
    for (char& c : spaced)
        if (c == ',' || c == ':') c = ' ';
    return io::parseNumbers(spaced, count, what);
}

}  // namespace

JointMotion parseJointMotion(const std::string& text, int frames, const glm::dvec3& defaultCenter) {
    if (frames < 1 || frames > 100000) throw Error("--frames must be 1 to 100000");
    JointMotion m;
    m.text = text;
    if (std::filesystem::path(text).extension() == ".tra") {
        const TraFile tra = readTra(text, TraForm::Matrix, 1);
        if (static_cast<int>(tra.frames.size()) < frames)
            throw Error("--motion " + text + ": " + std::to_string(tra.frames.size()) + " rows for " +
                        std::to_string(frames) + " frames");
        for (int f = 0; f < frames; ++f) {
            if (!tra.frames[static_cast<std::size_t>(f)][0])
                throw Error("--motion " + text + ": frame " + std::to_string(f) + " holds no pose");
            m.poses.push_back(*tra.frames[static_cast<std::size_t>(f)][0]);
        }
        return m;
    }
    const std::string prefix = "rotate:";
    if (text.rfind(prefix, 0) != 0)
        throw Error("--motion \"" + text + "\": give rotate:axis=...,angle=A0:A1[,center=X,Y,Z] or a .tra file");
    glm::dvec3 axis{0.0}, center = defaultCenter;
    double a0 = 0.0, a1 = 0.0;
    bool haveAxis = false, haveAngle = false;
    // key=value parts; a value may hold commas (axis and center take three numbers).
    std::string rest = text.substr(prefix.size());
    std::vector<std::pair<std::string, std::string>> parts;
    std::size_t pos = 0;
    while (pos < rest.size()) {
        const std::size_t eq = rest.find('=', pos);
        if (eq == std::string::npos) throw Error("--motion: \"" + rest.substr(pos) + "\" is not key=value");
        std::size_t next = rest.find('=', eq + 1);
        std::size_t end = rest.size();
        if (next != std::string::npos) end = rest.rfind(',', next);
        parts.emplace_back(rest.substr(pos, eq - pos), rest.substr(eq + 1, end - eq - 1));
        pos = end + 1;
    }
    for (const auto& [key, value] : parts) {
        if (key == "axis") {
            if (value == "x" || value == "y" || value == "z") axis[value[0] - 'x'] = 1.0;
            else {
                const auto v = numbersOf(value, 3, "--motion axis");
                axis = {v[0], v[1], v[2]};
            }
            if (!(glm::length(axis) > 0.0)) throw Error("--motion: the axis has no length");
            axis = glm::normalize(axis);
            haveAxis = true;
        } else if (key == "angle") {
            const auto v = numbersOf(value, 2, "--motion angle (A0:A1 degrees)");
            a0 = v[0], a1 = v[1];
            haveAngle = true;
        } else if (key == "center") {
            const auto v = numbersOf(value, 3, "--motion center (x,y,z mm)");
            center = {v[0], v[1], v[2]};
        } else {
            throw Error("--motion: unknown \"" + key + "\" (axis, angle, center)");
        }
    }
    if (!haveAxis || !haveAngle) throw Error("--motion rotate: give axis=... and angle=A0:A1");
    constexpr double kPi = 3.14159265358979323846;
    for (int f = 0; f < frames; ++f) {
        const double s = frames == 1 ? 0.0 : (1.0 - std::cos(kPi * f / (frames - 1))) / 2.0;
        m.poses.push_back(rotationAbout(axis, a0 + (a1 - a0) * s, center));
    }
    return m;
}

}  // namespace fm
