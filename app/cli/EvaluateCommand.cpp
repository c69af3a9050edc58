// `fluoromatch evaluate`: the van de Kraats et al. (2005) protocol for every search method on one
// volume: starts at known initial mTRE bins, success rate, median final mTRE split into in-plane
// and out-of-plane parts, capture range and time per registration. See docs/search.md.
#include <unistd.h>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <memory>
#include <span>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "bones/BoneRegistration.h"
#include "bones/BoneVolume.h"
#include "cli/BoneOptions.h"
#include "cli/CommandRegistry.h"
#include "cli/SearchCli.h"
#include "cli/SliceCli.h"
#include "cli/ValueChecks.h"
#include "cli/VolumeOption.h"
#include "core/Error.h"
#include "distributed/JobRunner.h"
#include "distributed/ProcessTransport.h"
#include "io/AtomicFile.h"
#include "scene/VolumeScene.h"
#include "search/Evaluation.h"
#include "source/VolumeSource.h"

namespace {

struct EvaluateArgs {
    std::string volume = fm::kDefaultVolumeSpec;
    std::string methods = "mc,pso,bees,cmaes";
    std::string truth = "0,0,0,0,0,0";
    int starts = 10;
    std::string csv;
    fm::cli::SearchArgs search;
    bool slice = false;
    fm::cli::SliceGridArgs grid;
    std::string interpolation = "cubic";
    fm::cli::BoneOptions bones;
    bool noRest = false;
    double marginMm = 20.0;
};

// What is evaluated: the 2011 scene of the whole CT, or (--bone) one bone's pose in the camera
// --truth places (its frame), the other objects static, its truth where the CT has it,
// compared in its footprint.
struct Evaluated {
    fm::EvaluationScene scene;
    fm::Image reference;
    fm::SceneParams truth{};
    std::vector<glm::dvec3> targets;
    std::string describe;
};

Evaluated wholeCt(const EvaluateArgs& a, const fm::Volume& volume, int threads) {
    const fm::DrrVolumePtr prepared = fm::cli::prepareForSearch(volume, a.search.values);
    const fm::Pose truth = fm::parsePose(a.truth);
    const auto parameterization =
        std::make_shared<fm::Pose2011Parameterization>(fm::defaultSceneSetup(), volume.center());
    return {{fm::volumeScene(prepared), parameterization, 0, std::nullopt},
            fm::cli::renderReference(*prepared, parameterization->geometry(truth), threads),
            truth.toArray(), fm::registrationTargets(volume), "truth " + a.truth};
}

Evaluated oneBone(const EvaluateArgs& a, const fm::Volume& ct) {
    if (!a.bones.without.empty()) throw fm::Error("evaluate takes --bone NAME (not --without)");
    if (a.bones.labels.empty())
        throw fm::Error("evaluate --bone needs --labels (a label map, phantom:knee or components)");
    if (!(a.marginMm >= 0.0) || a.marginMm > 500.0)
        throw fm::Error("--footprint-margin must be 0..500 mm");
    const fm::LabelledVolume labels = fm::loadLabels(a.bones.labels, a.bones.table, ct);
    const fm::BoneSelection bone = fm::resolveBone(a.bones.bone, labels.table);
    fm::DrrValueOptions values;
    values.values = a.search.values == "raw" ? fm::DrrValues::Raw : fm::DrrValues::Mu;
    fm::Scene scene = fm::cli::boneSceneFor(ct, labels, bone, a.noRest, values);
    scene.cameras.push_back(
        fm::sceneGeometry(fm::parsePose(a.truth), fm::defaultSceneSetup(), ct.center()));
    const auto parameterization = fm::boneParameterization(scene, bone.name);
    return {{scene, parameterization, *scene.find(bone.name),
             fm::boneFootprint(scene, bone.name, 0, a.marginMm)},
            fm::renderView(scene, 0, {}),
            parameterization->referenceParams(),
            fm::boneTargetPoints(fm::boneVolume(ct, labels.labels, bone), 200.0, 1000),
            "bone " + bone.name + " in the camera of " + a.truth + ", " +
                std::to_string(scene.objects.size() - 1) + " other objects static"};
}

void runEvaluate(const EvaluateArgs& a, bool similarityGiven) {
    if (a.starts < 1 || a.starts > 10000) throw fm::Error("--starts must be 1..10000");
    if (a.slice) {  // one process (the slice search is fast; docs/mri.md)
        fm::cli::SliceEvaluateArgs s;
        s.volume = a.volume;
        s.methods = a.methods;
        s.truth = a.truth;
        s.starts = a.starts;
        s.csv = a.csv;
        s.similarityGiven = similarityGiven;
        s.grid = a.grid;
        s.interpolation = a.interpolation;
        s.search = a.search;
        return fm::cli::runSliceEvaluate(s);
    }
    if (!a.grid.spacing.empty() || !a.grid.size.empty() || a.grid.thickness != 0.0)
        throw fm::Error("--size, --spacing and --thickness need --slice");
    fm::EvaluationSettings settings;
    settings.registration = fm::cli::registrationSettings(a.search);
    settings.startsPerBin = a.starts;
    settings.seed = a.search.seed;
    settings.methods.clear();
    std::stringstream ss(a.methods);
    for (std::string m; std::getline(ss, m, ',');) {
        const fm::SearchMethod method = fm::parseSearchMethod(m);
        if (method == fm::SearchMethod::NelderMead)
            throw fm::Error("--methods: nm is the local polish, not a global search");
        settings.methods.push_back(method);
    }
    if (settings.methods.empty()) throw fm::Error("--methods: give at least one method");
    // Every rank loads and prepares the volume once, and plans the same registrations. MPI
    // starts after the load, so that a volume no rank can read ends the run without aborts.
    const fm::Volume volume = fm::loadVolume(a.volume);
    fm::distributed::Transport& transport = fm::distributed::processTransport();
    const bool writer = transport.rank() == 0;
    // The CSV (rank 0) is rewritten whole and atomically: the header before any work (a path
    // that cannot be written fails now, not after the run), then at most once a second while
    // trials arrive (an interrupted run keeps complete rows; in a distributed run rows arrive
    // when every rank has finished its jobs), and at the end. A pipe or device gets the whole
    // file once, at the end.
    const bool csv = writer && !a.csv.empty();
    const bool saveOften = csv && !fm::io::writesThrough(a.csv);
    std::ostringstream rows;
    rows << "method,bin_low_mm,bin_high_mm,start,start_mtre_mm,final_mtre_mm,"
            "final_in_plane_mm,final_out_of_plane_mm,seconds,cpu_seconds,evaluations,success,"
            "similarity_ratio,verdict\n";
    auto lastSave = std::chrono::steady_clock::now();
    const auto saveCsv = [&] {
        fm::io::writeFileAtomically(a.csv, rows.str());
        lastSave = std::chrono::steady_clock::now();
    };
    if (saveOften) saveCsv();

    settings.registration.threads =
        fm::distributed::threadsPerRank(transport, settings.registration.threads);
    if (a.bones.bone.empty()) fm::cli::useWholeCtSpeedups(settings.registration, a.search);
    const Evaluated e = a.bones.bone.empty()
                            ? wholeCt(a, volume, settings.registration.threads)
                            : oneBone(a, volume);
    const fm::EvaluationScene& scene = e.scene;
    const fm::Image& reference = e.reference;
    const auto& targets = e.targets;
    const std::vector<fm::EvaluationStart> plan =
        fm::evaluationPlan(e.truth, scene, targets, settings);
    const int threads = settings.registration.threads;

    if (writer) {
        std::printf("volume     %s (%d x %d x %d), %s, %zu mTRE targets\n", a.volume.c_str(),
                    volume.dims.x, volume.dims.y, volume.dims.z, e.describe.c_str(),
                    targets.size());
        std::printf(
            "protocol   %d starts per bin, seed %llu, success = final mTRE < %.1f mm, %d "
            "threads\n",
            a.starts, static_cast<unsigned long long>(settings.seed), settings.successMm,
            threads);
        // The levels a registration keeps (those finer than the voxels are left out).
        const fm::Registration probe(scene.scene, scene.parameterization,
                                     {{0, reference, scene.valid}}, settings.registration);
        std::printf("search     %s, %s\n", fm::toString(settings.registration.similarity),
                    fm::cli::describeLevels(probe.settings()).c_str());
        std::printf("processes  %d (%s), %d thread%s each; %zu registrations, %zu bytes each "
                    "to rank 0\n",
                    transport.size(), transport.name(), threads, threads == 1 ? "" : "s",
                    plan.size(), fm::distributed::bytesPerJob(sizeof(fm::EvaluationTrial)));
        std::fflush(stdout);
    }

    // One job per registration; a rank builds each method's Registration once, when first used.
    std::vector<std::unique_ptr<fm::Registration>> registrations(settings.methods.size());
    auto registrationFor = [&](fm::SearchMethod method) -> const fm::Registration& {
        const std::size_t m = static_cast<std::size_t>(
            std::find(settings.methods.begin(), settings.methods.end(), method) -
            settings.methods.begin());
        if (!registrations[m]) {
            fm::RegistrationSettings rs = settings.registration;
            rs.method = method;
            registrations[m] = std::make_unique<fm::Registration>(
                scene.scene, scene.parameterization,
                std::vector<fm::RegistrationView>{{0, reference, scene.valid}}, rs);
        }
        return *registrations[m];
    };
    static_assert(std::is_trivially_copyable_v<fm::EvaluationTrial>);
    std::vector<fm::EvaluationTrial> trials;
    const bool interactive = writer && isatty(fileno(stderr)) != 0;
    const int total = static_cast<int>(plan.size());
    const auto failures = fm::distributed::runIndexedJobs(
        transport, total, sizeof(fm::EvaluationTrial),
        [&](int job, std::span<std::byte> record) {
            const fm::EvaluationStart& start = plan[job];
            const fm::EvaluationTrial t = fm::runEvaluationTrial(
                registrationFor(start.method), start, scene, e.truth, targets, settings);
            std::memcpy(record.data(), &t, sizeof t);
        },
        [&](int, std::span<const std::byte> record) {
            fm::EvaluationTrial t;
            std::memcpy(&t, record.data(), sizeof t);
            trials.push_back(t);
            if (!csv) return;
            const fm::StartBin& b = settings.bins[t.bin];
            rows << fm::toString(t.method) << ',' << b.lowMm << ',' << b.highMm << ',' << t.start
                 << ',' << t.startMtreMm << ',' << t.final.meanMm << ',' << t.final.meanInPlaneMm
                 << ',' << t.final.meanDepthMm << ',' << t.seconds << ',' << t.cpuSeconds << ','
                 << t.evaluations << ',' << (t.success ? 1 : 0) << ',' << t.similarityRatio << ','
                 << fm::toString(t.verdict) << '\n';
            if (saveOften && std::chrono::steady_clock::now() - lastSave > std::chrono::seconds(1))
                saveCsv();
        },
        [&](int job, int done, int mine) {
            // Rank 0 shows its own share; the others run theirs silently.
            if (writer && (interactive || done == mine || done % 10 == 0))
                std::fprintf(stderr, "%sregistration %d/%d (%s)%s%s", interactive ? "\r" : "",
                             done, mine, fm::toString(plan[job].method),
                             transport.size() > 1 ? " on rank 0" : "", interactive ? "   " : "\n");
        });
    if (interactive) std::fprintf(stderr, "\n");
    if (!writer) return;

    if (csv) {
        saveCsv();
        std::printf("wrote %s\n", a.csv.c_str());
    }

    std::printf("\n%-6s %-9s %4s %8s %12s %10s %13s %10s %9s\n", "method", "start mm", "n",
                "success", "median mTRE", "in-plane", "out-of-plane", "time/reg", "cpu/reg");
    for (const auto& b : fm::summarizeBins(trials, settings)) {
        char bin[32];
        std::snprintf(bin, sizeof bin, "%g-%g", b.bin.lowMm, b.bin.highMm);
        std::printf("%-6s %-9s %4d %7.0f%% %9.3f mm %7.3f mm %10.3f mm %8.3f s %7.3f s\n",
                    fm::toString(b.method), bin, b.count, 100.0 * b.successRate, b.medianMtreMm,
                    b.medianInPlaneMm, b.medianOutOfPlaneMm, b.medianSeconds, b.medianCpuSeconds);
    }
    std::printf("\n%-6s %14s %16s %16s\n", "method", "capture range", "success (all)",
                "median time/reg");
    for (const auto& m : fm::summarizeMethods(trials, settings))
        std::printf("%-6s %11.0f mm %15.0f%% %14.3f s\n", fm::toString(m.method), m.captureRangeMm,
                    100.0 * m.successRate, m.medianSeconds);
    std::printf(
        "(capture range: largest initial mTRE up to which every bin reaches %.0f%% "
        "success)\n",
        100.0 * settings.captureSuccessRate);
    // The verdict (judged without the truth) against the truth's success: does "ok" mean right?
    for (const fm::SearchMethod method : settings.methods) {
        int okRight = 0, okWrong = 0, notOkRight = 0, notOkWrong = 0;
        for (const fm::EvaluationTrial& t : trials) {
            if (t.method != method) continue;
            const bool ok = t.verdict == fm::AnswerVerdict::Ok;
            (ok ? (t.success ? okRight : okWrong) : (t.success ? notOkRight : notOkWrong)) += 1;
        }
        std::printf("verdict %-6s ok %d (%d of them misses), not ok %d (%d of them misses): %d of %d misses "
                    "flagged\n",
                    fm::toString(method), okRight + okWrong, okWrong, notOkRight + notOkWrong, notOkWrong,
                    notOkWrong, okWrong + notOkWrong);
    }
    for (const fm::SearchMethod method : settings.methods) {
        fm::EvaluationProfile profile;
        for (const fm::EvaluationTrial& t : trials)
            if (t.method == method) profile += t.profile;
        std::printf("speed %-6s %s\n", fm::toString(method),
                    fm::describeEvaluations(profile, settings.registration.threads).c_str());
    }
    if (!failures.empty())
        throw fm::distributed::JobsFailed(
            std::to_string(failures.size()) + " of " + std::to_string(total) +
            " registrations failed (the tables and CSV hold the others): " +
            fm::distributed::describeFailures(failures));
}

FM_REGISTER_COMMAND("evaluate", 41, [](CLI::App& app) {
    auto* cmd = app.add_subcommand(
        "evaluate",
        "Evaluate the search methods (van de Kraats 2005 protocol): success rate, "
        "median mTRE, capture range, time");
    auto a = std::make_shared<EvaluateArgs>();
    fm::cli::addVolumeOption(cmd, a->volume);
    cmd->add_option("--methods", a->methods, "Comma-separated: mc, pso, bees, cmaes")
        ->capture_default_str();
    cmd->add_option("--starts", a->starts, "Start poses per mTRE bin")->capture_default_str();
    cmd->add_option("--truth", a->truth, "True pose: the reference DRR is rendered there")
        ->capture_default_str()
        ->check(fm::cli::kPoseText);
    cmd->add_option("--csv", a->csv, "Write one row per registration to this CSV file");
    fm::cli::addSearchOptions(cmd, a->search, false);
    fm::cli::addBoneOptions(cmd, a->bones);
    cmd->add_flag("--no-rest", a->noRest, "With --bone: leave the rest of the CT out of the images");
    cmd->add_option("--footprint-margin", a->marginMm,
                    "With --bone: mm added around the bone's footprint (the compared pixels)")
        ->capture_default_str();
    cmd->add_flag("--slice", a->slice,
                  "MRI slice mode: evaluate slice-to-volume registration (reference = a slice "
                  "at --truth; similarity mi by default; see docs/mri.md)");
    fm::cli::addSliceGridOptions(cmd, a->grid);
    cmd->add_option("--interpolation", a->interpolation,
                    "With --slice: cubic (B-spline, default) or linear")
        ->capture_default_str();
    cmd->callback([a, cmd] { runEvaluate(*a, cmd->get_option("--similarity")->count() > 0); });
    return cmd;
});

}  // namespace
