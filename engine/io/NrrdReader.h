#pragma once
// NRRD (.nrrd with attached data, .nhdr with detached data files): encodings raw, gzip and
// ascii; either byte order; every scalar type name and synonym of the NRRD0004/5 format;
// spacings or space directions + space origin; spaces RAS/LAS/LPS (converted to our LPS frame)
// and scanner-xyz / 3D-right-handed / 3D-left-handed (taken as LPS: they name no patient
// axes); line skip and byte skip (-1 for raw: data at the end of the file); data file as one
// name, a "pattern min max step [subdim]" list, or LIST.
#include <filesystem>

#include "volume/Volume.h"

namespace fm {

Volume readNrrd(const std::filesystem::path& path);

}  // namespace fm
