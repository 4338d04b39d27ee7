#pragma once
// The document-reader module, libtlab_documents.so: PDF through poppler and HTML through libxml2,
// loaded at run time (dlopen) from beside the tlab executable when statcheck first reads such a
// file. tlab itself does not link poppler, libxml2 or ICU (some 40 MiB), so the relocatable
// bundle for GPU servers stays small, and a tlab without the module reads plain text and says
// what is missing for PDF and HTML.
#include <cstddef>
#include <string>
#include <string_view>

namespace tlab::analysis {

// Inside the module (pdf_text.cpp, html_text.cpp); throw AnalysisError.
std::string pdfTextWithPoppler(const std::string& path);
std::string htmlTextWithLibxml2(std::string_view html, const std::string& source);

}  // namespace tlab::analysis

// The module's entry points: 0 and *text on success, else 1 and *error (both freed by tlab_documents_free).
extern "C" {
int tlab_documents_pdf(const char* path, char** text, char** error);
int tlab_documents_html(const char* html, std::size_t size, const char* source, char** text, char** error);
void tlab_documents_free(char* p);
}
