#include "bones/LabelTable.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "bones/LabelMap.h"
#include "core/Error.h"
#include "core/StrictJson.h"
#include "io/ByteSource.h"

namespace fm {
namespace {

std::string trim(const std::string& s) {
    std::size_t b = 0, e = s.size();
    while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
    while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
    return s.substr(b, e - b);
}

// A whole number 1..kMaxLabel, or nothing.
bool parseLabelNumber(const std::string& text, int& out) {
    const std::string t = trim(text);
    if (t.empty()) return false;
    long long value = 0;
    const auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
    if (ec != std::errc() || ptr != t.data() + t.size()) return false;
    if (value < 1 || value > kMaxLabel) return false;
    out = static_cast<int>(value);
    return true;
}

void addEntry(LabelTable& table, const std::string& name, long long label,
              const std::string& what, const std::string& where) {
    if (name.empty()) throw Error(what + ": " + where + ": empty label name");
    if (name.find('+') != std::string::npos)
        throw Error(what + ": " + where + ": the name \"" + name +
                    "\" holds '+', which joins labels in --bone");
    if (label < 1 || label > kMaxLabel)
        throw Error(what + ": " + where + ": label " + std::to_string(label) + " of \"" + name +
                    "\" is outside 1.." + std::to_string(kMaxLabel));
    for (const LabelEntry& e : table.entries) {
        if (e.name == name) throw Error(what + ": " + where + ": the name \"" + name +
                                        "\" is given twice");
        if (e.label == label)
            throw Error(what + ": " + where + ": label " + std::to_string(label) +
                        " is named twice (\"" + e.name + "\" and \"" + name + "\")");
    }
    table.entries.push_back({name, static_cast<int>(label)});
}

LabelTable parseJson(const std::string& text, const std::string& what) {
    // Strict: {"femur_left": 1, "femur_left": 2} is refused, not read as its last entry.
    const nlohmann::json j = parseStrictJson(text, what);
    LabelTable table;
    auto number = [&](const nlohmann::json& v, const std::string& where) -> long long {
        if (!v.is_number_integer())
            throw Error(what + ": " + where + ": the label must be a whole number");
        return v.get<long long>();
    };
    if (j.is_object()) {
        for (auto it = j.begin(); it != j.end(); ++it)
            addEntry(table, it.key(), number(it.value(), "\"" + it.key() + "\""), what,
                     "\"" + it.key() + "\"");
    } else if (j.is_array()) {
        for (std::size_t n = 0; n < j.size(); ++n) {
            const std::string where = "entry " + std::to_string(n);
            const auto& e = j[n];
            if (!e.is_object() || !e.contains("name") || !e.contains("label") ||
                !e["name"].is_string())
                throw Error(what + ": " + where + ": needs {\"name\": text, \"label\": number}");
            addEntry(table, e["name"].get<std::string>(), number(e["label"], where), what, where);
        }
    } else {
        throw Error(what + ": expected an object {name: label} or an array of {name, label}");
    }
    return table;
}

LabelTable parseCsv(const std::string& text, const std::string& what) {
    LabelTable table;
    std::istringstream in(text);
    std::string line;
    int lineNo = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        const std::string t = trim(line);
        if (t.empty() || t[0] == '#') continue;
        const std::string where = "line " + std::to_string(lineNo);
        const auto comma = t.find(',');
        if (comma == std::string::npos)
            throw Error(what + ": " + where + ": expected \"label,name\", got \"" + t + "\"");
        const std::string first = trim(t.substr(0, comma));
        const std::string name = trim(t.substr(comma + 1));
        if (table.entries.empty() && first == "label") continue;  // header
        long long value = 0;
        const auto [ptr, ec] = std::from_chars(first.data(), first.data() + first.size(), value);
        if (first.empty() || ec != std::errc() || ptr != first.data() + first.size())
            throw Error(what + ": " + where + ": \"" + first + "\" is not a label number");
        addEntry(table, name, value, what, where);
    }
    if (table.entries.empty()) throw Error(what + ": no labels in the table");
    return table;
}

std::string knownNames(const LabelTable& table) {
    if (table.entries.empty()) return "no label table given: use label numbers";
    std::string s = "known names:";
    for (const LabelEntry& e : table.entries)
        s += " " + e.name + " (" + std::to_string(e.label) + ")";
    return s;
}

}  // namespace

const LabelEntry* LabelTable::find(const std::string& name) const {
    for (const LabelEntry& e : entries)
        if (e.name == name) return &e;
    return nullptr;
}

std::string LabelTable::nameOf(int label) const {
    for (const LabelEntry& e : entries)
        if (e.label == label) return e.name;
    return "label " + std::to_string(label);
}

LabelTable parseLabelTable(const std::string& text, const std::string& what) {
    // A UTF-8 byte-order mark (spreadsheet exports write one) is not part of the table.
    const std::string t = trim(text.rfind("\xEF\xBB\xBF", 0) == 0 ? text.substr(3) : text);
    if (t.empty()) throw Error(what + ": empty label table");
    return (t[0] == '{' || t[0] == '[') ? parseJson(t, what) : parseCsv(t, what);
}

LabelTable readLabelTable(const std::string& path) {
    io::fileSize(path);  // names a missing file, a folder or a device as such
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error("label table " + path + ": cannot open the file");
    constexpr std::streamsize kMaxBytes = 1 << 20;  // a table of names, not a data file
    std::string text(static_cast<std::size_t>(kMaxBytes) + 1, '\0');
    in.read(text.data(), kMaxBytes + 1);
    if (in.gcount() > kMaxBytes) throw Error("label table " + path + ": larger than 1 MiB");
    text.resize(static_cast<std::size_t>(in.gcount()));
    return parseLabelTable(text, "label table " + path);
}

bool BoneSelection::has(int label) const {
    return std::binary_search(labels.begin(), labels.end(), label);
}

BoneSelection resolveBone(const std::string& spec, const LabelTable& table) {
    BoneSelection bone;
    bone.name = trim(spec);
    if (bone.name.empty()) throw Error("--bone: empty bone name");
    std::set<int> labels;
    std::size_t start = 0;
    while (start <= spec.size()) {
        const std::size_t plus = std::min(spec.find('+', start), spec.size());
        const std::string part = trim(spec.substr(start, plus - start));
        int number = 0;
        if (const LabelEntry* e = table.find(part))
            labels.insert(e->label);
        else if (parseLabelNumber(part, number))
            labels.insert(number);
        else
            throw Error("bone \"" + part + "\": not a label name or a number 1.." +
                        std::to_string(kMaxLabel) + "; " + knownNames(table));
        start = plus + 1;
    }
    bone.labels.assign(labels.begin(), labels.end());
    return bone;
}

void requireVoxels(const BoneSelection& bone, const Volume& labels, const std::string& what) {
    for (float v : labels.values)
        if (v != 0.0f && bone.has(static_cast<int>(v))) return;
    std::string list;
    for (int l : bone.labels) list += (list.empty() ? "" : ", ") + std::to_string(l);
    throw Error("bone \"" + bone.name + "\" (label " + list + ") has no voxel in " + what +
                ": an empty label, or a label table naming labels this map does not have");
}

}  // namespace fm
