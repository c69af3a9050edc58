#include "cli/SearchCli.h"

#include <cmath>
#include <cstdio>
#include <ostream>
#include <sstream>

#include "cli/NumberChecks.h"
#include "cli/ValueChecks.h"
#include "cli/ValuesChoice.h"
#include "core/Error.h"
#include "io/AtomicFile.h"
#include "io/ReadVolume.h"
#include "radiograph/Radiograph.h"
#include "radiograph/RadiographPreparation.h"
#include "search/SearchOptions.h"

namespace fm::cli {

namespace {

std::vector<double> parseNumbers(const std::string& text, const std::string& option) {
    std::vector<double> values;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ',')) {
        try {
            std::size_t used = 0;
            const double v = std::stod(item, &used);
            if (used != item.size() || !std::isfinite(v)) throw std::invalid_argument(item);
            values.push_back(v);
        } catch (const std::exception&) {
            throw Error(option + ": \"" + item + "\" is not a number");
        }
    }
    return values;
}

}  // namespace

void addSearchOptions(CLI::App* cmd, SearchArgs& a, bool withMethod) {
    if (withMethod)
        cmd->add_option("--method", a.method, "Global search: mc, pso, bees or cmaes")
            ->capture_default_str()
            ->check(oneOf(globalMethodNames(), "search method",
                          {{"nm", "nm is the local polish, not a global search (mc, pso, bees or "
                                  "cmaes; the polish is --polish nm)"}}));
    cmd->add_option("--similarity", a.similarity,
                    "Similarity: ncc, gncc (gradient NCC), gd (gradient difference) or mi (mutual "
                    "information; the default with --slice)")
        ->capture_default_str()
        ->check(oneOf(similarityNames(), "similarity measure"));
    cmd->add_option("--seed", a.seed, "Random seed (same seed, same result)")
        ->capture_default_str()
        ->check(kSeedNumber);
    // Given values are checked (0 or -1 would otherwise silently mean "the default").
    cmd->add_option("--budget", a.budget, "Evaluations of the global search (default 600)")
        ->check(CLI::Range(1, kMaxEvaluations));
    cmd->add_option("--polish-budget", a.polishBudget,
                    "Evaluations of the local polish at every level (default 100, 30 at the finest "
                    "level; 0 = no polish)")
        ->check(CLI::Range(0, kMaxEvaluations));
    cmd->add_option("--levels", a.levels,
                    "Detector downsampling factors, coarse to fine (default 4,2,1)");
    cmd->add_option("--radius", a.radius,
                    "Search radius: one number or u,v,depth mm,az,el,rot deg (default "
                    "10,10,20,10,10,10)");
    cmd->add_option("--threads", a.threads, "Threads (0 = all cores)")->capture_default_str();
    cmd->add_option("--polish", a.polish, "Local refinement per level: nm (Nelder-Mead) or cmaes")
        ->capture_default_str()
        ->check(oneOf(polishMethodNames(), "polish method"));
    addValuesOption(cmd, a.values);
}

RegistrationSettings registrationSettings(const SearchArgs& a, RegistrationSettings s) {
    SearchOptions o;
    o.method = a.method;
    o.similarity = a.similarity;
    o.polish = a.polish;
    o.seed = a.seed;
    o.budget = a.budget;
    o.polishBudget = a.polishBudget;
    o.threads = a.threads;
    if (!a.levels.empty()) {
        for (double f : parseNumbers(a.levels, "--levels")) {
            if (f != std::floor(f) || f < 1 || f > 64)
                throw Error("--levels: factors must be whole numbers 1..64");
            o.levels.push_back(static_cast<int>(f));
        }
    }
    if (!a.radius.empty()) o.radius = parseNumbers(a.radius, "--radius");
    return applySearchOptions(o, std::move(s));
}

void useWholeCtSpeedups(RegistrationSettings& settings, const SearchArgs& args) {
    fm::useWholeCtSpeedups(settings, args.levels.empty());
}

std::string describeLevels(const RegistrationSettings& s) {
    std::string text = "levels";
    for (std::size_t i = 0; i < s.levelFactors.size(); ++i)
        text += (i ? "," : " ") + std::to_string(s.levelFactors[i]);
    text += ", budget " + std::to_string(s.globalEvaluations) + " + " +
            std::to_string(s.polishEvaluations) + " per polish";
    const int finest = s.finestPolishEvaluations >= 0 ? s.finestPolishEvaluations : s.polishEvaluations;
    if (finest != s.polishEvaluations) text += " (" + std::to_string(finest) + " at the finest)";
    return text;
}

DrrVolumePtr prepareForSearch(const Volume& volume, const std::string& values) {
    DrrValueOptions options;
    options.values = reportValues(volume, values);
    return prepareDrrVolume(volume, options);
}

Image renderReference(const DrrVolume& volume, const ProjectionGeometry& geometry, int threads) {
    DrrRenderOptions options;
    options.output = DrrOutput::LineIntegral;
    options.threads = threads;
    return renderDrr(volume, geometry, options);
}

Image readReferenceImage(const std::string& path) {
    const auto dot = path.find_last_of('.');
    std::string ext = dot == std::string::npos ? "" : path.substr(dot);
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".png") {
        // The radiograph reader (every check in one place), scaled to 0..1 by the file's full
        // scale: 8-bit and 16-bit PNGs alike, no gamma applied.
        RadiographFile file = readRadiograph(path);
        const float scale = static_cast<float>(radiographFullScale(file.bitsPerSample));
        for (float& p : file.image.pixels) p /= scale;
        return std::move(file.image);
    }
    const Volume v = readVolume(path);
    if (v.dims.z != 1)
        throw Error(path + ": a reference image must be 2-D, this file holds " +
                    std::to_string(v.dims.z) + " slices");
    Image img(v.dims.x, v.dims.y);
    img.spacing = {v.spacing.x, v.spacing.y};
    img.pixels = v.values;
    for (float p : img.pixels)
        if (!std::isfinite(p)) throw Error(path + ": the image holds non-finite values");
    return img;
}

