#pragma once
// A linked GLSL program from two shaders embedded from shaders/*.glsl.
#include <string>

#include <glm/glm.hpp>

#include "platform/Gl.h"

namespace fm::render {

// The text of shaders/<name> (embedded at build time), or nullptr.
const char* embeddedShader(const char* name);

class ShaderProgram {
  public:
    ShaderProgram() = default;
    // Compiles shaders/<vertexName> and shaders/<fragmentName>; throws fm::Error with the GL log.
    ShaderProgram(const char* vertexName, const char* fragmentName);
    ~ShaderProgram();
    ShaderProgram(ShaderProgram&& other) noexcept : id_(other.id_) { other.id_ = 0; }
    ShaderProgram& operator=(ShaderProgram&& other) noexcept;
    ShaderProgram(const ShaderProgram&) = delete;
    ShaderProgram& operator=(const ShaderProgram&) = delete;

    void use() const { glUseProgram(id_); }
    void set(const char* name, const glm::mat4& m) const;
    void set(const char* name, const glm::vec3& v) const;
    void set(const char* name, float f) const;
    void set(const char* name, int i) const;
    GLuint id() const { return id_; }

  private:
    GLuint id_ = 0;
};

}  // namespace fm::render
