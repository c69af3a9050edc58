#pragma once
// The physics tables of data/xray/ built into the binary (engine/CMakeLists.txt generates the
// definition), so the engine needs no data folder at run time.

namespace fm {

// The text of data/xray/<name>; fm::Error for a name that is not there.
const char* embeddedXrayTable(const char* name);

}  // namespace fm
