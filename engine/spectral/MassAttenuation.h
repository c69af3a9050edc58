#pragma once
// Mass attenuation coefficients mu/rho (cm^2/g) of the materials a radiograph is made of, from
// NIST's tables (data/xray/nist_mass_attenuation.json, built into the binary; its "source"
// says where they come from): air, water, soft tissue and cortical bone (ICRU-44), aluminium
// (filters) and the implant metals (titanium, chromium, cobalt, molybdenum). Between the
// tabulated energies log-log interpolation, as the tables are meant to be read; an absorption
// edge (two rows of one energy) is kept sharp.
#include <string>
#include <utility>
#include <vector>

namespace fm {

struct MaterialTable {
    std::string name;            // "Water, Liquid", "Bone, Cortical (ICRU-44)", ...
    double densityGPerCm3 = 1.0;
    std::vector<double> energyKeV;
    std::vector<double> muRho;   // cm^2/g, at energyKeV

    // mu/rho at `keV` (1..200 keV); fm::Error outside the table.
    double muRhoAt(double keV) const;
    // The linear attenuation coefficient at `keV` in 1/mm for a density (g/cm^3).
    double muPerMmAt(double keV, double densityGPerCm3) const { return muRhoAt(keV) * densityGPerCm3 / 10.0; }
};

// "air", "water", "soft_tissue", "cortical_bone", "aluminium", "titanium", "chromium", "cobalt",
// "molybdenum", "iodine", "caesium". fm::Error naming the known ones otherwise.
const MaterialTable& materialTable(const std::string& key);

// A mixture by mass fractions (summing to 1): mu/rho = sum of w_i (mu/rho)_i on the union of the
// energy grids (the alloys of implants: no table holds them).
MaterialTable mixtureTable(const std::string& name, const std::vector<std::pair<std::string, double>>& fractions,
                           double densityGPerCm3);

// Cobalt-chromium-molybdenum implant alloy (ASTM F75: Co balance, Cr 27-30 %, Mo 5-7 %):
// Co 0.65, Cr 0.29, Mo 0.06 by mass, 8.3 g/cm^3.
const MaterialTable& cobaltChromeTable();

}  // namespace fm
