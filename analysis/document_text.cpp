#include "analysis/document_text.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "analysis/analysis_error.hpp"

namespace tlab::analysis {

namespace fs = std::filesystem;

DocumentFormat documentFormatOf(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".pdf") return DocumentFormat::Pdf;
  if (ext == ".htm" || ext == ".html" || ext == ".xhtml") return DocumentFormat::Html;
  return DocumentFormat::Text;
}

namespace {

std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw AnalysisError(path + ": cannot open file");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

bool isDocument(const fs::path& p) {
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".txt" || ext == ".pdf" || ext == ".htm" || ext == ".html";
}

}  // namespace

std::string readDocumentText(const std::string& path) {
  switch (documentFormatOf(path)) {
    case DocumentFormat::Pdf: return fixPdfTypesetting(pdfText(path));
    case DocumentFormat::Html: return htmlText(readBytes(path), path);
    case DocumentFormat::Text: return readBytes(path);
  }
  return {};
}

std::vector<std::string> collectDocuments(const std::vector<std::string>& paths) {
  std::vector<std::string> out;
  for (const auto& path : paths) {
    std::error_code ec;
    if (fs::is_directory(path, ec)) {
      std::vector<std::string> found;
      for (fs::recursive_directory_iterator it(path, ec), end; !ec && it != end; it.increment(ec))
        if (it->is_regular_file(ec) && isDocument(it->path())) found.push_back(it->path().string());
      if (ec) throw AnalysisError(path + ": cannot list folder (" + ec.message() + ")");
      if (found.empty()) throw AnalysisError(path + ": no .txt, .pdf, .htm or .html file in this folder");
      std::sort(found.begin(), found.end());
      out.insert(out.end(), found.begin(), found.end());
    } else if (fs::exists(path, ec)) {
      out.push_back(path);
    } else {
      throw AnalysisError(path + ": no such file or folder");
    }
  }
  return out;
}

}  // namespace tlab::analysis
