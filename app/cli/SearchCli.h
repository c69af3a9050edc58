#pragma once
// What `register` and `evaluate` share: the search options, preparing a volume for DRRs,
// rendering or reading the reference image, and the progress bar.
#include <chrono>
#include <sstream>
#include <string>

#include <CLI/CLI.hpp>

#include "core/Image.h"
#include "drr/Drr.h"
#include "search/Evaluation.h"
#include "search/Registration.h"
#include "volume/Volume.h"

namespace fm::cli {

struct SearchArgs {
    std::string method = "cmaes";
    std::string similarity = "gncc";
    std::uint64_t seed = 1;
    int budget = 0;         // global search evaluations (0: not given, the default)
    int polishBudget = -1;  // per polish level (-1: not given, the default)
    std::string levels;     // e.g. "4,2" (empty = the default)
    std::string radius;     // "t" or "u,v,depth,az,el,rot" (empty = the default)
    int threads = 0;
    std::string values = "auto";  // auto (as the app: HU -> mu, else raw), mu or raw
    std::string polish = "nm";    // local refinement method
};

// --method, --similarity, --seed, --budget, --polish-budget, --levels, --radius, --threads,
// --values.
void addSearchOptions(CLI::App* cmd, SearchArgs& args, bool withMethod = true);
// `base` (the mode's defaults) with what the options set: the similarity, method, seed and
// threads always, budgets, levels and radius when given. Throws fm::Error naming the option
// on a bad value.
RegistrationSettings registrationSettings(const SearchArgs& args, RegistrationSettings base = {});
// The whole-CT scene (register / evaluate without --bone): coarse levels trace block means of
// the CT, and levels finer than its voxels are left out unless --levels names the levels.
void useWholeCtSpeedups(RegistrationSettings& settings, const SearchArgs& args);
std::string describeLevels(const RegistrationSettings& settings);

// "auto": decided by the unit detection (cli/ValuesChoice, printed); "mu": HU converted to
// attenuation (what a CT needs; air becomes 0); "raw": values as stored.
DrrVolumePtr prepareForSearch(const Volume& volume, const std::string& values = "auto");
// A full-resolution line-integral DRR (the synthetic reference).
Image renderReference(const DrrVolume& volume, const ProjectionGeometry& geometry, int threads = 0);
// .png (8 or 16 bit, grey or colour: converted to grey) or a 2-D MetaImage/NIfTI/NRRD file.
Image readReferenceImage(const std::string& path);

// --methods "mc,pso,..." (global methods only); fm::Error naming the option.
std::vector<SearchMethod> parseMethodList(const std::string& text);
// The evaluation CSV, one row per registration, rewritten whole and atomically: the header
// before any work (a path that cannot be written fails now, not after the run), then at most
// once a second while trials finish (an interrupted run keeps complete rows), and at the end.
// A pipe or device gets the whole file once, at the end. An empty path writes nothing.
class EvaluationCsv {
  public:
    explicit EvaluationCsv(std::string path);
    void add(const EvaluationTrial& t, const EvaluationSettings& settings);
    void finish();  // the final write, and "wrote PATH" on stdout

  private:
    void save();
    std::string path_;
    bool saveOften_ = false;
    std::ostringstream rows_;
    std::chrono::steady_clock::time_point lastSave_;
};
// The two summary tables of an evaluation on stdout.
void printEvaluationSummary(const std::vector<EvaluationTrial>& trials,
                            const EvaluationSettings& settings);
// "registration 3/40 (cmaes)" on stderr (every 10th when not a terminal).
void reportTrial(const EvaluationTrial& t, int done, int total, bool interactive);

// "[#####.....]  52%  level 1/2 polish  evals 480/900  cost -0.9712" on stderr, \r-updated
// at most every 0.1 s when `interactive`, otherwise one line per stage.
class ProgressBar {
  public:
    explicit ProgressBar(bool interactive) : interactive_(interactive) {}
    void update(const RegistrationProgress& p);
    void finish();

  private:
    bool interactive_;
    double lastShown_ = -1.0;
    std::string lastStage_;
    bool drawn_ = false;
};

}  // namespace fm::cli
