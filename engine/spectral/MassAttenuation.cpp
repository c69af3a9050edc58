#include "spectral/MassAttenuation.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "core/Error.h"
#include "core/StrictJson.h"
#include "spectral/EmbeddedTables.h"

namespace fm {

namespace {

std::map<std::string, MaterialTable> loadTables() {
    const nlohmann::json root = parseStrictJson(embeddedXrayTable("nist_mass_attenuation.json"),
                                                "data/xray/nist_mass_attenuation.json");
    std::map<std::string, MaterialTable> tables;
    for (const auto& [key, m] : root.at("materials").items()) {
        MaterialTable t;
        t.name = m.at("name").get<std::string>();
        t.densityGPerCm3 = m.at("density_g_cm3").get<double>();
        t.energyKeV = m.at("energy_kev").get<std::vector<double>>();
        t.muRho = m.at("mu_rho_cm2_g").get<std::vector<double>>();
        tables.emplace(key, std::move(t));
    }
    return tables;
}

const std::map<std::string, MaterialTable>& tables() {
    static const std::map<std::string, MaterialTable> all = loadTables();
    return all;
}

}  // namespace

double MaterialTable::muRhoAt(double keV) const {
    if (energyKeV.empty() || !(keV >= energyKeV.front()) || !(keV <= energyKeV.back()))
        throw Error(name + ": no attenuation data at " + std::to_string(keV) + " keV (the table covers " +
                    (energyKeV.empty() ? std::string("nothing") : std::to_string(energyKeV.front()) + " to " +
                     std::to_string(energyKeV.back()) + " keV") + ")");
    // The first row above keV: at an edge (two rows of one energy) the energy itself reads the
    // row above the edge, just below it the row below.
    const auto above = std::upper_bound(energyKeV.begin(), energyKeV.end(), keV);
    if (above == energyKeV.end()) return muRho.back();
    const std::size_t i = static_cast<std::size_t>(above - energyKeV.begin());
    if (i == 0) return muRho.front();
    const double e0 = energyKeV[i - 1], e1 = energyKeV[i];
    if (keV == e0) return muRho[i - 1];
    const double s = std::log(keV / e0) / std::log(e1 / e0);
    return std::exp(std::log(muRho[i - 1]) + s * (std::log(muRho[i]) - std::log(muRho[i - 1])));
}

const MaterialTable& materialTable(const std::string& key) {
    const auto it = tables().find(key);
    if (it == tables().end()) {
        std::string known;
        for (const auto& [k, t] : tables()) known += (known.empty() ? "" : ", ") + k;
        throw Error("no attenuation table \"" + key + "\" (known: " + known + ")");
    }
    return it->second;
}

MaterialTable mixtureTable(const std::string& name, const std::vector<std::pair<std::string, double>>& fractions,
                           double densityGPerCm3) {
    double total = 0.0;
    std::set<double> grid;
    double low = 0.0, high = 1e9;
    for (const auto& [key, w] : fractions) {
        const MaterialTable& t = materialTable(key);
        if (!(w > 0.0)) throw Error(name + ": mass fraction of " + key + " must be positive");
        total += w;
        grid.insert(t.energyKeV.begin(), t.energyKeV.end());
        low = std::max(low, t.energyKeV.front());
        high = std::min(high, t.energyKeV.back());
    }
    if (std::abs(total - 1.0) > 1e-6) throw Error(name + ": mass fractions sum to " + std::to_string(total) + ", not 1");
    MaterialTable m;
    m.name = name;
    m.densityGPerCm3 = densityGPerCm3;
    for (double e : grid) {
        if (e < low || e > high) continue;
        double mu = 0.0;
        for (const auto& [key, w] : fractions) mu += w * materialTable(key).muRhoAt(e);
        m.energyKeV.push_back(e);
        m.muRho.push_back(mu);
    }
    return m;
}

const MaterialTable& cobaltChromeTable() {
    static const MaterialTable t =
        mixtureTable("CoCrMo (ASTM F75)", {{"cobalt", 0.65}, {"chromium", 0.29}, {"molybdenum", 0.06}}, 8.3);
    return t;
}

}  // namespace fm
