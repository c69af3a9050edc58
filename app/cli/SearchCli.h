#pragma once
// What `register` and `evaluate` share: the search options, preparing a volume for DRRs,
// rendering or reading the reference image, and the progress bar.
#include <string>

#include <CLI/CLI.hpp>

#include "core/Image.h"
#include "drr/Drr.h"
#include "search/Registration.h"
#include "volume/Volume.h"

namespace fm::cli {

struct SearchArgs {
    std::string method = "cmaes";
    std::string similarity;  // empty = the mode's default (gncc; edge for models)
    std::uint64_t seed = 1;
    int budget = 0;         // global search evaluations (0 = the default)
    int polishBudget = -1;  // per polish level (-1 = the default)
    std::string levels;     // e.g. "4,2" (empty = the default)
    std::string radius;     // "t" or "u,v,depth,az,el,rot" (empty = the default)
    int threads = 0;
    std::string values = "mu";
    std::string polish = "nm";  // local refinement method  // how voxel values become attenuation:
                                // mu (HU -> 1/mm) or raw
};

// --method, --similarity, --seed, --budget, --polish-budget, --levels, --radius, --threads,
// --values.
void addSearchOptions(CLI::App* cmd, SearchArgs& args, bool withMethod = true);
// `base` with what the options change. Throws fm::Error naming the option on a bad value.
RegistrationSettings registrationSettings(const SearchArgs& args, RegistrationSettings base = {});
std::string describeLevels(const RegistrationSettings& settings);

// "mu": HU converted to attenuation (what a CT needs; air becomes 0); "raw": values as stored.
DrrVolumePtr prepareForSearch(const Volume& volume, const std::string& values = "mu");
// A full-resolution line-integral DRR (the synthetic reference).
Image renderReference(const DrrVolume& volume, const ProjectionGeometry& geometry, int threads = 0);
// .png (8 or 16 bit, grey or colour: converted to grey) or a 2-D MetaImage/NIfTI/NRRD file.
Image readReferenceImage(const std::string& path);

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
