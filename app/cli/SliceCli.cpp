#include "cli/SliceCli.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string_view>

#include "core/Error.h"

namespace fm::cli {

namespace {

double parseNumber(std::string_view text, const std::string& option) {
    double value = 0.0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || r.ec != std::errc() || r.ptr != text.data() + text.size() ||
        !std::isfinite(value))
        throw Error(option + ": \"" + std::string(text) + "\" is not a finite number");
    return value;
}

void applyGrid(const SliceGridArgs& a, SliceSetup& s) {
    if (!a.size.empty()) {
        const auto x = a.size.find_first_of("xX");
        if (x == std::string::npos)
            throw Error("--size: expected WIDTHxHEIGHT pixels, got \"" + a.size + "\"");
        const std::string_view all = a.size;
        const double w = parseNumber(all.substr(0, x), "--size");
        const double h = parseNumber(all.substr(x + 1), "--size");
        if (w != std::floor(w) || h != std::floor(h) || w < 1 || h < 1 || w > 16384 || h > 16384)
            throw Error("--size: slice pixels must be whole numbers 1..16384, got \"" + a.size +
                        "\"");
        s.pixels = {static_cast<int>(w), static_cast<int>(h)};
    }
    if (!a.spacing.empty()) {
        const auto comma = a.spacing.find(',');
        const std::string_view all = a.spacing;
        if (comma == std::string::npos) {
            s.spacingMm.x = s.spacingMm.y = parseNumber(all, "--spacing");
        } else {
            s.spacingMm.x = parseNumber(all.substr(0, comma), "--spacing");
            s.spacingMm.y = parseNumber(all.substr(comma + 1), "--spacing");
        }
    }
    s.thicknessMm = a.thickness;
    validateSliceSetup(s);
}

}  // namespace

void addSliceGridOptions(CLI::App* cmd, SliceGridArgs& a, bool withSize) {
    if (withSize)
        cmd->add_option("--size", a.size,
                        "Slice pixels WxH (default: 256 across the volume's box diagonal)");
    cmd->add_option("--spacing", a.spacing,
                    "Slice pixel spacing in mm: s or su,sv (default: the diagonal / 256, never "
                    "finer than the voxels)");
    cmd->add_option("--thickness", a.thickness,
                    "Slice thickness in mm: the profile across the plane is averaged (0 = an "
                    "ideal plane)")
        ->capture_default_str();
}

SliceSetup sliceSetupFrom(const SliceGridArgs& a, const Volume& volume) {
    SliceSetup s = defaultSliceSetup(volume);
    applyGrid(a, s);
    return s;
}

SliceSetup sliceSetupFrom(const SliceGridArgs& a) {
    SliceSetup s;
    applyGrid(a, s);
    return s;
}

SliceWindow sliceWindow(const Image& image, const Mask& mask) {
    std::vector<float> data;
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        if (mask.inside[i]) data.push_back(image.pixels[i]);
    SliceWindow w;
    if (data.empty()) return w;
    auto percentile = [&](double p) {
        const auto k = static_cast<std::size_t>(std::llround(p * (data.size() - 1)));
        std::nth_element(data.begin(), data.begin() + k, data.end());
        return static_cast<double>(data[k]);
    };
    w.low = percentile(0.01);
    w.high = percentile(0.995);
    if (!(w.high > w.low)) w.high = w.low + 1.0;
    return w;
}

std::string emptySliceMessage(const Pose& pose) {
    return "the plane of pose " + formatPose(pose) +
           " misses the volume: the slice is empty (every pixel masked as no data)";
}

SliceRegistrationSettings sliceRegistrationSettings(const SearchArgs& a, bool similarityGiven,
                                                    const std::string& interpolation) {
    // The X-ray parser checks every shared option; the slice search takes what applies.
    const RegistrationSettings x = registrationSettings(a);
    SliceRegistrationSettings s;
    s.method = x.method;
    s.similarity = similarityGiven ? x.similarity : SimilarityMeasure::MutualInformation;
    s.interpolation = parseSliceInterpolation(interpolation);
    s.seed = x.seed;
    s.threads = x.threads;
    if (a.budget > 0) s.globalEvaluations = a.budget;
    if (a.polishBudget >= 0) s.polishEvaluations = a.polishBudget;
    if (!a.levels.empty()) s.levelFactors = x.levelFactors;
    if (!a.radius.empty()) s.searchRadius = x.searchRadius;
    if (x.polishMethod != SearchMethod::NelderMead)
        throw Error("--polish: the slice search polishes with nm only");
    return s;
}

}  // namespace fm::cli
