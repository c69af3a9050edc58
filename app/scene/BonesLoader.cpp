#include "scene/BonesLoader.h"

namespace fm::app {

void BonesLoader::start(std::uint64_t sceneGeneration, std::string what, Job job) {
    job_.start(
        what,
        [sceneGeneration, what, job = std::move(job)](const JobReport& report) {
            return Result{sceneGeneration, what, job(report), {}};
        },
        [sceneGeneration, what](const std::string& error) {
            return Result{sceneGeneration, what, nullptr,
                          error.empty() ? "unknown error while building the bones of " + what : error};
        });
}

}  // namespace fm::app
