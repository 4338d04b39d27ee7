// PDF text through poppler-cpp, in reading order (part of the document-reader module).
#include <poppler-document.h>
#include <poppler-global.h>
#include <poppler-page.h>

#include <memory>

#include "analysis/analysis_error.hpp"
#include "analysis/document_module.hpp"

namespace tlab::analysis {

namespace {
void quiet(const std::string&, void*) {}  // poppler's warnings about damaged files go nowhere
}  // namespace

std::string pdfTextWithPoppler(const std::string& path) {
  poppler::set_debug_error_function(quiet, nullptr);
  const std::unique_ptr<poppler::document> doc(poppler::document::load_from_file(path));
  if (!doc) throw AnalysisError(path + ": not a readable PDF");
  if (doc->is_locked()) throw AnalysisError(path + ": the PDF is encrypted");
  std::string text;
  for (int i = 0; i < doc->pages(); ++i) {
    const std::unique_ptr<poppler::page> page(doc->create_page(i));
    if (!page) continue;
    // Reading order (as pdftotext without -layout), so two-column pages come out column by column.
    const poppler::byte_array utf8 = page->text(poppler::rectf(), poppler::page::non_raw_non_physical_layout).to_utf8();
    text.append(utf8.begin(), utf8.end());
    text.push_back('\n');
  }
  return text;
}

}  // namespace tlab::analysis
