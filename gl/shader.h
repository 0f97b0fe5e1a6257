// GLSL programs built from the shader files under gl/shaders (embedded at build
// time). Every stage gets "#version 450 core" and gl/shaders/common.glsl first,
// so the Fresnel and shadow helpers exist once.
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "gl/gl.h"

namespace tsis {

class ShaderProgram {
  public:
    // defines: lines such as "#define X 1\n", placed before common.glsl in
    // both stages (a shader file's variants, instead of copies of it).
    ShaderProgram(const std::string& vertexFile, const std::string& fragmentFile,
                  const std::string& defines = "");
    ~ShaderProgram();
    ShaderProgram(const ShaderProgram&) = delete;
    ShaderProgram& operator=(const ShaderProgram&) = delete;

    void use() const { glUseProgram(id_); }
    GLint location(const char* name) const;  // -1 when optimised away
    void set(const char* name, int v) const;
    void set(const char* name, float v) const;
    void set(const char* name, const glm::vec2& v) const;
    void set(const char* name, const glm::vec3& v) const;
    void set(const char* name, const glm::mat3& m) const;
    void set(const char* name, const glm::mat4& m) const;

  private:
    GLuint id_ = 0;
    std::string name_;
};

// A shader pair compiled once per combination of on/off features, each a
// macro defined 0 or 1 (`#if TSIS_ENV`), on first use. llvmpipe runs both
// sides of every branch, masked, so a feature behind a uniform costs its
// lookups even where it is off; a variant without it does not have them.
class ShaderVariants {
  public:
    ShaderVariants(std::string vertexFile, std::string fragmentFile,
                   std::vector<std::string> features, std::string defines = "");
    // Bit i of `on`: features[i] on.
    const ShaderProgram& get(unsigned on);

  private:
    std::string vertexFile_, fragmentFile_, defines_;
    std::vector<std::string> features_;
    std::map<unsigned, std::unique_ptr<ShaderProgram>> programs_;
};

}  // namespace tsis
