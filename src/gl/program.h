// A GLSL 1.20 program built from files in glsl120/. The loader resolves
// `#include "file"` lines (shared helpers are included, never copied) and inserts
// `#define`s after the #version line, so one file serves several variants.
#pragma once
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gl/gl.h"

namespace dsr {

// Reads `dir/name`, expanding #include "x" (relative to dir) recursively.
// Throws dsr::Error naming file and line for a missing include.
std::string load_shader_source(const std::string& dir, const std::string& name);

class Program {
public:
    Program() = default;
    Program(const std::string& dir, const std::string& vert, const std::string& frag,
            const std::vector<std::string>& defines = {});
    ~Program();
    Program(Program&& o) noexcept { *this = std::move(o); }
    Program& operator=(Program&& o) noexcept;
    Program(const Program&) = delete;
    Program& operator=(const Program&) = delete;

    // Binds it through the state cache (gl/state.h), so the cache knows the bound program.
    void use() const;
    GLuint id() const { return id_; }
    // Programs built so far in this process (tests: resizing must not rebuild any).
    static long long built() { return built_; }
    const std::string& name() const { return name_; }

    // Setters on the current program; a uniform the compiler removed is ignored.
    void set(const char* name, int v);
    void set(const char* name, float v);
    void set(const char* name, glm::vec2 v);
    void set(const char* name, glm::vec3 v);
    void set(const char* name, glm::vec4 v);
    // The first n elements of a uniform array (`uniform vec4 name[N]`).
    void set_array(const char* name, const glm::vec3* v, int n);
    void set_array(const char* name, const glm::vec4* v, int n);

private:
    static long long built_;
    GLint location(const char* name);
    GLuint id_ = 0;
    std::string name_;
    std::map<std::string, GLint, std::less<>> locations_;  // less<>: found by a const char* without a string made
};

}  // namespace dsr
