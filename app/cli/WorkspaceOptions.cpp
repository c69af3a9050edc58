#include "cli/WorkspaceOptions.h"

#include "cli/TrialPreparationOptions.h"
#include "cli/ValueChecks.h"
#include "core/Error.h"
#include "pose/AutoscoperTra.h"
#include "radiograph/Radiograph.h"

namespace fm::cli {

void addWorkspaceOptions(CLI::App* cmd, WorkspaceArgs& a, bool withOut) {
    cmd->add_option("--trial", a.trial, "Open the real X-ray workspace on a trial (.json or Autoscoper .cfg)");
    cmd->add_option("--reference", a.reference,
                    "Open the real X-ray workspace on one radiograph (with --camera and --model)");
    cmd->add_option("--camera", a.camera, "With --reference: its calibration (MayaCam, JT_INTCALIB, geometry JSON)");
    cmd->add_option("--model", a.models, "With --reference: an implant or bone model (.stl, .ply, .obj); repeatable");
    cmd->add_option("--start", a.starts, "With --reference: start poses (.jts or .tra row --frame, or six numbers)");
    cmd->add_option("--mask", a.masks, "With --reference: a label mask per model (the silhouette IoU is shown)");
    if (withOut)
        cmd->add_option("--out", a.out, "Where Save writes the poses (.tra for a trial; .jts or .tra for one radiograph)");
    cmd->add_option("--frame", a.frame, "A trial's frame to open at; with --reference: the row of --start files")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--tra-form", a.traForm,
                    "With --reference: how a --start .tra's numbers divide when their count does not "
                    "say: matrix or xyzypr")
        ->check(oneOf({"matrix", "xyzypr"}, ".tra form"));
    cmd->add_option("--mu", a.mu, "With --reference: the models' attenuation 1/mm (default 1.2, cobalt-chromium)");
    addRadiographOptions(cmd, a.prep);
}

bool wantsWorkspace(const WorkspaceArgs& a) { return !a.trial.empty() || !a.reference.empty(); }

app::WorkspaceSource workspaceSource(const WorkspaceArgs& a) {
    if (!a.trial.empty() && !a.reference.empty()) throw Error("give --trial or --reference, not both");
    app::WorkspaceSource s;
    s.out = a.out;
    if (!a.trial.empty()) {
        if (!a.camera.empty() || !a.models.empty() || !a.starts.empty() || !a.masks.empty())
            throw Error("--camera, --model, --start and --mask go with --reference (a trial names its own)");
        // The flags over the trial's preparation of every camera, as track takes them.
        s.trialOverride = preparationOverride(a.prep);
        s.trial = a.trial;
        return s;
    }
    s.reference = a.reference;
    s.camera = a.camera;
    for (const std::string& m : a.models) s.models.emplace_back(m);
    for (const std::string& m : a.masks) s.masks.emplace_back(m);
    s.starts = a.starts;
    s.startFrame = a.frame;
    s.muPerMm = a.mu;
    if (!a.traForm.empty()) s.traForm = parseTraForm(a.traForm, "--tra-form");
    s.preparation = preparationFrom(a.prep, readRadiograph(a.reference).bitsPerSample);
    return s;
}

}  // namespace fm::cli
