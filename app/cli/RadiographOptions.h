#pragma once
// The radiograph preparation flags every command that compares against a real X-ray shares
// (radiograph, and registration against real images): one wording, one parser.
#include <string>

#include <CLI/CLI.hpp>

#include "radiograph/RadiographPreparation.h"

namespace fm::cli {

struct RadiographOptions {
    bool invert = false;
    bool log = false;
    std::string i0;  // number > 0; empty = the full scale
    std::string excludeBelow;  // number; empty = keep every pixel
    int erode = 3;
    bool erodeGiven = false;  // --erode was on the command line (a trial's own erosion otherwise)
    std::string roi;  // "x,y,w,h"
};

// Adds --invert, --log, --i0, --exclude-below, --erode, --roi.
void addRadiographOptions(CLI::App* cmd, RadiographOptions& options);

// --page: the 0-based page of a multi-page TIFF (-1 = not given).
void addPageOption(CLI::App* cmd, int& page, const std::string& help);
// --page applies to TIFF files only: refused (naming the file) for a PNG or JPEG.
void checkPageApplies(const std::string& image, int page);

// The preparation the flags describe for a file of `bitsPerSample` (full scale 2^bits - 1).
// Throws fm::Error naming the flag for malformed values.
RadiographPreparation preparationFrom(const RadiographOptions& options, int bitsPerSample);

}  // namespace fm::cli
