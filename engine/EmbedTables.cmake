# Writes OUT: a C++ source defining fm::embeddedXrayTable(name) over the files in FILES
# (data/xray/*.json), so the tables live as plain files in data/ while the binary needs none.
set(body "// Generated from data/xray/ by engine/EmbedTables.cmake. Do not edit.\n")
string(APPEND body "#include <cstring>\n#include <string>\n\n#include \"core/Error.h\"\n#include \"spectral/EmbeddedTables.h\"\n\nnamespace fm {\n\nconst char* embeddedXrayTable(const char* name) {\n")
foreach(file ${FILES})
    get_filename_component(name ${file} NAME)
    file(READ ${file} text)
    string(APPEND body "    if (std::strcmp(name, \"${name}\") == 0) return R\"fmtable(${text})fmtable\";\n")
endforeach()
string(APPEND body "    throw Error(std::string(\"no built-in table data/xray/\") + name);\n}\n\n}  // namespace fm\n")
file(WRITE ${OUT}.tmp "${body}")
file(COPY_FILE ${OUT}.tmp ${OUT} ONLY_IF_DIFFERENT)
