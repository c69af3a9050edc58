# Writes OUT: a C++ source defining fm::render::embeddedShader(name) over the files in FILES,
# so shaders live as plain files in shaders/ while the binary stays self-contained.
set(body "// Generated from shaders/*.glsl by app/cmake/EmbedShaders.cmake. Do not edit.\n")
string(APPEND body "#include <cstring>\n\nnamespace fm::render {\n\nconst char* embeddedShader(const char* name) {\n")
foreach(file ${FILES})
    get_filename_component(name ${file} NAME)
    file(READ ${file} text)
    string(APPEND body "    if (std::strcmp(name, \"${name}\") == 0) return R\"fmglsl(${text})fmglsl\";\n")
endforeach()
string(APPEND body "    return nullptr;\n}\n\n}  // namespace fm::render\n")
file(WRITE ${OUT}.tmp "${body}")
file(COPY_FILE ${OUT}.tmp ${OUT} ONLY_IF_DIFFERENT)
