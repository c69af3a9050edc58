#include "drr/DrrBatch.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/Error.h"
#include "io/HeaderText.h"
#include "io/TextFile.h"
#include "match/PoseError.h"

namespace fm {

namespace {
constexpr std::size_t kMaxViewsFileBytes = 64u << 20;

std::string trimmed(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r");
    if (b == std::string::npos) return "";
    return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}
}  // namespace

std::vector<DrrView> parseDrrViews(const std::string& text, const std::string& what,
                                   const std::filesystem::path& baseFolder) {
    std::vector<DrrView> views;
    std::istringstream in(text);
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        const std::string where = what + ":" + std::to_string(number);
        if (const auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
        line = trimmed(line);
        if (line.empty()) continue;
        if (views.size() >= kMaxDrrViews)
            throw Error(where + ": more than " + std::to_string(kMaxDrrViews) + " views");
        DrrView view;
        view.origin = where;
        const std::vector<std::string> fields = io::splitFields(line);
        if (fields.size() == 6) {
            std::string joined;
            for (const auto& f : fields) joined += (joined.empty() ? "" : ",") + f;
            try {
                view.pose = parsePose(joined);
            } catch (const Error& e) {
                throw Error(where + ": " + e.what());
            }
        } else if (fields.size() == 1) {
            const std::filesystem::path file(line);
            view.geometryFile = file.is_absolute() ? file : baseFolder / file;
        } else {
            throw Error(where + ": expected six numbers \"x y z az el rot\" or one geometry file, "
                        "got " + std::to_string(fields.size()) + " fields");
        }
        views.push_back(std::move(view));
    }
    if (views.empty()) throw Error(what + ": no view found (one pose or geometry file per line)");
    return views;
}

std::vector<DrrView> readDrrViews(const std::filesystem::path& path) {
    const std::string text = io::readTextFile(path, kMaxViewsFileBytes, "views file");
    return parseDrrViews(text, path.string(), path.parent_path());
}

std::vector<DrrView> azimuthSweep(const Pose& start, int count, double stepDeg) {
    if (count < 1 || static_cast<std::size_t>(count) > kMaxDrrViews)
        throw Error("sweep: the number of angles must be 1.." + std::to_string(kMaxDrrViews) +
                    ", got " + std::to_string(count));
    if (!std::isfinite(stepDeg)) throw Error("sweep: the angle step must be a finite number");
    validatePose(start);
    std::vector<DrrView> views(count);
    for (int i = 0; i < count; ++i) {
        Pose p = start;
        p.azimuthDeg = wrapDegrees(start.azimuthDeg + i * stepDeg);
        views[i].pose = p;
        views[i].origin = "sweep " + std::to_string(i + 1) + " of " + std::to_string(count);
    }
    return views;
}

std::filesystem::path numberedOutput(const std::filesystem::path& base, std::size_t index,
                                     std::size_t count) {
    if (base.empty()) return base;
    int digits = 3;
    for (std::size_t n = count > 0 ? count - 1 : 0; n >= 1000; n /= 10) ++digits;
    std::string name = base.filename().string();
    // The extension: the last one, or two for ".nii.gz".
    std::size_t dot = name.rfind('.');
    if (io::endsWith(io::toLower(name), ".nii.gz")) dot = name.size() - 7;
    if (dot == std::string::npos || dot == 0) dot = name.size();
    char number[32];
    std::snprintf(number, sizeof(number), "_%0*zu", digits, index);
    return base.parent_path() / (name.substr(0, dot) + number + name.substr(dot));
}

std::vector<DrrJob> makeDrrJobs(const std::vector<DrrView>& views, const SceneSetup& setup,
                                const glm::dvec3& volumeCenter, int downsample,
                                const std::filesystem::path& output,
                                const std::filesystem::path& rawOutput) {
    std::vector<DrrJob> jobs(views.size());
    for (std::size_t i = 0; i < views.size(); ++i) {
        DrrJob& job = jobs[i];
        job.index = i;
        job.origin = views[i].origin;
        try {
            job.geometry = views[i].pose ? sceneGeometry(*views[i].pose, setup, volumeCenter)
                                         : readGeometryFile(views[i].geometryFile);
            if (downsample != 1) job.geometry = job.geometry.downsampled(downsample);
            job.geometry.validate(job.origin);
        } catch (const Error& e) {
            throw Error(job.origin + ": " + e.what());
        }
        job.output = numberedOutput(output, i, views.size());
        job.rawOutput = numberedOutput(rawOutput, i, views.size());
    }
    return jobs;
}

}  // namespace fm
