#pragma once
// What the MRI slice commands share (slice, geometry --slice, register --slice,
// evaluate --slice): the slice grid options, the display window of a masked slice, and the
// slice versions of register and evaluate (SliceRegisterCli.cpp). See docs/mri.md.
#include <string>

#include <CLI/CLI.hpp>

#include "cli/SearchCli.h"
#include "search/ConfirmedSearch.h"
#include "core/Image.h"
#include "similarity/Mask.h"
#include "slice/SliceGeometry.h"
#include "slice/SliceRegistration.h"
#include "volume/Volume.h"

namespace fm::cli {

struct SliceGridArgs {
    std::string size;     // "WxH" pixels; empty = defaultSliceSetup
    std::string spacing;  // "s" or "su,sv" mm; empty = defaultSliceSetup
    double thickness = 0.0;
};

// --spacing and --thickness (and --size when `withSize`; the geometry command has its own).
void addSliceGridOptions(CLI::App* cmd, SliceGridArgs& args, bool withSize = true);
// defaultSliceSetup(volume) with the options applied; fm::Error naming the option.
SliceSetup sliceSetupFrom(const SliceGridArgs& args, const Volume& volume);
// The same without a volume (geometry --slice --center): 256 x 256 pixels of 1 mm by default.
SliceSetup sliceSetupFrom(const SliceGridArgs& args);

// Display window of a slice: the 1st..99.5th percentile of its data pixels.
struct SliceWindow {
    double low = 0.0, high = 1.0;
};
SliceWindow sliceWindow(const Image& image, const Mask& mask);

// "the plane of pose ... misses the volume: the slice is empty (fully masked)".
std::string emptySliceMessage(const Pose& pose);

// register --slice / evaluate --slice: the arguments the X-ray commands parse, passed on.
struct SliceRegisterArgs {
    std::string volume, referencePose, reference, start, truth;
    bool similarityGiven = false;
    SliceGridArgs grid;
    std::string interpolation = "cubic";
    SearchArgs search;
    ConfirmationSettings confirmation;  // register's --runs, --max-runs
};
void runSliceRegister(const SliceRegisterArgs& args);

struct SliceEvaluateArgs {
    std::string volume, methods, truth;
    int starts = 10;
    std::string csv;
    bool similarityGiven = false;
    SliceGridArgs grid;
    std::string interpolation = "cubic";
    SearchArgs search;
};
void runSliceEvaluate(const SliceEvaluateArgs& args);

// The slice search settings from the shared search options (--similarity defaults to mi).
SliceRegistrationSettings sliceRegistrationSettings(const SearchArgs& args, bool similarityGiven,
                                                    const std::string& interpolation);

}  // namespace fm::cli
