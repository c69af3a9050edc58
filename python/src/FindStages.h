#pragma once
// A find's stages (find/FindStage.h) as Python sees them, in `register`'s and `track`'s answers:
// one dict per stage, name, seconds (wall), evaluations (renders, placements or searches'
// evaluations, as the stage counts its work) and kept (what it hands on).
#include <vector>

#include <pybind11/pybind11.h>

#include "find/FindStage.h"

namespace fm::py {

inline pybind11::list findStagesList(const std::vector<FindStage>& stages) {
    pybind11::list out;
    for (const FindStage& s : stages) {
        pybind11::dict d;
        d["name"] = s.name;
        d["seconds"] = s.seconds;
        d["evaluations"] = s.evaluations;
        d["kept"] = s.kept;
        out.append(d);
    }
    return out;
}

}  // namespace fm::py
