// pdfText and htmlText through the document-reader module (document_module.hpp), opened once with
// dlopen from the folder of the running executable.
#include <dlfcn.h>
#include <unistd.h>

#include <filesystem>
#include <mutex>

#include "analysis/analysis_error.hpp"
#include "analysis/document_module.hpp"
#include "analysis/document_text.hpp"

namespace tlab::analysis {

namespace {

struct DocumentModule {
  void* handle = nullptr;
  decltype(&tlab_documents_pdf) pdf = nullptr;
  decltype(&tlab_documents_html) html = nullptr;
  decltype(&tlab_documents_free) release = nullptr;
  std::string error;
};

std::string executableFolder() {
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::string(".") : exe.parent_path().string();
}

DocumentModule load() {
  DocumentModule m;
  const std::string path = executableFolder() + "/libtlab_documents.so";
  m.handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!m.handle) {
    m.error = "reading PDF and HTML needs tlab's document reader " + path + " (poppler and libxml2), which cannot be loaded (" +
              dlerror() + "): use the tlab of a full build, or give the text as a .txt file";
    return m;
  }
  m.pdf = reinterpret_cast<decltype(m.pdf)>(dlsym(m.handle, "tlab_documents_pdf"));
  m.html = reinterpret_cast<decltype(m.html)>(dlsym(m.handle, "tlab_documents_html"));
  m.release = reinterpret_cast<decltype(m.release)>(dlsym(m.handle, "tlab_documents_free"));
  if (!m.pdf || !m.html || !m.release) m.error = path + ": not tlab's document reader (entry points missing)";
  return m;
}

const DocumentModule& module() {
  static const DocumentModule m = load();  // the one loaded library, like the GL libraries
  if (!m.error.empty()) throw AnalysisError(m.error);
  return m;
}

std::string take(const DocumentModule& m, int status, char* text, char* error) {
  const std::string out = status == 0 ? (text ? text : "") : (error ? error : "the document reader failed");
  m.release(text);
  m.release(error);
  if (status != 0) throw AnalysisError(out);
  return out;
}

}  // namespace

std::string pdfText(const std::string& path) {
  const DocumentModule& m = module();
  char *text = nullptr, *error = nullptr;
  const int status = m.pdf(path.c_str(), &text, &error);  // before take() reads text and error
  return take(m, status, text, error);
}

std::string htmlText(std::string_view html, const std::string& source) {
  const DocumentModule& m = module();
  char *text = nullptr, *error = nullptr;
  const int status = m.html(html.data(), html.size(), source.c_str(), &text, &error);
  return take(m, status, text, error);
}

}  // namespace tlab::analysis