std::vector<SearchMethod> parseMethodList(const std::string& text) {
    std::vector<SearchMethod> methods;
    std::stringstream ss(text);
    for (std::string m; std::getline(ss, m, ',');) {
        const SearchMethod method = parseSearchMethod(m);
        if (method == SearchMethod::NelderMead)
            throw Error("--methods: nm is the local polish, not a global search");
        methods.push_back(method);
    }
    if (methods.empty()) throw Error("--methods: give at least one method");
    return methods;
}

EvaluationCsv::EvaluationCsv(std::string path) : path_(std::move(path)) {
    if (path_.empty()) return;
    saveOften_ = !io::writesThrough(path_);
    rows_ << "method,bin_low_mm,bin_high_mm,start,start_mtre_mm,final_mtre_mm,"
             "final_in_plane_mm,final_out_of_plane_mm,seconds,cpu_seconds,evaluations,success\n";
    if (saveOften_) save();
}

void EvaluationCsv::save() {
    io::writeFileAtomically(path_, rows_.str());
    lastSave_ = std::chrono::steady_clock::now();
}

void EvaluationCsv::add(const EvaluationTrial& t, const EvaluationSettings& settings) {
    if (path_.empty()) return;
    const StartBin& b = settings.bins[t.bin];
    rows_ << toString(t.method) << ',' << b.lowMm << ',' << b.highMm << ',' << t.start << ','
          << t.startMtreMm << ',' << t.final.meanMm << ',' << t.final.meanInPlaneMm << ','
          << t.final.meanDepthMm << ',' << t.seconds << ',' << t.cpuSeconds << ',' << t.evaluations
          << ',' << (t.success ? 1 : 0) << '\n';
    if (saveOften_ && std::chrono::steady_clock::now() - lastSave_ > std::chrono::seconds(1))
        save();
}

void EvaluationCsv::finish() {
    if (path_.empty()) return;
    save();
    std::printf("wrote %s\n", path_.c_str());
}

void reportTrial(const EvaluationTrial& t, int done, int total, bool interactive) {
    if (interactive || done == total || done % 10 == 0)
        std::fprintf(stderr, "%sregistration %d/%d (%s)%s", interactive ? "\r" : "", done, total,
                     toString(t.method), interactive ? "   " : "\n");
}

void printEvaluationSummary(const std::vector<EvaluationTrial>& trials,
                            const EvaluationSettings& settings) {
    std::printf("\n%-6s %-9s %4s %8s %12s %10s %13s %10s %9s\n", "method", "start mm", "n",
                "success", "median mTRE", "in-plane", "out-of-plane", "time/reg", "cpu/reg");
    for (const auto& b : summarizeBins(trials, settings)) {
        char bin[32];
        std::snprintf(bin, sizeof bin, "%g-%g", b.bin.lowMm, b.bin.highMm);
        std::printf("%-6s %-9s %4d %7.0f%% %9.3f mm %7.3f mm %10.3f mm %8.3f s %7.3f s\n",
                    toString(b.method), bin, b.count, 100.0 * b.successRate, b.medianMtreMm,
                    b.medianInPlaneMm, b.medianOutOfPlaneMm, b.medianSeconds, b.medianCpuSeconds);
    }
    std::printf("\n%-6s %14s %16s %16s\n", "method", "capture range", "success (all)",
                "median time/reg");
    for (const auto& m : summarizeMethods(trials, settings))
        std::printf("%-6s %11.0f mm %15.0f%% %14.3f s\n", toString(m.method), m.captureRangeMm,
                    100.0 * m.successRate, m.medianSeconds);
    std::printf(
        "(capture range: largest initial mTRE up to which every bin reaches %.0f%% "
        "success)\n",
        100.0 * settings.captureSuccessRate);
}

void ProgressBar::update(const RegistrationProgress& p) {
    const double fraction =
        p.evaluationBudget > 0 ? std::min(1.0, double(p.evaluations) / p.evaluationBudget) : 0.0;
    const std::string stage =
        std::to_string(p.level + 1) + "/" + std::to_string(p.levelCount) + " " + p.stage;
    if (!interactive_) {
        if (stage != lastStage_)
            std::fprintf(stderr, "level %s (detector / %d)\n", stage.c_str(), p.factor);
        lastStage_ = stage;
        return;
    }
    if (p.seconds - lastShown_ < 0.1 && stage == lastStage_) return;
    lastShown_ = p.seconds;
    lastStage_ = stage;
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(fraction * kWidth);
    std::fprintf(stderr, "\r[%s%s] %3d%%  level %s  evals %d/%d  cost %.5f  %.1f s   ",
                 std::string(filled, '#').c_str(), std::string(kWidth - filled, '.').c_str(),
                 static_cast<int>(fraction * 100.0), stage.c_str(), p.evaluations,
                 p.evaluationBudget, p.bestCost, p.seconds);
    std::fflush(stderr);
    drawn_ = true;
}

void ProgressBar::finish() {
    if (drawn_) std::fprintf(stderr, "\n");
    drawn_ = false;
}

}  // namespace fm::cli
