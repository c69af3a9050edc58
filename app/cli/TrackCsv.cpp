#include "cli/TrackCsv.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <system_error>

#include "core/Error.h"
#include "io/ByteSource.h"
#include "io/HeaderText.h"
#include "io/TextFile.h"

namespace fm::cli {

std::string trackCsvHeader(std::size_t cameras) {
    std::string h = "frame,bone,status,cameras_used";
    for (std::size_t c = 0; c < cameras; ++c) h += ",cost_cam" + std::to_string(c + 1);
    // How sure each frame is: the verdict, the spread the images allow per coordinate of the
    // first taking camera's frame (inf: not fixed), the similarity against the last good frames.
    // The same spreads along the bone's own axes (its volume's x, y, z).
    return h + ",verdict,sd_u_mm,sd_v_mm,sd_depth_mm,sd_about_u_deg,sd_about_v_deg,sd_about_view_deg,"
               "sd_bone_x_mm,sd_bone_y_mm,sd_bone_z_mm,sd_about_bone_x_deg,sd_about_bone_y_deg,sd_about_bone_z_deg,"
               "similarity_ratio,searches,evaluations,time_ms,note\n";
}

std::string trackCsvRow(const FrameRecord& r, const std::string& bone) {
    char buf[64];
    std::string row = std::to_string(r.frame) + "," + bone + "," + toString(r.status) + "," +
                      std::to_string(r.camerasUsed);
    for (double c : r.viewCost) {
        std::snprintf(buf, sizeof buf, ",%.*f", kStoredCostDecimals, c);  // as storedCost keeps it
        row += std::isnan(c) ? std::string(",") : std::string(buf);
    }
    row += std::string(",") + (r.status == FrameRecord::Status::Tracked ? toString(r.verdict) : "lost");
    for (int i = 0; i < 12; ++i) {
        const double sd = !r.evidence.uncertainty ? 0.0 : i < 6 ? r.evidence.uncertainty->sd[i] : r.boneFrameSd[i - 6];
        std::snprintf(buf, sizeof buf, ",%.4g", sd);
        row += r.evidence.uncertainty ? std::string(buf) : std::string(",");
    }
    std::snprintf(buf, sizeof buf, ",%.4f", r.evidence.similarityRatio.value_or(0.0));
    row += r.evidence.similarityRatio ? std::string(buf) : std::string(",");
    row += "," + std::to_string(r.searches);
    std::snprintf(buf, sizeof buf, ",%d,%.1f,", r.evaluations, 1000.0 * r.seconds);
    std::string note = r.verdictText.empty() ? r.note : r.note + "; " + r.verdictText;
    if (r.found) note += "; not ok, then searched for with no start: " + *r.found;
    for (char& ch : note)
        if (ch == ',' || ch == '\n') ch = ';';
    return row + buf + note + "\n";
}

std::map<int, std::string> keptTrackCsvRows(const std::filesystem::path& csv, std::size_t cameras,
                                            const std::string& bone, const std::set<int>& kept) {
    std::map<int, std::string> rows;
    std::error_code ec;
    if (!std::filesystem::exists(csv, ec)) return rows;
    // A frame's row is short; 1 GiB of them is millions of frames, more than any trial.
    const std::string text = io::readTextFile(csv, std::size_t{1} << 30, "track CSV");
    std::istringstream in(text);
    std::string line;
    std::string header = trackCsvHeader(cameras);
    header.pop_back();
    const std::string where = "--resume: " + io::quoted(csv);
    if (!std::getline(in, line)) return rows;  // empty: the earlier run wrote nothing yet
    if (line != header)
        throw Error(where + ": its header \"" + line + "\" is not this run's \"" + header +
                    "\" (a CSV of another trial or camera set?)");
    const std::size_t fields = 22 + cameras;
    for (int number = 2; std::getline(in, line); ++number) {
        std::size_t commas = 0;
        for (char ch : line) commas += ch == ',' ? 1 : 0;
        const std::size_t first = line.find(','), second = line.find(',', first + 1);
        int frame = -1;
        if (commas + 1 == fields && first != std::string::npos && first > 0 && first <= 9 &&
            line.find_first_not_of("0123456789") == first)
            frame = std::stoi(line.substr(0, first));
        if (frame < 0)
            throw Error(where + ": line " + std::to_string(number) + " is not a row of " +
                        std::to_string(fields) + " fields starting with a frame number");
        if (line.substr(first + 1, second - first - 1) == bone && kept.count(frame) != 0)
            rows[frame] = line + "\n";
    }
    return rows;
}

FrameRecord keptFrameRecord(const std::string& row, std::size_t cameras, const std::string& where) {
    std::vector<std::string> fields;
    std::size_t begin = 0;
    for (std::size_t i = 0; i <= row.size(); ++i)
        if (i == row.size() || row[i] == ',' || row[i] == '\n') {
            fields.push_back(row.substr(begin, i - begin));
            begin = i + 1;
            if (i < row.size() && row[i] == '\n') break;
        }
    if (fields.size() < 5 + cameras) throw Error(where + ": a row of " + std::to_string(fields.size()) + " fields");
    FrameRecord r;
    r.frame = static_cast<int>(io::parseInteger(fields[0], where + ": frame"));
    const std::string at = where + ": frame " + fields[0] + ": ";
    const std::string& status = fields[2];
    bool known = false;
    for (FrameRecord::Status s : {FrameRecord::Status::Tracked, FrameRecord::Status::NoStart, FrameRecord::Status::NotInView,
                                  FrameRecord::Status::BadFrame, FrameRecord::Status::Stopped})
        if (status == toString(s)) {
            r.status = s;
            known = true;
        }
    if (!known) throw Error(at + "status '" + status + "' is not one this program writes");
    for (std::size_t c = 0; c < cameras; ++c) {
        const std::string& cost = fields[4 + c];
        r.viewCost.push_back(cost.empty() ? std::numeric_limits<double>::quiet_NaN()
                                          : io::parseFinite(cost, at + "cost_cam" + std::to_string(c + 1)));
    }
    const std::string& verdict = fields[4 + cameras];
    known = false;
    for (AnswerVerdict v : {AnswerVerdict::Ok, AnswerVerdict::Doubtful, AnswerVerdict::Lost})
        if (verdict == toString(v)) {
            r.verdict = v;
            known = true;
        }
    if (!known) throw Error(at + "verdict '" + verdict + "' is not ok, doubtful or lost");
    return r;
}

}  // namespace fm::cli
