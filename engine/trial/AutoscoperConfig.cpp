#include "trial/AutoscoperConfig.h"

#include <algorithm>
#include <sstream>

#include "core/Error.h"
#include "io/AtomicFile.h"
#include "io/ByteSource.h"
#include "io/HeaderText.h"

namespace fm {

namespace fs = std::filesystem;

namespace {

// A .cfg is a few dozen lines; anything much larger is not one.
constexpr std::uintmax_t kMaxConfigBytes = 1 << 20;

std::string unixSlashes(std::string path) {
    std::replace(path.begin(), path.end(), '\\', '/');
    while (path.size() > 1 && path.back() == '/') path.pop_back();
    return path;
}

}  // namespace

AutoscoperConfig readAutoscoperConfig(const fs::path& path) {
    const std::uintmax_t size = io::fileSize(path);
    if (size > kMaxConfigBytes)
        throw Error(io::quoted(path) + ": " + std::to_string(size) +
                    " bytes is too large for a trial configuration");
    const io::Bytes bytes = io::readFileRange(path, 0, static_cast<std::size_t>(size));
    const std::string text(bytes.begin(), bytes.end());

    AutoscoperConfig cfg;
    std::vector<std::string> flips, sizes, volumeFiles;
    std::size_t pos = 0;
    std::string line;
    int lineNo = 0;
    auto where = [&](const std::string& key) {
        return io::quoted(path) + " line " + std::to_string(lineNo) + " (" + key + ")";
    };
    while (io::nextLine(text, pos, line)) {
        ++lineNo;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty() || line[0] == '#') continue;
        const std::size_t space = line.find(' ');
        const std::string key = line.substr(0, space);
        const std::string value = space == std::string::npos ? "" : io::trim(line.substr(space + 1));
        if (key == "Version") {
            const std::size_t dot = value.find('.');
            cfg.versionMajor = static_cast<int>(io::parseInteger(value.substr(0, dot), where(key)));
            cfg.versionMinor =
                dot == std::string::npos
                    ? 0
                    : static_cast<int>(io::parseInteger(value.substr(dot + 1), where(key)));
            if (cfg.versionMajor != 1 || cfg.versionMinor < 0 || cfg.versionMinor > 2)
                throw Error(where(key) + ": version " + value + " is not 1.0, 1.1 or 1.2");
            cfg.versionGiven = true;
        } else if (key == "mayaCam_csv" || key == "CameraRootDir" || key == "VolumeFile" ||
                   key == "MeshFile") {
            if (value.empty()) throw Error(where(key) + ": no path given");
            const std::string p = unixSlashes(value);
            if (key == "mayaCam_csv") cfg.calibrations.emplace_back(p);
            if (key == "CameraRootDir") cfg.cameraRootDirs.emplace_back(p);
            if (key == "VolumeFile") volumeFiles.push_back(p);
            if (key == "MeshFile") cfg.meshes.emplace_back(p);
        } else if (key == "VolumeFlip") {
            const auto f = io::parseNumbers(value, 3, where(key));
            for (double x : f)
                if (x != 0.0 && x != 1.0) throw Error(where(key) + ": flips must be 0 or 1");
            flips.push_back(value);
        } else if (key == "VoxelSize") {
            const auto s = io::parseNumbers(value, 3, where(key));
            for (double x : s)
                if (!(x > 0.0) || x > 1000.0)
                    throw Error(where(key) + ": voxel sizes must be positive mm (at most 1000)");
            sizes.push_back(value);
        } else if (key == "RenderResolution") {
            const auto r = io::parseNumbers(value, 2, where(key));
            for (double x : r)
                if (x < 1 || x > 16384 || x != static_cast<int>(x))
                    throw Error(where(key) + ": the resolution must be whole pixels, 1..16384");
            cfg.renderResolution = {static_cast<int>(r[0]), static_cast<int>(r[1])};
        } else if (key == "OptimizationOffsets") {
            const auto o = io::parseNumbers(value, 6, where(key));
            for (int i = 0; i < 6; ++i) {
                if (!(o[i] > 0.0)) throw Error(where(key) + ": offsets must be positive");
                cfg.optimizationOffsets[i] = o[i];
            }
        } else if (key == "RadiographPreparation") {
            cfg.preparations.push_back(framePreparationFromText(value, where(key)));
        } else {
            cfg.warnings.push_back(where(key) + ": unknown key, ignored");
        }
    }
    if (!cfg.versionGiven)
        cfg.warnings.push_back(io::quoted(path) +
                               ": no Version key; read as 1.0 (paths must be absolute)");

