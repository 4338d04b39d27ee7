#include "renderer/params/style_program.hpp"

#include <regex>
#include <sstream>
#include <stdexcept>

namespace tlab::render {

namespace {

const char* const kCodeMarker = "// TLAB_STYLE_CODE";
// tlab's own lines are numbered from here, so an error's line says whose code it is in even where
// a driver ignores #line's source-string number.
constexpr int kTlabLines = 1000000;

const char* glslType(StyleValueType type) {
  switch (type) {
    case StyleValueType::Int: return "int";
    case StyleValueType::Bool: return "bool";
    case StyleValueType::Float: break;
  }
  return "float";
}

}  // namespace

std::string assembleStyleSource(const StyleProgram& style, std::string_view mainFile, const gpu::ShaderDefines& defines) {
  const std::string frame = gpu::preprocessShader(mainFile, defines);
  const auto marker = frame.find(kCodeMarker);
  if (marker == std::string::npos) throw std::logic_error(std::string(mainFile) + " has no " + kCodeMarker + " line");
  std::string code;
  for (const auto& u : style.uniforms) code += std::string("uniform ") + glslType(u.type) + " " + u.name + ";\n";
  // Source string 1 is the user's file, so the compiler's log names its lines; tlab's code before
  // and after it has lines above kTlabLines.
  code += "#line 1 1\n" + style.text + "\n#line " + std::to_string(2 * kTlabLines) + " 2\n";
  std::string head = frame.substr(0, marker);
  const auto lineTwo = head.find("\n#line 2\n");  // preprocessShader's, after the defines
  if (lineTwo != std::string::npos) head.replace(lineTwo, 9, "\n#line " + std::to_string(kTlabLines) + " 0\n");
  return head + code + frame.substr(frame.find('\n', marker) + 1);
}

std::string mapStyleCompileLog(const std::string& path, const std::string& log) {
  // Mesa: "1:12(5): error: message"; NVIDIA: "1(12) : error C1008: message".
  static const std::regex mesa(R"(^\s*(\d+):(\d+)\(\d+\):\s*error:\s*(.*)$)");
  static const std::regex nvidia(R"(^\s*(\d+)\((\d+)\)\s*:\s*error\s*\w*:\s*(.*)$)");
  std::istringstream in(log);
  std::string line;
  while (std::getline(in, line)) {
    std::smatch m;
    if (!std::regex_match(line, m, mesa) && !std::regex_match(line, m, nvidia)) continue;
    const bool inUserFile = m[1] == "1" || (m[1] == "0" && std::stol(m[2]) < kTlabLines);
    return path + ":" + (inUserFile ? m[2].str() : "1") + ": " + m[3].str() +
           (inUserFile ? "" : " (in tlab's code around the style: does the file define what its stage calls?)");
  }
  std::string oneLine = log;
  for (char& c : oneLine)
    if (c == '\n') c = ' ';
  return path + ":1: GLSL does not compile: " + oneLine;
}

const gpu::ShaderProgram& StyleProgram::compile(gpu::ShaderCache& shaders, std::string_view mainFile,
                                                const gpu::ShaderDefines& defines) const {
  std::string key = std::string(mainFile) + "|" + path + "|" + sha256;
  for (const auto& u : uniforms) key += "|" + u.name;
  for (const auto& [n, v] : defines) key += "|" + n + "=" + v;
  try {
    return shaders.computeFromSource(key, assembleStyleSource(*this, mainFile, defines), path);
  } catch (const gpu::ShaderCompileError& e) {
    throw std::invalid_argument(mapStyleCompileLog(path, e.log()));
  }
}

void StyleProgram::setUniforms(const gpu::ShaderProgram& program) const {
  for (const auto& u : uniforms) {
    const GLint at = program.uniform(u.name.c_str());
    if (at < 0) continue;  // declared but unused: the compiler removed it
    if (u.type == StyleValueType::Float) glUniform1f(at, static_cast<float>(u.value));
    else glUniform1i(at, static_cast<GLint>(u.value));
  }
}

}  // namespace tlab::render
