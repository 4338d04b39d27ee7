#include "renderer/gpu/shader_program.hpp"

#include <sstream>

#include "renderer/gpu/gl_error.hpp"

namespace tlab::gpu {

namespace {

void expandIncludes(std::string_view file, std::string& out, int depth) {
  if (depth > 8) throw GlError("shader " + std::string(file) + ": #include nested too deeply");
  std::istringstream in{std::string(embeddedShader(file))};
  std::string line;
  int lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    const auto pos = line.find("#include");
    if (pos != std::string::npos && line.find_first_not_of(" \t") == pos) {
      const auto a = line.find('"');
      const auto b = line.rfind('"');
      if (a == std::string::npos || b <= a)
        throw GlError("shader " + std::string(file) + ":" + std::to_string(lineNo) + ": malformed #include");
      expandIncludes(line.substr(a + 1, b - a - 1), out, depth + 1);
      continue;
    }
    out += line;
    out += '\n';
  }
}

ShaderName compileSource(GLenum stage, const std::string& source, std::string_view file) {
  ShaderName shader(glCreateShader(stage));
  const char* text = source.c_str();
  glShaderSource(shader.id(), 1, &text, nullptr);
  glCompileShader(shader.id());
  GLint ok = 0;
  glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetShaderiv(shader.id(), GL_INFO_LOG_LENGTH, &len);
    std::string log(static_cast<std::size_t>(len > 1 ? len : 1), '\0');
    glGetShaderInfoLog(shader.id(), len, nullptr, log.data());
    while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
    std::string oneLine = log;
    for (char& c : oneLine)
      if (c == '\n') c = ' ';
    throw ShaderCompileError("shader " + std::string(file) + " failed to compile: " + oneLine, log);
  }
  return shader;
}

ShaderName compileStage(GLenum stage, std::string_view file, const ShaderDefines& defines) {
  return compileSource(stage, preprocessShader(file, defines), file);
}

ProgramName link(std::initializer_list<GLuint> shaders, std::string_view what) {
  ProgramName program(glCreateProgram());
  for (GLuint s : shaders) glAttachShader(program.id(), s);
  glLinkProgram(program.id());
  GLint ok = 0;
  glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint len = 0;
    glGetProgramiv(program.id(), GL_INFO_LOG_LENGTH, &len);
    std::string log(static_cast<std::size_t>(len > 1 ? len : 1), '\0');
    glGetProgramInfoLog(program.id(), len, nullptr, log.data());
    while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
    for (char& c : log)
      if (c == '\n') c = ' ';
    throw GlError("shader program " + std::string(what) + " failed to link: " + log);
  }
  for (GLuint s : shaders) glDetachShader(program.id(), s);
  return program;
}

}  // namespace

std::string preprocessShader(std::string_view file, const ShaderDefines& defines) {
  std::string expanded;
  expandIncludes(file, expanded, 0);
  // Defines go right after the #version line, which must stay first.
  const auto eol = expanded.find('\n');
  if (expanded.rfind("#version", 0) != 0 || eol == std::string::npos)
    throw GlError("shader " + std::string(file) + ": first line must be #version");
  std::string head = expanded.substr(0, eol + 1);
  for (const auto& [name, value] : defines) head += "#define " + name + " " + value + "\n";
  head += "#line 2\n";
  return head + expanded.substr(eol + 1);
}

ShaderProgram ShaderProgram::graphics(std::string_view vertexFile, std::string_view fragmentFile,
                                      const ShaderDefines& defines) {
  ShaderName vs = compileStage(GL_VERTEX_SHADER, vertexFile, defines);
  ShaderName fs = compileStage(GL_FRAGMENT_SHADER, fragmentFile, defines);
  ShaderProgram p;
  p.program_ = link({vs.id(), fs.id()}, std::string(vertexFile) + " + " + std::string(fragmentFile));
  return p;
}

ShaderProgram ShaderProgram::compute(std::string_view computeFile, const ShaderDefines& defines) {
  ShaderName cs = compileStage(GL_COMPUTE_SHADER, computeFile, defines);
  ShaderProgram p;
  p.program_ = link({cs.id()}, computeFile);
  return p;
}

ShaderProgram ShaderProgram::computeFromSource(const std::string& source, std::string_view what) {
  ShaderName cs = compileSource(GL_COMPUTE_SHADER, source, what);
  ShaderProgram p;
  p.program_ = link({cs.id()}, what);
  return p;
}

ShaderDefines joined(ShaderDefines a, const ShaderDefines& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

}  // namespace tlab::gpu
