// libtlab_documents.so: C entry points around the poppler and libxml2 readers (document_module.hpp).
#include "analysis/document_module.hpp"

#include <cstdlib>
#include <cstring>
#include <exception>

namespace {

char* copy(const std::string& s) {
  char* p = static_cast<char*>(std::malloc(s.size() + 1));
  if (p) std::memcpy(p, s.c_str(), s.size() + 1);
  return p;
}

template <typename Read>
int run(Read read, char** text, char** error) {
  try {
    const std::string out = read();
    *text = copy(out);
    return 0;
  } catch (const std::exception& e) {
    *error = copy(e.what());
    return 1;
  }
}

}  // namespace

extern "C" {
__attribute__((visibility("default"))) int tlab_documents_pdf(const char* path, char** text, char** error) {
  return run([&] { return tlab::analysis::pdfTextWithPoppler(path); }, text, error);
}

__attribute__((visibility("default"))) int tlab_documents_html(const char* html, std::size_t size, const char* source, char** text,
                                                               char** error) {
  return run([&] { return tlab::analysis::htmlTextWithLibxml2(std::string_view(html, size), source); }, text, error);
}

__attribute__((visibility("default"))) void tlab_documents_free(char* p) { std::free(p); }
}
