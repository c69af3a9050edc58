#include "render/Shader.h"

#include <glm/gtc/type_ptr.hpp>

#include "core/Error.h"

namespace fm::render {
namespace {

GLuint compile(GLenum type, const char* name) {
    const char* text = embeddedShader(name);
    if (!text)
        throw Error(std::string("shader shaders/") + name + " is not embedded in the binary");
    const GLuint shader = glCreateShader(type);
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[2048] = {};
        glGetShaderInfoLog(shader, sizeof(log), nullptr, log);
        glDeleteShader(shader);
        throw Error(std::string("shaders/") + name + " does not compile: " + log);
    }
    return shader;
}

}  // namespace

ShaderProgram::ShaderProgram(const char* vertexName, const char* fragmentName) {
    const GLuint vs = compile(GL_VERTEX_SHADER, vertexName);
    const GLuint fs = compile(GL_FRAGMENT_SHADER, fragmentName);
    id_ = glCreateProgram();
    glAttachShader(id_, vs);
    glAttachShader(id_, fs);
    glLinkProgram(id_);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(id_, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[2048] = {};
        glGetProgramInfoLog(id_, sizeof(log), nullptr, log);
        throw Error(std::string("shaders ") + vertexName + " + " + fragmentName +
                    " do not link: " + log);
    }
}

ShaderProgram::~ShaderProgram() {
    if (id_) glDeleteProgram(id_);
}

ShaderProgram& ShaderProgram::operator=(ShaderProgram&& other) noexcept {
    if (this != &other) {
        if (id_) glDeleteProgram(id_);
        id_ = other.id_;
        other.id_ = 0;
    }
    return *this;
}

void ShaderProgram::set(const char* name, const glm::mat4& m) const {
    glUniformMatrix4fv(glGetUniformLocation(id_, name), 1, GL_FALSE, glm::value_ptr(m));
}
void ShaderProgram::set(const char* name, const glm::vec3& v) const {
    glUniform3fv(glGetUniformLocation(id_, name), 1, glm::value_ptr(v));
}
void ShaderProgram::set(const char* name, float f) const {
    glUniform1f(glGetUniformLocation(id_, name), f);
}
void ShaderProgram::set(const char* name, int i) const {
    glUniform1i(glGetUniformLocation(id_, name), i);
}

}  // namespace fm::render
