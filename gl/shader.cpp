#include "gl/shader.h"

#include <glm/gtc/type_ptr.hpp>
#include <vector>

#include "tsis_shared.h"
#include "util/embedded.h"
#include "util/error.h"

namespace tsis {

namespace {

// Fails with `what` and the object's info log unless its `status` (a compile
// or link status) is true.
template <typename GetIv, typename GetLog>
void requireStatus(GLuint object, GLenum status, GetIv getIv, GetLog getLog,
                   const std::string& what) {
    GLint ok = 0;
    getIv(object, status, &ok);
    if (ok) return;
    GLint len = 0;
    getIv(object, GL_INFO_LOG_LENGTH, &len);
    std::vector<char> log(static_cast<size_t>(len) + 1);
    getLog(object, len, nullptr, log.data());
    checkFailed(__FILE__, __LINE__, concat(what, " failed:\n", log.data()));
}

#define TSIS_TEXT(x) #x
#define TSIS_LITERAL(x) TSIS_TEXT(x)

GLuint compile(GLenum stage, const std::string& file, const std::string& defines) {
    std::string src = "#version 450 core\n";
    src += "#define MAX_LIGHTS " + std::to_string(TSIS_MAX_LIGHTS) + "\n";
    // The luminance weights as the host's (float literals, 'f' and all).
    src += "#define LUMA vec3(" TSIS_LITERAL(TSIS_LUMA_R) ", " TSIS_LITERAL(
        TSIS_LUMA_G) ", " TSIS_LITERAL(TSIS_LUMA_B) ")\n";
    src += defines;
    src += embeddedText(embeddedShaders(), "common.glsl");
    src += "\n#line 1 1\n";  // messages: source string 1 = the stage's own file
    src += embeddedText(embeddedShaders(), file);
    GLuint s = glCreateShader(stage);
    const char* text = src.c_str();
    glShaderSource(s, 1, &text, nullptr);
    glCompileShader(s);
    requireStatus(s, GL_COMPILE_STATUS, glGetShaderiv, glGetShaderInfoLog,
                  "GLSL compile of " + file);
    return s;
}

}  // namespace

ShaderProgram::ShaderProgram(const std::string& vertexFile, const std::string& fragmentFile,
                             const std::string& defines)
    : name_(vertexFile + "+" + fragmentFile) {
    GLuint vs = compile(GL_VERTEX_SHADER, vertexFile, defines);
    GLuint fs = compile(GL_FRAGMENT_SHADER, fragmentFile, defines);
    id_ = glCreateProgram();
    glAttachShader(id_, vs);
    glAttachShader(id_, fs);
    glLinkProgram(id_);
    glDeleteShader(vs);
    glDeleteShader(fs);
    requireStatus(id_, GL_LINK_STATUS, glGetProgramiv, glGetProgramInfoLog,
                  "GLSL link of " + name_);
}

ShaderProgram::~ShaderProgram() {
    if (id_) glDeleteProgram(id_);
}

GLint ShaderProgram::location(const char* name) const {
    return glGetUniformLocation(id_, name);
}
void ShaderProgram::set(const char* name, int v) const {
    glProgramUniform1i(id_, location(name), v);
}
void ShaderProgram::set(const char* name, float v) const {
    glProgramUniform1f(id_, location(name), v);
}
void ShaderProgram::set(const char* name, const glm::vec2& v) const {
    glProgramUniform2fv(id_, location(name), 1, glm::value_ptr(v));
}
void ShaderProgram::set(const char* name, const glm::vec3& v) const {
    glProgramUniform3fv(id_, location(name), 1, glm::value_ptr(v));
}
void ShaderProgram::set(const char* name, const glm::mat3& m) const {
    glProgramUniformMatrix3fv(id_, location(name), 1, GL_FALSE, glm::value_ptr(m));
}

void ShaderProgram::set(const char* name, const glm::mat4& m) const {
    glProgramUniformMatrix4fv(id_, location(name), 1, GL_FALSE, glm::value_ptr(m));
}

ShaderVariants::ShaderVariants(std::string vertexFile, std::string fragmentFile,
                               std::vector<std::string> features, std::string defines)
    : vertexFile_(std::move(vertexFile)),
      fragmentFile_(std::move(fragmentFile)),
      defines_(std::move(defines)),
      features_(std::move(features)) {
    TSIS_CHECK_LE(features_.size(), size_t(16));
}

const ShaderProgram& ShaderVariants::get(unsigned on) {
    std::unique_ptr<ShaderProgram>& p = programs_[on];
    if (!p) {
        std::string defines = defines_;
        for (size_t i = 0; i < features_.size(); ++i)
            defines += "#define " + features_[i] + ((on >> i) & 1u ? " 1\n" : " 0\n");
        p = std::make_unique<ShaderProgram>(vertexFile_, fragmentFile_, defines);
    }
    return *p;
}

}  // namespace tsis
