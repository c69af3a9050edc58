#include "source/LabelSource.h"

#include <cmath>

#include "bones/ConnectedComponents.h"
#include "bones/LabelMap.h"
#include "core/Error.h"
#include "phantom/ArticulatedKnee.h"
#include "phantom/Phantoms.h"

namespace fm {
namespace {

constexpr const char* kPhantomPrefix = "phantom:";
constexpr const char* kComponents = "components";

bool startsWith(const std::string& s, const std::string& prefix) {
    return s.compare(0, prefix.size(), prefix) == 0;
}

}  // namespace

LabelledVolume loadLabels(const std::string& spec, const std::string& tablePath, const Volume& ct) {
    if (spec.empty()) throw Error("--labels: empty");
    LabelledVolume out;
    out.source = spec;
    if (startsWith(spec, kPhantomPrefix)) {
        const KneePhantomParams p = kneePhantomParams(spec.substr(std::string(kPhantomPrefix).size()));
        out.labels = labelsOnGrid(makeKneeBoneLabels(p), ct, "labels " + spec);
        out.table = kneeLabelTable();
    } else if (spec == kComponents || startsWith(spec, std::string(kComponents) + ":")) {
        ComponentOptions options;
        if (spec != kComponents) {
            const std::string level = spec.substr(std::string(kComponents).size() + 1);
            std::size_t used = 0;
            try {
                options.threshold = std::stod(level, &used);
            } catch (const std::exception&) {
                used = 0;
            }
            if (used != level.size() || level.empty() || !std::isfinite(options.threshold))
                throw Error("--labels " + spec + ": expected components:HU, e.g. components:300");
        }
        out.labels = labelConnectedComponents(ct, options);
        out.table = componentLabelTable(out.labels);
    } else {
        out.labels = loadLabelMap(spec, ct);
    }
    out.labels.meta.source = spec;
    if (!tablePath.empty()) out.table = readLabelTable(tablePath);
    return out;
}

std::vector<LabelEntry> missingLabels(const LabelledVolume& labelled) {
    const auto counts = labelVoxelCounts(labelled.labels);
    std::vector<LabelEntry> missing;
    for (const LabelEntry& e : labelled.table.entries)
        if (!counts.count(e.label)) missing.push_back(e);
    return missing;
}

}  // namespace fm