    const std::string file = io::quoted(path);
    if (cfg.calibrations.empty()) throw Error(file + ": no camera (mayaCam_csv)");
    if (cfg.calibrations.size() != cfg.cameraRootDirs.size())
        throw Error(file + ": " + std::to_string(cfg.calibrations.size()) +
                    " cameras (mayaCam_csv) but " + std::to_string(cfg.cameraRootDirs.size()) +
                    " image folders (CameraRootDir)");
    if (!cfg.preparations.empty() && cfg.preparations.size() != cfg.calibrations.size())
        throw Error(file + ": one RadiographPreparation per camera or none (" +
                    std::to_string(cfg.calibrations.size()) + " cameras, " +
                    std::to_string(cfg.preparations.size()) + " RadiographPreparation lines)");
    if (volumeFiles.empty()) throw Error(file + ": no volume (VolumeFile)");
    if (sizes.size() != volumeFiles.size())
        throw Error(file + ": " + std::to_string(volumeFiles.size()) + " volumes but " +
                    std::to_string(sizes.size()) + " VoxelSize lines");
    if (flips.size() > volumeFiles.size())
        throw Error(file + ": more VolumeFlip lines than volumes");
    if (!cfg.meshes.empty() && cfg.meshes.size() != volumeFiles.size())
        throw Error(file + ": one MeshFile per volume or none (" +
                    std::to_string(volumeFiles.size()) + " volumes, " +
                    std::to_string(cfg.meshes.size()) + " meshes)");

    const bool relative = cfg.versionMajor == 1 && cfg.versionMinor >= 1;
    const fs::path base = path.parent_path();
    auto resolve = [&](fs::path& p, const char* key) {
        if (p.is_relative()) {
            if (!relative)
                throw Error(file + ": " + key + " " + io::quoted(p) +
                            " is relative, which Version 1.0 does not allow (write Version 1.1)");
            p = (base / p).lexically_normal();
        }
    };
    for (auto& p : cfg.calibrations) resolve(p, "mayaCam_csv");
    for (auto& p : cfg.cameraRootDirs) resolve(p, "CameraRootDir");
    for (auto& p : cfg.meshes) resolve(p, "MeshFile");
    for (std::size_t i = 0; i < volumeFiles.size(); ++i) {
        AutoscoperVolume v;
        v.file = volumeFiles[i];
        resolve(v.file, "VolumeFile");
        const auto s = io::parseNumbers(sizes[i], 3, file);
        v.voxelSize = {s[0], s[1], s[2]};
        if (i < flips.size()) {
            const auto f = io::parseNumbers(flips[i], 3, file);
            v.flip = {static_cast<int>(f[0]), static_cast<int>(f[1]), static_cast<int>(f[2])};
        }
        cfg.volumes.push_back(v);
    }
    return cfg;
}

void writeAutoscoperConfig(const fs::path& path, const AutoscoperConfig& config) {
    const fs::path base = fs::absolute(path).parent_path();
    auto rel = [&](const fs::path& p) {
        return fs::absolute(p).lexically_relative(base).generic_string();
    };
    std::ostringstream out;
    out.precision(12);
    // MeshFile exists only from 1.2 on.
    out << (config.meshes.empty() ? "Version 1.1\n" : "Version 1.2\n");
    for (const auto& p : config.calibrations) out << "mayaCam_csv " << rel(p) << "\n";
    for (const auto& p : config.cameraRootDirs) out << "CameraRootDir " << rel(p) << "\n";
    // Ours (Autoscoper skips the key): how each camera's frames are prepared.
    if (!config.preparations.empty() && config.preparations.size() != config.calibrations.size())
        throw Error(io::quoted(path) + ": one preparation per camera or none");
    for (const auto& p : config.preparations) out << "RadiographPreparation " << framePreparationText(p) << "\n";
    for (const auto& v : config.volumes) {
        out << "VolumeFile " << rel(v.file) << "\n";
        out << "VolumeFlip " << v.flip.x << " " << v.flip.y << " " << v.flip.z << "\n";
        out << "VoxelSize " << v.voxelSize.x << " " << v.voxelSize.y << " " << v.voxelSize.z
            << "\n";
    }
    for (const auto& p : config.meshes) out << "MeshFile " << rel(p) << "\n";
    out << "RenderResolution " << config.renderResolution.x << " " << config.renderResolution.y
        << "\n";
    out << "OptimizationOffsets";
    for (double o : config.optimizationOffsets) out << " " << o;
    out << "\n";
    const std::string s = out.str();
    io::writeFileAtomically(path, std::vector<std::uint8_t>(s.begin(), s.end()));
}

}  // namespace fm
