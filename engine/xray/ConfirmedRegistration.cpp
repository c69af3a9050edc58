#include "xray/ConfirmedRegistration.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>

#include "core/Error.h"
#include "core/Parallel.h"
#include "scene/ObjectPoseParameterization.h"
#include "xray/CameraPoseDifference.h"

namespace fm {

namespace {

struct Search {
    std::size_t object = 0;
    int run = 0;
};

// One search per core when there are several and cores to spare; each then single-threaded.
void runSearches(const std::vector<Search>& searches, const RegistrationSettings& settings,
                 const std::function<void(const Search&, const RegistrationSettings&)>& run) {
    if (registersSideBySide(searches.size(), settings)) {
        RegistrationSettings single = settings;
        single.threads = 1;
        const int cores = settings.threads > 0 ? settings.threads : defaultThreadCount();
        parallelFor(
            static_cast<int>(searches.size()), cores,
            [&](int begin, int end) {
                for (int i = begin; i < end; ++i) run(searches[static_cast<std::size_t>(i)], single);
            },
            static_cast<int>(searches.size()));
    } else {
        for (const Search& s : searches) run(s, settings);
    }
}

}  // namespace

RigidTransform confirmationStart(const ProjectionGeometry& camera, const RigidTransform& start,
                                 const glm::dvec3& pivot, const RegistrationSettings& settings,
                                 const ConfirmationSettings& confirmation, int run) {
    if (run <= 0) return start;
    const ObjectPoseParameterization at("object", camera, start, pivot, DepthSearch::AlongRay);
    const SearchPoint point = confirmationPoint(settings, confirmation, run);
    return at.worldFromObject(at.fromSearchPoint(at.referenceParams(), point));
}

bool posesAgree(const RigidTransform& a, const RigidTransform& b, const glm::dvec3& pivot,
                const ConfirmationSettings& bounds) {
    return glm::length(a.applyToPoint(pivot) - b.applyToPoint(pivot)) <= bounds.agreeInPlaneMm &&
           rotationBetweenDeg(a.rotation, b.rotation) <= bounds.agreeRotationDeg;
}

bool sameAnswerInView(const CameraPoseDifference& d, const ConfirmationSettings& bounds) {
    return d.inPlaneMm <= bounds.agreeInPlaneMm && d.rotationDeg <= bounds.agreeRotationDeg;
}

bool registersSideBySide(std::size_t searches, const RegistrationSettings& settings) {
    return searches > 1 && (settings.threads > 0 ? settings.threads : defaultThreadCount()) > 1;
}

ObjectsRegistration registerObjects(const Scene& scene, const RegistrationView& view,
                                    const RegistrationSettings& settings,
                                    const ConfirmationSettings& confirmation,
                                    const std::function<RegistrationCallback(std::size_t)>& progressFor,
                                    const std::atomic<bool>* stop) {
    if (confirmation.runs < 1 || confirmation.maxRuns < confirmation.runs)
        throw Error("registration: confirmation runs must be at least 1 and at most maxRuns");
    if (view.camera >= scene.cameras.size())
        throw Error("registration: camera " + std::to_string(view.camera + 1) + " is not in the scene");
    const std::size_t n = scene.objects.size();
    const ProjectionGeometry& camera = scene.cameras[view.camera];
    ObjectsRegistration out;
    out.objects.resize(n);
    const auto started = std::chrono::steady_clock::now();
    std::vector<std::vector<ObjectRegistrationResult>> runs(n);
    // 0. Each object's view prepared once (pyramids, edge maps), side by side: every search of
    //    the object and its uncertainty share it.
    std::vector<std::optional<Registration>> prepared(n);
    parallelFor(
        static_cast<int>(n), n > 1 ? settings.threads : 1,
        [&](int begin, int end) {
            for (int k = begin; k < end; ++k)
                prepared[static_cast<std::size_t>(k)].emplace(
                    prepareObjectRegistration(scene, static_cast<std::size_t>(k), view, settings));
        },
        1);
    const auto search = [&](const Search& s, const RegistrationSettings& base) {
        const SceneObject& o = scene.objects[s.object];
        const glm::dvec3 pivot = o.model ? defaultPivot(*o.model) : glm::dvec3(0.0);
        const RigidTransform start = confirmationStart(camera, o.worldFromObject, pivot, base, confirmation, s.run);
        runs[s.object][static_cast<std::size_t>(s.run)] = registerObject(
            *prepared[s.object], scene, s.object, view, start, base.seed + static_cast<std::uint64_t>(s.run),
            base.threads, progressFor && s.run == 0 ? progressFor(s.object) : RegistrationCallback{}, stop);
    };
    const auto stopped = [&] { return stop && stop->load(); };
    // 1. The first runs of every object, side by side.
    std::vector<Search> searches;
    for (std::size_t k = 0; k < n; ++k) {
        runs[k].resize(static_cast<std::size_t>(confirmation.runs));
        for (int r = 0; r < confirmation.runs; ++r) searches.push_back({k, r});
    }
    out.sideBySide = registersSideBySide(searches.size(), settings);
    runSearches(searches, settings, search);
    // 2. The best run of each object and the runs that agree with it.
    std::vector<int> best(n, 0), agreeing(n, 0);
    const auto judge = [&](std::size_t k) {
        const auto& rk = runs[k];
        int b = 0;
        for (std::size_t r = 1; r < rk.size(); ++r)
            if (rk[r].similarity > rk[static_cast<std::size_t>(b)].similarity) b = static_cast<int>(r);
        best[k] = b;
        const glm::dvec3 pivot = defaultPivot(*scene.objects[k].model);
        agreeing[k] = 0;
        for (const ObjectRegistrationResult& r : rk) {
            const CameraPoseDifference d =
                cameraPoseDifference(camera, rk[static_cast<std::size_t>(b)].worldFromObject, r.worldFromObject, pivot);
            agreeing[k] += sameAnswerInView(d, confirmation);
        }
    };
    for (std::size_t k = 0; k < n; ++k) judge(k);
    // 3. The re-search: objects that no second run confirms get more runs (as many at a time as
    //    there are cores to share among them), until two agree or maxRuns have run.
    const int cores = settings.threads > 0 ? settings.threads : defaultThreadCount();
    while (confirmation.runs >= 2 && !stopped()) {
        searches.clear();
        std::vector<std::size_t> needy;
        for (std::size_t k = 0; k < n; ++k)
            if (agreeing[k] < 2 && static_cast<int>(runs[k].size()) < confirmation.maxRuns) needy.push_back(k);
        if (needy.empty()) break;
        const int each = std::max(1, cores / static_cast<int>(needy.size()));
        for (std::size_t k : needy) {
            const int first = static_cast<int>(runs[k].size());
            const int last = std::min(confirmation.maxRuns, first + each);
            runs[k].resize(static_cast<std::size_t>(last));
            for (int r = first; r < last; ++r) searches.push_back({k, r});
        }
        runSearches(searches, settings, search);
        for (std::size_t k : needy) judge(k);
    }
    // 4. How well the image fixes each coordinate at each answer.
    for (std::size_t k = 0; k < n; ++k) {
        ConfirmedObject& c = out.objects[k];
        c.runs = runs[k];
        c.answer = answerOfRuns(runs[k], static_cast<std::size_t>(best[k]));
        for (const ObjectRegistrationResult& r : runs[k]) c.answer.stopped = c.answer.stopped || r.stopped;
        if (settings.similarity == SimilarityMeasure::EdgeDistance) {
            c.evidence.similarityRatio = c.answer.similarity;  // against a perfect outline match's 1
            c.evidence.similarityReference = "a perfect outline match's";
            c.evidence.confirmedRatio = kConfirmedOutlineRatio;
        }
        c.evidence.runs = static_cast<int>(runs[k].size());
        c.evidence.agreeing = agreeing[k];
        c.evidence.stopped = c.answer.stopped;
    }
    if (confirmation.uncertainty && !stopped()) {
        const int cores2 = n > 1 ? 1 : settings.threads;
        parallelFor(
            static_cast<int>(n), n > 1 ? cores : 1,
            [&](int begin, int end) {
                for (int i = begin; i < end; ++i) {
                    const auto k = static_cast<std::size_t>(i);
                    ConfirmedObject& c = out.objects[k];
                    c.evidence.uncertainty = objectPoseUncertainty(*prepared[k], scene, k, view,
                                                                   c.answer.worldFromObject, cores2);
                }
            },
            static_cast<int>(n));
    }
    out.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return out;
}

}  // namespace fm
