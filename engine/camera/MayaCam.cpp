#include "camera/MayaCam.h"

#include <cmath>
#include <string_view>

#include "geometry/EulerAngles.h"
#include "core/Error.h"
#include "io/AtomicFile.h"
#include "io/HeaderText.h"
#include "io/TextFile.h"

namespace fm {

namespace {

// The numbered lines of a text, with line numbers for messages.
struct Lines {
    std::vector<std::string> text;
    explicit Lines(const std::string& all) {
        std::size_t pos = 0;
        std::string line;
        while (io::nextLine(all, pos, line)) text.push_back(line);
    }
};

[[noreturn]] void failAt(const std::string& what, std::size_t lineIndex, const std::string& field,
                         const std::string& why) {
    throw Error(what + ": line " + std::to_string(lineIndex + 1) + " (\"" + field + "\"): " + why);
}

std::vector<double> numbersAt(const Lines& lines, std::size_t i, std::size_t count,
                              const std::string& what, const std::string& field) {
    if (i >= lines.text.size()) failAt(what, i, field, "missing (the file ends early)");
    const auto fields = io::splitFields(lines.text[i]);
    if (fields.size() != count)
        failAt(what, i, field, "expected " + std::to_string(count) + " numbers, got " +
                                   std::to_string(fields.size()) + " in '" + lines.text[i] + "'");
    std::vector<double> values;
    for (const auto& f : fields) {
        try {
            values.push_back(io::parseFinite(f, "value"));
        } catch (const Error& e) {
            failAt(what, i, field, e.what());
        }
    }
    return values;
}

int imageSide(double value, const std::string& what, std::size_t line, const char* name) {
    if (value != std::floor(value) || value < 1 || value > kMaxImageSide)
        failAt(what, line, "image size",
               std::string(name) + " must be a whole number of pixels between 1 and " +
                   std::to_string(kMaxImageSide) + ", got " + io::exactNumber(value));
    return static_cast<int>(value);
}

void expectTitle(const Lines& lines, std::size_t i, const char* title, const std::string& what) {
    if (i >= lines.text.size()) failAt(what, i, title, "missing (the file ends early)");
    if (!io::equalsIgnoreCase(io::trim(lines.text[i]), title))
        failAt(what, i, title, "expected the line '" + std::string(title) + "', got '" + lines.text[i] + "'");
}

void expectBlank(const Lines& lines, std::size_t i, const std::string& what, const char* before) {
    if (i >= lines.text.size()) failAt(what, i, before, "missing (the file ends early)");
    if (!io::trim(lines.text[i]).empty())
        failAt(what, i, before, "expected a blank line before '" + std::string(before) +
                                    "' (Autoscoper reads fixed line numbers), got '" + lines.text[i] + "'");
}

}  // namespace

CameraReadResult parseMayaCam2(const std::string& text, const std::string& what) {
    const Lines lines(text);
    expectTitle(lines, 0, "image size", what);
    const auto size = numbersAt(lines, 1, 2, what, "image size");
    const glm::ivec2 imageSize(imageSide(size[0], what, 1, "width"),
                               imageSide(size[1], what, 1, "height"));
    expectBlank(lines, 2, what, "camera matrix");
    expectTitle(lines, 3, "camera matrix", what);
    CameraMatrix K;
    for (int r = 0; r < 3; ++r) {
        const auto row = numbersAt(lines, 4 + r, 3, what, "camera matrix");
        for (int c = 0; c < 3; ++c) K.k[r][c] = row[c];
    }
    expectBlank(lines, 7, what, "rotation");
    expectTitle(lines, 8, "rotation", what);
    double R[3][3];
    for (int r = 0; r < 3; ++r) {
        const auto row = numbersAt(lines, 9 + r, 3, what, "rotation");
        for (int c = 0; c < 3; ++c) R[r][c] = row[c];
    }
    expectBlank(lines, 12, what, "translation");
    expectTitle(lines, 13, "translation", what);
    glm::dvec3 t;
    for (int i = 0; i < 3; ++i) t[i] = numbersAt(lines, 14 + i, 1, what, "translation")[0];

    CameraReadResult result;
    result.format = "MayaCam 2.0";
    // After the 17 lines: blank lines, or XMALab's undistortion block (ignored, as Autoscoper
    // does). Anything else is a file we do not understand.
    for (std::size_t i = 17; i < lines.text.size(); ++i) {
        const std::string line = io::trim(lines.text[i]);
        if (line.empty()) continue;
        if (io::equalsIgnoreCase(line, "undistortion")) {
            result.warnings.push_back(what + ": line " + std::to_string(i + 1) +
                                      ": the 'undistortion' block is ignored: the radiographs must "
                                      "already be undistorted (as Autoscoper assumes)");
            break;
        }
        failAt(what, i, "translation", "unexpected text after the translation: '" + line + "'");
    }
    result.camera = makePinholeCamera(K, R, t, imageSize, what);
    return result;
}

CameraReadResult parseMayaCam1(const std::string& text, const std::string& what) {
    const Lines lines(text);
    std::vector<std::size_t> used;  // non-blank lines
    for (std::size_t i = 0; i < lines.text.size(); ++i)
        if (!io::trim(lines.text[i]).empty()) used.push_back(i);
    if (used.size() != 5)
        throw Error(what + ": a MayaCam 1.0 file has 5 lines of 3 numbers, this one has " +
                    std::to_string(used.size()) + " non-blank lines");
    static const char* kFields[5] = {"camera position", "rotation", "image plane", "u0,v0,Z",
                                     "scale,width,height"};
    std::vector<double> v[5];
    for (int i = 0; i < 5; ++i) v[i] = numbersAt(lines, used[i], 3, what, kFields[i]);

    glm::ivec2 imageSize;
    for (int i = 0; i < 2; ++i) {
        const double side = v[4][1 + i] == 0.0 ? 1024.0 : v[4][1 + i];  // Autoscoper: 0 means 1024
        imageSize[i] = imageSide(side, what, used[4], i == 0 ? "width" : "height");
    }
    const double focal = std::abs(v[3][2]);
    if (!(focal > 0.0)) failAt(what, used[3], "u0,v0,Z", "the focal length Z must not be 0");

    // The file's camera is an OpenGL one (x right, y up, looks along -z), placed in the world
    // by world_R_gl = Rz(rz) Ry(ry) Rx(rx). OpenCV's camera axes are (x, -y, -z) of it, so
    // R (world -> camera) = diag(1, -1, -1) world_R_gl^T and t = -R C.
    const glm::dmat3 worldFromGl = rotationZyx(v[1][2], v[1][1], v[1][0]);
    const glm::dmat3 flip(glm::dvec3(1, 0, 0), glm::dvec3(0, -1, 0), glm::dvec3(0, 0, -1));
    const glm::dmat3 Rcv = flip * glm::transpose(worldFromGl);
    const glm::dvec3 C(v[0][0], v[0][1], v[0][2]);
    CameraMatrix K;
    K.k[0][0] = K.k[1][1] = focal;
    // u0, v0 are 1-based (Autoscoper subtracts 1); v0 counts rows from the bottom, so the
    // OpenCV principal row is (H - 1) - (v0 - 1).
    K.k[0][2] = v[3][0] - 1.0;
    K.k[1][2] = (imageSize.y - 1) - (v[3][1] - 1.0);
    K.k[2][2] = 1.0;
    double R[3][3];
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) R[r][c] = Rcv[c][r];
    CameraReadResult result;
    result.format = "MayaCam 1.0";
    result.camera = makePinholeCamera(K, R, -(Rcv * C), imageSize, what);
    return result;
}

std::string mayaCam2Text(const PinholeCamera& camera) {
    camera.validate("camera to write");
    auto n = [](double v) { return io::exactNumber(v); };
    std::string s;
    s += "image size\n" + std::to_string(camera.imageSize.x) + "," + std::to_string(camera.imageSize.y) + "\n\n";
    s += "camera matrix\n";
    s += n(camera.fx) + ",0," + n(camera.cx) + "\n";
    s += "0," + n(camera.fy) + "," + n(camera.cy) + "\n";
    s += "0,0,1\n\n";
    s += "rotation\n";
    for (int r = 0; r < 3; ++r)
        s += n(camera.R(r, 0)) + "," + n(camera.R(r, 1)) + "," + n(camera.R(r, 2)) + "\n";
    s += "\ntranslation\n";
    for (int i = 0; i < 3; ++i) s += n(camera.translation[i]) + "\n";
    return s;
}

void writeMayaCam2(const std::filesystem::path& path, const PinholeCamera& camera) {
    const std::string text = mayaCam2Text(camera);
    io::writeFileAtomically(path, std::vector<std::uint8_t>(text.begin(), text.end()));
}

}  // namespace fm
