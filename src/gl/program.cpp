#include "gl/program.h"
#include "gl/state.h"

#include <fstream>
#include <sstream>
#include <utility>

#include "dsr_error.h"
#include "gl/caps.h"
#include "gl/glsl_dialect.h"

namespace dsr {

long long Program::built_ = 0;

void Program::use() const { gl_state().use_program(id_); }


static std::string expand(const std::string& dir, const std::string& name, int depth) {
    if (depth > 8) throw Error("shader include depth exceeded at " + name);
    std::string path = dir + "/" + name;
    std::ifstream in(path);
    if (!in) throw Error("cannot open shader " + path);
    std::ostringstream out;
    std::string line;
    int lineno = 0;
    while (std::getline(in, line)) {
        ++lineno;
        size_t p = line.find_first_not_of(" \t");
        if (p != std::string::npos && line.compare(p, 8, "#include") == 0) {
            size_t a = line.find('"', p), b = a == std::string::npos ? a : line.find('"', a + 1);
            if (b == std::string::npos)
                throw Error(path + ":" + std::to_string(lineno) + ": expected #include \"file\"");
            out << expand(dir, line.substr(a + 1, b - a - 1), depth + 1);
        } else {
            out << line << "\n";
        }
    }
    return out.str();
}

std::string load_shader_source(const std::string& dir, const std::string& name) { return expand(dir, name, 0); }

static std::string with_defines(std::string src, const std::vector<std::string>& defines) {
    if (defines.empty()) return src;
    std::string defs;
    for (auto& d : defines) defs += "#define " + d + "\n";
    size_t v = src.find("#version");
    size_t eol = v == std::string::npos ? 0 : src.find('\n', v) + 1;
    src.insert(eol, defs);
    return src;
}

static GLuint compile(GLenum type, const std::string& src, const std::string& label) {
    GLuint s = glCreateShader(type);
    const char* p = src.c_str();
    glShaderSource(s, 1, &p, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[4096] = {0};
        glGetShaderInfoLog(s, sizeof log, nullptr, log);
        glDeleteShader(s);
        throw Error("shader " + label + " does not compile:\n" + log);
    }
    return s;
}

// The current context's shader dialect (glsl_dialect.h): desktop GLSL, or GLSL ES 1.00 with the
// extensions this OpenGL ES offers.
static GlslDialect current_dialect() {
    GlslDialect d;
    d.es = current_gl_is_es();
    if (!d.es) return d;
    if (has_extension("GL_EXT_draw_buffers")) d.draw_buffers = "GL_EXT_draw_buffers";
    else if (has_extension("GL_NV_draw_buffers")) d.draw_buffers = "GL_NV_draw_buffers";
    d.frag_depth = has_extension("GL_EXT_frag_depth");
    d.shadow_samplers = has_extension("GL_EXT_shadow_samplers");
    return d;
}

Program::Program(const std::string& dir, const std::string& vert, const std::string& frag,
                 const std::vector<std::string>& defines) {
    name_ = vert + "+" + frag;
    for (auto& d : defines) name_ += " " + d;
    ++built_;
    const GlslDialect dialect = current_dialect();
    GLuint vs = compile(GL_VERTEX_SHADER,
                        glsl_in_dialect(with_defines(load_shader_source(dir, vert), defines), dialect, true, vert), vert);
    GLuint fs;
    try {
        fs = compile(GL_FRAGMENT_SHADER,
                     glsl_in_dialect(with_defines(load_shader_source(dir, frag), defines), dialect, false, frag), frag);
    } catch (...) {
        glDeleteShader(vs);
        throw;
    }
    id_ = glCreateProgram();
    glAttachShader(id_, vs);
    glAttachShader(id_, fs);
    // The prelude's attributes at fixed locations, so the drawing code feeds them without asking.
    if (dialect.es)
        for (const EsAttribute& a : es_attributes()) glBindAttribLocation(id_, a.location, a.glsl);
    glLinkProgram(id_);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(id_, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[4096] = {0};
        glGetProgramInfoLog(id_, sizeof log, nullptr, log);
        throw Error("program " + name_ + " does not link:\n" + log);
    }
}

Program::~Program() {
    if (id_) glDeleteProgram(id_);
}

Program& Program::operator=(Program&& o) noexcept {
    if (this != &o) {
        if (id_) glDeleteProgram(id_);
        id_ = std::exchange(o.id_, 0);
        name_ = std::move(o.name_);
        locations_ = std::move(o.locations_);
    }
    return *this;
}

GLint Program::location(const char* name) {
    auto it = locations_.find(name);
    if (it != locations_.end()) return it->second;
    GLint loc = glGetUniformLocation(id_, name);
    locations_[name] = loc;
    return loc;
}

void Program::set(const char* n, int v) { glUniform1i(location(n), v); }
void Program::set(const char* n, float v) { glUniform1f(location(n), v); }
void Program::set(const char* n, glm::vec2 v) { glUniform2f(location(n), v.x, v.y); }
void Program::set(const char* n, glm::vec3 v) { glUniform3f(location(n), v.x, v.y, v.z); }
void Program::set(const char* n, glm::vec4 v) { glUniform4f(location(n), v.x, v.y, v.z, v.w); }
void Program::set_array(const char* n, const glm::vec3* v, int count) { glUniform3fv(location(n), count, &v[0].x); }
void Program::set_array(const char* n, const glm::vec4* v, int count) { glUniform4fv(location(n), count, &v[0].x); }

}  // namespace dsr
