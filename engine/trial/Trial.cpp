#include "trial/Trial.h"

#include <algorithm>
#include <system_error>

#include <nlohmann/json.hpp>

#include "core/Error.h"
#include "core/StrictJson.h"
#include "io/AtomicFile.h"
#include "io/ByteSource.h"
#include "io/HeaderText.h"
#include "io/TiffReader.h"
#include "trial/AutoscoperConfig.h"

namespace fm {

namespace fs = std::filesystem;

bool TrialBone::tiffStack() const { return io::hasTiffExtension(volume); }

using Json = nlohmann::json;

namespace {

constexpr std::uintmax_t kMaxTrialBytes = 16 << 20;

// Strict JSON access with the file and the field in every message.
struct Reader {
    std::string file;
    [[noreturn]] void fail(const std::string& field, const std::string& why) const {
        throw Error(file + ": \"" + field + "\" " + why);
    }
    const Json& member(const Json& o, const char* key, const std::string& field) const {
        if (!o.is_object()) fail(field, "must be an object");
        const auto it = o.find(key);
        if (it == o.end()) fail(field + "." + key, "is missing");
        return *it;
    }
    std::string text(const Json& v, const std::string& field) const {
        if (!v.is_string() || v.get<std::string>().empty()) fail(field, "must be a non-empty string");
        return v.get<std::string>();
    }
    std::vector<double> numbers(const Json& v, std::size_t n, const std::string& field) const {
        if (!v.is_array() || v.size() != n)
            fail(field, "must be an array of " + std::to_string(n) + " numbers");
        std::vector<double> out;
        for (const Json& x : v) {
            if (!x.is_number()) fail(field, "must hold numbers only");
            out.push_back(x.get<double>());
        }
        return out;
    }
};

VolumeFrame parseVolumeFrame(const Reader& r, const Json& v, const std::string& field) {
    const std::string s = r.text(v, field);
    if (s == "autoscoper") return VolumeFrame::Autoscoper;
    if (s == "fluoromatch") return VolumeFrame::Fluoromatch;
    r.fail(field, "must be \"autoscoper\" or \"fluoromatch\", not \"" + s + "\"");
}

TrialPose parsePose(const Reader& r, const Json& p, const std::string& field) {
    TrialPose pose;
    const Json& frame = r.member(p, "frame", field);
    if (!frame.is_number_integer() || frame.get<long long>() < 0 || frame.get<long long>() > 10000000)
        r.fail(field + ".frame", "must be a frame index >= 0");
    pose.frame = static_cast<int>(frame.get<long long>());
    const auto m = r.numbers(r.member(p, "world_from_volume", field), 16, field + ".world_from_volume");
    std::array<double, 16> a{};
    std::copy(m.begin(), m.end(), a.begin());
    pose.worldFromVolume = RigidTransform::fromRowMajor4x4(a, r.file + " " + field);
    pose.volumeFrame = parseVolumeFrame(r, r.member(p, "volume_frame", field), field + ".volume_frame");
    return pose;
}

fs::path resolve(const fs::path& base, const std::string& p) {
    const fs::path path(p);
    return path.is_absolute() ? path : (base / path).lexically_normal();
}

Trial readTrialJson(const fs::path& path) {
    const std::uintmax_t size = io::fileSize(path);
    if (size > kMaxTrialBytes) throw Error(io::quoted(path) + ": too large for a trial file");
    const io::Bytes bytes = io::readFileRange(path, 0, static_cast<std::size_t>(size));
    const Json root = parseStrictJson(std::string(bytes.begin(), bytes.end()), io::quoted(path));
    const Reader r{io::quoted(path)};
    const fs::path base = path.parent_path();
    Trial t;
    t.source = path;
    t.name = root.contains("name") ? r.text(root["name"], "name") : path.stem().string();
    const Json& cams = r.member(root, "cameras", "trial");
    if (!cams.is_array() || cams.empty()) r.fail("cameras", "must be a non-empty array");
    for (std::size_t i = 0; i < cams.size(); ++i) {
        const std::string f = "cameras[" + std::to_string(i) + "]";
        TrialCamera c;
        c.name = "cam";
        c.name += std::to_string(i + 1);
        if (cams[i].contains("name")) c.name = r.text(cams[i]["name"], f + ".name");
        c.calibration = resolve(base, r.text(r.member(cams[i], "calibration", f), f + ".calibration"));
        c.frames = resolve(base, r.text(r.member(cams[i], "frames", f), f + ".frames"));
        if (cams[i].contains("preparation"))
            c.preparation = framePreparationFromJson(cams[i]["preparation"], r.file, f + ".preparation");
        for (auto it = cams[i].begin(); it != cams[i].end(); ++it)
            if (it.key() != "name" && it.key() != "calibration" && it.key() != "frames" && it.key() != "preparation")
                t.warnings.push_back(r.file + ": unknown key \"" + f + "." + it.key() +
                                     "\" ignored (a camera has name, calibration, frames, preparation)");
        t.cameras.push_back(c);
    }
    const Json& bones = r.member(root, "bones", "trial");
    if (!bones.is_array() || bones.empty()) r.fail("bones", "must be a non-empty array");
    for (std::size_t i = 0; i < bones.size(); ++i) {
        const std::string f = "bones[" + std::to_string(i) + "]";
        TrialBone b;
        b.name = r.text(r.member(bones[i], "name", f), f + ".name");
        for (const TrialBone& other : t.bones)
            if (other.name == b.name) r.fail(f + ".name", "repeats the bone name \"" + b.name + "\"");
        // A bone is a volume (with its voxel size), or a mesh alone (an implant, a surface).
        if (bones[i].contains("volume") || !bones[i].contains("mesh")) {
            b.volume = resolve(base, r.text(r.member(bones[i], "volume", f), f + ".volume"));
            // A TIFF stack needs its voxel size; any other volume file has its own geometry.
            if (b.tiffStack()) {
                const auto s = r.numbers(r.member(bones[i], "voxel_size", f), 3, f + ".voxel_size");
                for (double x : s)
                    if (!(x > 0.0) || x > 1000.0) r.fail(f + ".voxel_size", "must be positive mm (at most 1000)");
                b.voxelSize = {s[0], s[1], s[2]};
            } else if (bones[i].contains("voxel_size")) {
                r.fail(f + ".voxel_size", "belongs to a TIFF stack: " + b.volume.filename().string() +
                                              " is placed by its own spacing, origin and direction");
            }
        } else if (bones[i].contains("voxel_size")) {
            r.fail(f + ".voxel_size", "belongs to a volume: this bone is a mesh only");
        }
        if (bones[i].contains("mu")) {
            if (!b.meshOnly()) r.fail(f + ".mu", "applies to a mesh-only bone (a volume has its own values)");
            const Json& mu = bones[i]["mu"];
            if (!mu.is_number() || !(mu.get<double>() > 0.0) || mu.get<double>() > 1000.0)
                r.fail(f + ".mu", "must be a positive attenuation in 1/mm (at most 1000)");
            b.muPerMm = mu.get<double>();
        }
        if (bones[i].contains("masks")) b.masks = resolve(base, r.text(bones[i]["masks"], f + ".masks"));
        if (bones[i].contains("flip")) {
            const auto fl = r.numbers(bones[i]["flip"], 3, f + ".flip");
            for (double x : fl)
                if (x != 0.0 && x != 1.0) r.fail(f + ".flip", "must hold 0 or 1");
            b.flip = {int(fl[0]), int(fl[1]), int(fl[2])};
        }
        if (bones[i].contains("mesh")) b.mesh = resolve(base, r.text(bones[i]["mesh"], f + ".mesh"));
        t.bones.push_back(b);
    }
    if (root.contains("render_resolution")) {
        const auto rr = r.numbers(root["render_resolution"], 2, "render_resolution");
        for (double x : rr)
            if (x < 1 || x > 16384 || x != int(x))
                r.fail("render_resolution", "must be whole pixels, 1..16384");
        t.renderResolution = {int(rr[0]), int(rr[1])};
    }
    if (root.contains("optimization_offsets")) {
        const auto o = r.numbers(root["optimization_offsets"], 6, "optimization_offsets");
        for (int i = 0; i < 6; ++i) {
            if (!(o[i] > 0.0)) r.fail("optimization_offsets", "must be positive");
            t.optimizationOffsets[i] = o[i];
        }
    }
    if (root.contains("keyframes")) {
        const Json& k = root["keyframes"];
        if (!k.is_object()) r.fail("keyframes", "must be an object of bone name -> list of poses");
        for (auto it = k.begin(); it != k.end(); ++it) {
            const std::string f = "keyframes." + it.key();
            t.bone(it.key());  // must name a bone of the trial
            if (!it->is_array()) r.fail(f, "must be an array of poses");
            std::vector<TrialPose> poses;
            for (std::size_t i = 0; i < it->size(); ++i)
                poses.push_back(parsePose(r, (*it)[i], f + "[" + std::to_string(i) + "]"));
            std::sort(poses.begin(), poses.end(),
                      [](const TrialPose& a, const TrialPose& b) { return a.frame < b.frame; });
            for (std::size_t i = 1; i < poses.size(); ++i)
                if (poses[i].frame == poses[i - 1].frame)
                    r.fail(f, "has two keyframes for frame " + std::to_string(poses[i].frame));
            t.keyframes[it.key()] = std::move(poses);
        }
    }
    for (auto it = root.begin(); it != root.end(); ++it) {
        static const char* known[] = {"name", "cameras", "bones", "render_resolution",
                                      "optimization_offsets", "keyframes", "comment"};
        if (std::find(std::begin(known), std::end(known), it.key()) == std::end(known))
            t.warnings.push_back(io::quoted(path) + ": unknown key \"" + it.key() + "\" ignored");
    }
    return t;
}

Trial trialFromConfig(const fs::path& path) {
    const AutoscoperConfig cfg = readAutoscoperConfig(path);
    Trial t;
    t.source = path;
    t.name = path.stem().string();
    t.warnings = cfg.warnings;
    for (std::size_t i = 0; i < cfg.calibrations.size(); ++i) {
        std::string name = "cam";  // piecewise: GCC 12 warns falsely on "literal" + string
        name += std::to_string(i + 1);
        TrialCamera c{name, cfg.calibrations[i], cfg.cameraRootDirs[i], std::nullopt};
        if (!cfg.preparations.empty()) c.preparation = cfg.preparations[i];
        t.cameras.push_back(c);
    }
    for (std::size_t i = 0; i < cfg.volumes.size(); ++i) {
        TrialBone b;
        b.name = cfg.volumes[i].file.stem().string();
        for (const TrialBone& other : t.bones)
            if (other.name == b.name) {
                b.name += '_';
                b.name += std::to_string(i + 1);
            }
        b.volume = cfg.volumes[i].file;
        b.voxelSize = cfg.volumes[i].voxelSize;
        b.flip = cfg.volumes[i].flip;
        if (!cfg.meshes.empty()) b.mesh = cfg.meshes[i];
        t.bones.push_back(b);
    }
    t.renderResolution = cfg.renderResolution;
    t.optimizationOffsets = cfg.optimizationOffsets;
    return t;
}

}  // namespace

const char* toString(VolumeFrame frame) {
    return frame == VolumeFrame::Autoscoper ? "autoscoper" : "fluoromatch";
}

const TrialBone& Trial::bone(const std::string& name) const {
    for (const TrialBone& b : bones)
        if (b.name == name) return b;
    std::string names;
    for (const TrialBone& b : bones) names += (names.empty() ? "" : ", ") + b.name;
    throw Error("trial " + io::quoted(source) + " has no bone \"" + name + "\" (it has " + names + ")");
}

namespace {

// The same file or folder however it is spelled ("f", "./f", "f/", through a link).
bool sameFile(const fs::path& a, const fs::path& b) {
    auto normal = [](const fs::path& p) {
        std::error_code ec;
        fs::path n = fs::weakly_canonical(fs::absolute(p), ec);
        return n.has_filename() ? n : n.parent_path();
    };
    return normal(a) == normal(b);
}

// A camera listed twice (the same name, or the same calibration and frames) is a copy-paste
// slip: it would double one view's weight and hide the camera that was meant.
void refuseRepeatedCameras(const Trial& t) {
    for (std::size_t i = 0; i < t.cameras.size(); ++i)
        for (std::size_t j = 0; j < i; ++j) {
            const TrialCamera &a = t.cameras[j], &b = t.cameras[i];
            if (a.name == b.name)
                throw Error(io::quoted(t.source) + ": cameras " + std::to_string(j + 1) + " and " +
                            std::to_string(i + 1) + " are both named \"" + a.name + "\"");
            if (sameFile(a.calibration, b.calibration) && sameFile(a.frames, b.frames))
                throw Error(io::quoted(t.source) + ": cameras " + a.name + " and " + b.name +
                            " are the same camera (calibration " + io::quoted(a.calibration) +
                            ", frames " + io::quoted(a.frames) + ")");
        }
}

}  // namespace

Trial readTrial(const fs::path& path) {
    const std::string ext = io::toLower(path.extension().string());
    Trial t;
    if (ext == ".cfg")
        t = trialFromConfig(path);
    else if (ext == ".json")
        t = readTrialJson(path);
    else
        throw Error(io::quoted(path) + ": a trial is an Autoscoper .cfg or a fluoromatch .json file");
    refuseRepeatedCameras(t);
    return t;
}

void writeTrialJson(const fs::path& path, const Trial& trial) {
    const fs::path base = fs::absolute(path).parent_path();
    auto rel = [&](const fs::path& p) { return fs::absolute(p).lexically_relative(base).generic_string(); };
    Json root;
    root["name"] = trial.name;
    for (const TrialCamera& c : trial.cameras) {
        Json j{{"name", c.name}, {"calibration", rel(c.calibration)}, {"frames", rel(c.frames)}};
        if (c.preparation) j["preparation"] = framePreparationToJson(*c.preparation);
        root["cameras"].push_back(j);
    }
    for (const TrialBone& b : trial.bones) {
        Json j{{"name", b.name}};
        if (!b.meshOnly()) {
            j["volume"] = rel(b.volume);
            if (b.tiffStack()) j["voxel_size"] = {b.voxelSize.x, b.voxelSize.y, b.voxelSize.z};
            j["flip"] = {b.flip.x, b.flip.y, b.flip.z};
        }
        if (!b.mesh.empty()) j["mesh"] = rel(b.mesh);
        if (b.muPerMm > 0.0) j["mu"] = b.muPerMm;
        if (!b.masks.empty()) j["masks"] = rel(b.masks);
        root["bones"].push_back(j);
    }
    root["render_resolution"] = {trial.renderResolution.x, trial.renderResolution.y};
    root["optimization_offsets"] = trial.optimizationOffsets;
    for (const auto& [bone, poses] : trial.keyframes)
        for (const TrialPose& p : poses)
            root["keyframes"][bone].push_back({{"frame", p.frame},
                                               {"world_from_volume", p.worldFromVolume.toRowMajor4x4()},
                                               {"volume_frame", toString(p.volumeFrame)}});
    const std::string s = root.dump(2) + "\n";
    io::writeFileAtomically(path, std::vector<std::uint8_t>(s.begin(), s.end()));
}

namespace {

// What is wrong with a path that should name a regular file ("" when it does): missing, a
// folder, or a device or pipe (/dev/zero would never end).
std::string notAFile(const fs::path& p) {
    std::error_code ec;
    const fs::file_status s = fs::status(p, ec);
    if (!fs::exists(s)) return "does not exist";
    if (fs::is_directory(s)) return "is a folder, not a file";
    if (!fs::is_regular_file(s)) return "is not a regular file (a device or pipe?)";
    return "";
}

}  // namespace

void checkTrialFiles(const Trial& trial) {
    std::error_code ec;
    const std::string t = "trial " + io::quoted(trial.source);
    auto needFile = [&](const std::string& what, const fs::path& p) {
        if (const std::string why = notAFile(p); !why.empty())
            throw Error(t + ": " + what + " " + io::quoted(p) + " " + why);
    };
    for (const TrialCamera& c : trial.cameras) {
        needFile("camera " + c.name + " calibration", c.calibration);
        if (!fs::exists(c.frames, ec))
            throw Error(t + ": camera " + c.name + " frames " + io::quoted(c.frames) + " do not exist");
    }
    for (const TrialBone& b : trial.bones) {
        if (!b.meshOnly()) needFile("bone " + b.name + " volume", b.volume);
        if (!b.mesh.empty()) needFile("bone " + b.name + " mesh", b.mesh);
        if (!b.masks.empty() && !fs::exists(b.masks, ec))
            throw Error(t + ": bone " + b.name + " masks " + io::quoted(b.masks) + " do not exist");
    }
}

}  // namespace fm
