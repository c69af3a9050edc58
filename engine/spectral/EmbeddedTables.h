#pragma once
// The physics tables of data/xray/ built into the binary (engine/CMakeLists.txt generates the
// definition with engine/EmbedTextFiles.cmake), so the engine needs no data folder at run time.
#include <string>

#include "core/Error.h"

namespace fm {

// The text of data/xray/<name>, or nullptr (generated).
const char* embeddedXrayFile(const char* name);

// The same; fm::Error for a name that is not built in.
inline const char* embeddedXrayTable(const char* name) {
    const char* text = embeddedXrayFile(name);
    if (!text) throw Error(std::string("no built-in table data/xray/") + name);
    return text;
}

}  // namespace fm
