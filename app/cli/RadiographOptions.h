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
    double i0 = 0.0;
    std::string excludeBelow;  // number; empty = keep every pixel
    int erode = 3;
    std::string roi;  // "x,y,w,h"
};

// Adds --invert, --log, --i0, --exclude-below, --erode, --roi.
void addRadiographOptions(CLI::App* cmd, RadiographOptions& options);

// The preparation the flags describe for a file of `bitsPerSample` (full scale 2^bits - 1).
// Throws fm::Error naming the flag for malformed values.
RadiographPreparation preparationFrom(const RadiographOptions& options, int bitsPerSample);

}  // namespace fm::cli
